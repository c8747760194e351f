// polyDEM: damping coefficient of a contact law from the coefficient of restitution.
//
// With the normal force clamped to be non-negative (no cohesion), the classic
// closed forms (beta = -ln e / sqrt(ln^2 e + pi^2)) do not give the restitution
// that a simulation actually shows: the contact ends when the force reaches zero,
// before the overlap does. Both laws have a velocity-independent restitution
// (Tsuji et al. 1992 for Hertz with d^(1/4) damping), so the exact mapping is
// found once by integrating the dimensionless impact
//     Hertz:  s'' = -s^(3/2) - gamma sqrt(3/2) s^(1/4) s'
//     linear: s'' = -s - 2 zeta s'
// with s(0) = 0, s'(0) = 1, e = -s'(end), and solving e(damping) = e_input.
#pragma once

#include "polyDEM/Config.hpp"

namespace polydem
{

//- Coefficient of restitution that a damping value gives (dimensionless impact)
double restitutionForDamping(ContactLaw law, double damping);

//- Damping (gamma for Hertz, zeta for linear) that gives restitution e in (0, 1]
double dampingForRestitution(ContactLaw law, double e);

} // namespace polydem

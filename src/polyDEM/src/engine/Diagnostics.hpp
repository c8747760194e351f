// polyDEM engine: energies, overlap statistics, external forces.
// Part of ThrustEngine.inl: compiled once per back end inside
// namespace polydem::PD_BACKEND_NS (defined by the including back end).
#pragma once

#include "DeviceViews.hpp"
#include "Integration.hpp"

namespace polydem
{
namespace PD_BACKEND_NS
{

struct KineticEnergy
{
    ParticleView p;
    Vec3 gravity;

    PD_HD Energies operator()(int i) const
    {
        Energies e;
        e.translational = 0.5 * p.mass[i] * normSqr(p.vel[i]);
        e.rotational = 0.5 * dot(p.omega[i], worldInertiaTimes(p.q[i], p.inertia[i], p.omega[i]));
        e.gravitational = -p.mass[i] * dot(gravity, p.pos[i]);
        return e;
    }
};

//- Largest overlap of a particle's contacts relative to the smaller radius
//  (Hertz and linear laws): how hard the contacts are pressed, a check on the
//  stiffness chosen. Not defined for the volumetric law (its overlap is a volume).
struct MaxOverlapRatio
{
    ParticleView p;
    const int* pairStart;
    const int* partner;
    const unsigned char* touching;

    PD_HD double operator()(int i) const
    {
        double worst = 0;
        for (int k = pairStart[i]; k < pairStart[i + 1]; ++k)
        {
            if (!touching[k]) continue;
            const int j = partner[k];
            const double rMin = p.radius[i] < p.radius[j] ? p.radius[i] : p.radius[j];
            const double ratio = (p.radius[i] + p.radius[j] - norm(p.pos[j] - p.pos[i])) / rMin;
            worst = ratio > worst ? ratio : worst;
        }
        return worst;
    }
};

//- total += new - old, for the external part of a stored force or torque
struct ReplaceExternal
{
    Vec3* total;
    const Vec3* oldPart;   //!< null: none
    const Vec3* newPart;   //!< null: none

    PD_HD void operator()(int i) const
    {
        if (oldPart) total[i] -= oldPart[i];
        if (newPart) total[i] += newPart[i];
    }
};

struct AddEnergies
{
    PD_HD Energies operator()(const Energies& a, const Energies& b) const
    {
        Energies e;
        e.translational = a.translational + b.translational;
        e.rotational = a.rotational + b.rotational;
        e.gravitational = a.gravitational + b.gravitational;
        e.elastic = a.elastic + b.elastic;
        return e;
    }
};

} // namespace PD_BACKEND_NS
} // namespace polydem

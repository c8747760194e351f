#include "polyDEM/RestitutionCalibration.hpp"

#include "polyDEM/ContactLaws.hpp"
#include "polyDEM/Error.hpp"

#include <cmath>

namespace polydem
{

namespace
{

// Dimensionless contact force of the law (positive = repulsive), clamped at zero
double force(ContactLaw law, double damping, double s, double v)
{
    return withContactLaw(law, [&](auto L) { return decltype(L)::restitutionForce(damping, s, v); });
}

} // namespace


double restitutionForDamping(ContactLaw law, double damping)
{
    // RK4 on (s, v), v = ds/dt; the contact lasts ~3 time units
    const double h = 2e-4;
    double s = 0, v = 1;
    for (int step = 0; step < 200000; ++step)
    {
        auto acc = [&](double ss, double vv) { return -force(law, damping, ss > 0 ? ss : 0, vv); };
        const double k1s = v, k1v = acc(s, v);
        const double k2s = v + 0.5 * h * k1v, k2v = acc(s + 0.5 * h * k1s, v + 0.5 * h * k1v);
        const double k3s = v + 0.5 * h * k2v, k3v = acc(s + 0.5 * h * k2s, v + 0.5 * h * k2v);
        const double k4s = v + h * k3v, k4v = acc(s + h * k3s, v + h * k3v);
        const double sNew = s + h / 6 * (k1s + 2 * k2s + 2 * k3s + k4s);
        const double vNew = v + h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
        // Separation: overlap back to zero, or the (clamped) force vanishes while
        // rebounding; from then on the velocity no longer changes.
        if (sNew <= 0 || (vNew < 0 && force(law, damping, sNew, vNew) <= 0))
        {
            return -vNew;
        }
        s = sNew;
        v = vNew;
    }
    return 0; // never separated: fully damped
}


double dampingForRestitution(ContactLaw law, double e)
{
    if (!(e > 0 && e <= 1))
    {
        throw Error("coefficient of restitution must be in (0, 1], got " + std::to_string(e));
    }
    if (e >= 1)
    {
        return 0;
    }
    // e(damping) decreases monotonically: bisect
    double lo = 0, hi = 1;
    while (restitutionForDamping(law, hi) > e)
    {
        hi *= 2;
        if (hi > 1e6)
        {
            break;
        }
    }
    for (int it = 0; it < 60; ++it)
    {
        const double mid = 0.5 * (lo + hi);
        if (restitutionForDamping(law, mid) > e)
        {
            lo = mid;
        }
        else
        {
            hi = mid;
        }
    }
    return 0.5 * (lo + hi);
}

} // namespace polydem

// polyDEM: rolling resistance of a contact (host+device), on the rolling part of
// the relative angular velocity w_r = w_rel - (w_rel . n) n.
//     constantTorque: M = -mu_r R* Fn w_r/|w_r|                     (Ai et al. 2011, type A)
//     elasticPlastic: dM_k = -k_r w_r dt, k_r = 2.25 kn mu_r^2 R*^2, |M_k| <= mu_r R* Fn,
//                     M_d = -eta_r 2 sqrt(I_r k_r) w_r while not fully mobilised
//                                                                    (Ai et al. 2011, type C)
// Twisting (torsional) resistance, an option of the rolling model, on the spin
// part w_n = (w_rel . n) n:
//     M_t = -mu_t R* Fn w_n/|w_n|, limited to I* |w_n| / dt so that it cannot
//     reverse the spin within a step (the constant-torque form of the rolling
//     torque applied about the normal; cf. the "spinning friction" of Zhou et al.
//     1999 and Jiang et al. 2015, whose torque is also proportional to Fn).
#pragma once

#include "polyDEM/contactLaws/ContactTypes.hpp"

namespace polydem
{

//- Rolling torque on body 1; mr: the EPSD spring torque of the contact (history)
//  dissipated (null: not wanted): += the energy the torque dissipates in the step [J]
PD_HD inline Vec3 rollingTorque
(
    const LawParameters& law, const PairCoefficients& pc, const ContactKinematics& k,
    double kn, double fn, Vec3& mr, double* dissipated = nullptr
)
{
    const Vec3& n = k.normal;
    const Vec3 wr = k.relOmega - dot(k.relOmega, n) * n;
    const double mMax = pc.rollingFriction * k.rStar * fn;
    if (law.rolling == RollingModel::constantTorque)
    {
        const double w = norm(wr);
        if (w > 0)
        {
            // Limit so that the torque cannot reverse the relative rolling
            // within one step (prevents chatter at rest)
            const double mStop = (k.rollingInertia > 0) ? k.rollingInertia * w / law.dt : mMax;
            const double m = mMax < mStop ? mMax : mStop;
            if (dissipated) *dissipated += m * w * law.dt;
            return (-m / w) * wr;
        }
        return Vec3();
    }
    const double kr = 2.25 * kn * pc.rollingFriction * pc.rollingFriction * k.rStar * k.rStar;
    mr -= dot(mr, n) * n;
    const double mrOldSqr = dissipated ? normSqr(mr) : 0.0;
    mr -= (kr * law.dt) * wr;
    const double mLen = norm(mr);
    Vec3 md;
    if (mLen > mMax)
    {
        mr *= (mLen > 0 ? mMax / mLen : 0.0);
        // Fully mobilised: the work on the rolling less what the spring keeps
        if (dissipated && kr > 0)
        {
            *dissipated += -dot(mr, wr) * law.dt - 0.5 * (normSqr(mr) - mrOldSqr) / kr;
        }
    }
    else
    {
        const double cr = pc.rollingDamping * 2.0 * sqrt(k.rollingInertia * kr);
        md = -cr * wr;
        if (dissipated) *dissipated += cr * normSqr(wr) * law.dt;
    }
    return mr + md;
}

//- Twisting torque on body 1 (about the normal)
//  dissipated (null: not wanted): += the energy it dissipates in the step [J]
PD_HD inline Vec3 twistingTorque
(
    const LawParameters& law, const PairCoefficients& pc, const ContactKinematics& k, double fn,
    double* dissipated = nullptr
)
{
    const double wn = dot(k.relOmega, k.normal);
    const double w = fabs(wn);
    if (!(w > 0)) return Vec3();
    const double mMax = pc.twistingFriction * k.rStar * fn;
    const double mStop = k.spinInertia > 0 ? k.spinInertia * w / law.dt : mMax;
    const double m = mMax < mStop ? mMax : mStop;
    if (dissipated) *dissipated += m * w * law.dt;
    return (wn > 0 ? -m : m) * k.normal;
}

} // namespace polydem

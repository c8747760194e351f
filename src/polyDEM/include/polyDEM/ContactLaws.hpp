// polyDEM: the contact laws (host+device) and the one place that picks a law.
//
// Each law lives in its own header under contactLaws/ with its coefficients,
// springs and dashpots, elastic energy, critical time step and the impact used
// to calibrate its damping for a restitution coefficient:
//     HertzMindlin, LinearSpringDashpot, OverlapVolume.
// The part every law shares is here (contactForce):
//     Fn = max(0, Fn_elastic + cn vn)
//     Ft = -kt xi - ct vt,  |Ft| <= mu Fn  (xi kept in the tangent plane, length preserved)
//     + rolling and twisting resistance (contactLaws/RollingResistance.hpp),
// and, when asked (LawParameters::accountEnergy), the energy the contact
// dissipates in the step. The normal force is never attractive (no cohesion): Fn >= 0.
#pragma once

#include "polyDEM/Config.hpp"
#include "polyDEM/Vec3.hpp"
#include "polyDEM/contactLaws/ContactTypes.hpp"
#include "polyDEM/contactLaws/HertzMindlin.hpp"
#include "polyDEM/contactLaws/LinearSpringDashpot.hpp"
#include "polyDEM/contactLaws/OverlapVolume.hpp"
#include "polyDEM/contactLaws/RollingResistance.hpp"

namespace polydem
{

#if defined(__CUDACC__)
#define PD_LAW_INLINE PD_HD inline
#else
// Inlined into the kernels: a call per contact costs more than the law itself
#define PD_LAW_INLINE __attribute__((always_inline)) inline
#endif

//- Evaluate law Law and advance the tangential/rolling history in place.
//  xi, mr: tangential spring displacement and rolling spring torque of this contact.
template<class Law>
PD_LAW_INLINE ContactResult contactForce
(
    const LawParameters& law,
    const PairCoefficients& pc,
    const ContactKinematics& k,
    Vec3& xi,
    Vec3& mr
)
{
    ContactResult res;
    const Vec3& n = k.normal;

    // Approach speed (> 0 when closing) and tangential slip velocity
    const double vn = dot(k.relVelocity, n);
    const Vec3 vt = k.relVelocity - vn * n;

    const ContactSprings s = Law::springs(law, pc, k.rStar, k.overlap, k.contactArea, k.mStar);

    double fn = s.fnElastic + s.cn * vn;
    if (fn < 0)
    {
        fn = 0;
    }
    res.normalForce = fn;

    // Tangential spring: keep it in the current tangent plane (the contact
    // frame rotates with the pair), preserving its length, then add the slip.
    // A fresh contact (xi = 0) has nothing to rotate.
    const double xiLenSqr = normSqr(xi);
    if (xiLenSqr > 0)
    {
        xi -= dot(xi, n) * n;
        const double xiProjSqr = normSqr(xi);
        if (xiProjSqr > 0)
        {
            xi *= sqrt(xiLenSqr / xiProjSqr);
        }
    }
    xi += law.dt * vt;

    Vec3 ft = -s.kt * xi - s.ct * vt;
    const double ftMagSqr = normSqr(ft);
    const double ftMax = pc.friction * fn;
    const bool sliding = ftMagSqr > ftMax * ftMax;
    if (sliding)
    {
        // Sliding: Coulomb cap; the spring holds the force it can carry
        ft *= ftMax / sqrt(ftMagSqr);
        xi = (s.kt > 0) ? (-1.0 / s.kt) * ft : Vec3();
    }

    res.force = -fn * n + ft;

    // Energy dissipated in the step (a diagnostic): the normal dashpot's
    // share of the normal force (all of it beyond the spring's, also when
    // the force is cut at zero); sticking, the tangential dashpot; sliding,
    // the work of the friction force on the slip less what the spring gained.
    // The normal force acts over the step at the approach speed of the
    // step's end, which the second half kick makes (k.relVelocity is half a
    // step older): estimated from this contact's own push over half a step,
    // fn dt / (2 m*), exact for a lone contact; without it a collision's loss
    // comes out high by about zeta omega dt (2 % at 30 steps per contact).
    // The tangential terms keep the contact's velocity: in a packing the
    // other contacts hold the slip, and a lone-contact estimate there
    // overshoots (docs/demProperties.md, "Energy flows")
    double* dissipated = nullptr;
    if (law.accountEnergy)
    {
        const double vnEnd = vn - 0.5 * law.dt * fn / k.mStar;
        double d = (fn - s.fnElastic) * vnEnd;
        d += sliding ? -dot(ft, vt) - 0.5 * s.kt * (normSqr(xi) - xiLenSqr) / law.dt
                     : s.ct * normSqr(vt);
        res.dissipated = d * law.dt;
        dissipated = &res.dissipated;
    }

    if (law.rolling != RollingModel::none && pc.rollingFriction > 0)
    {
        res.rollingTorque = rollingTorque(law, pc, k, s.kn, fn, mr, dissipated);
    }
    if (law.twisting && pc.twistingFriction > 0)
    {
        res.rollingTorque += twistingTorque(law, pc, k, fn, dissipated);
    }
    return res;
}

//- Run f(Law{}) with the law type of a run-time choice: the one switch over laws
template<class F>
inline auto withContactLaw(ContactLaw law, F&& f)
{
    switch (law)
    {
        case ContactLaw::linearSpringDashpot: return f(LinearSpringDashpot{});
        case ContactLaw::overlapVolume: return f(OverlapVolume{});
        case ContactLaw::hertzMindlin: break;
    }
    return f(HertzMindlin{});
}

//- Law constants of a contact model at time step dt
inline LawParameters lawParameters(const ContactModel& c, double dt)
{
    LawParameters p;
    p.law = c.law;
    p.rolling = c.rolling;
    p.twisting = c.twisting;
    p.normalStiffness = c.normalStiffness;
    p.tangentialStiffnessRatio = c.tangentialStiffnessRatio;
    p.volumetricStiffness = c.volumetricStiffness;
    p.dt = dt;
    return p;
}

//- Run-time law choice (host code, tests): same arithmetic as contactForce<Law>
PD_HD inline ContactResult evaluateContact
(
    const LawParameters& law,
    const PairCoefficients& pc,
    const ContactKinematics& k,
    Vec3& xi,
    Vec3& mr
)
{
    if (law.law == ContactLaw::hertzMindlin) return contactForce<HertzMindlin>(law, pc, k, xi, mr);
    if (law.law == ContactLaw::overlapVolume) return contactForce<OverlapVolume>(law, pc, k, xi, mr);
    return contactForce<LinearSpringDashpot>(law, pc, k, xi, mr);
}

//- Elastic energy stored in the normal spring of a contact (for energy checks)
PD_HD inline double normalElasticEnergy
(
    const LawParameters& law,
    const PairCoefficients& pc,
    double rStar,
    double overlap
)
{
    if (law.law == ContactLaw::hertzMindlin)
    {
        return HertzMindlin::elasticEnergy(law, pc, rStar, overlap);
    }
    return LinearSpringDashpot::elasticEnergy(law, pc, rStar, overlap);
}

} // namespace polydem

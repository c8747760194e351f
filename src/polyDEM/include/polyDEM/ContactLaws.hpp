// polyDEM: the contact laws (host+device) and the one place that picks a law.
//
// Each law lives in its own header under contactLaws/ with its coefficients,
// springs and dashpots, elastic energy, critical time step and the impact used
// to calibrate its damping for a restitution coefficient:
//     HertzMindlin, LinearSpringDashpot, OverlapVolume.
// The part every law shares is here (contactForce):
//     Fn = max(0, Fn_elastic + cn vn)
//     Ft = -kt xi - ct vt,  |Ft| <= mu Fn  (xi kept in the tangent plane, length preserved)
//     + rolling and twisting resistance (contactLaws/RollingResistance.hpp).
// The normal force is never attractive (no cohesion): Fn >= 0.
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
    if (ftMagSqr > ftMax * ftMax)
    {
        // Sliding: Coulomb cap; the spring holds the force it can carry
        ft *= ftMax / sqrt(ftMagSqr);
        xi = (s.kt > 0) ? (-1.0 / s.kt) * ft : Vec3();
    }

    res.force = -fn * n + ft;

    if (law.rolling != RollingModel::none && pc.rollingFriction > 0)
    {
        res.rollingTorque = rollingTorque(law, pc, k, s.kn, fn, mr);
    }
    if (law.twisting && pc.twistingFriction > 0)
    {
        res.rollingTorque += twistingTorque(law, pc, k, fn);
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

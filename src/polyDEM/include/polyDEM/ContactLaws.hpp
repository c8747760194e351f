// polyDEM: normal/tangential/rolling contact laws for spheres, host+device.
//
// Hertz-Mindlin (hertzMindlin)
//     Fn = 4/3 E* sqrt(R*) d^(3/2) - gamma sqrt(m* Sn) vn,   Sn = 2 E* sqrt(R* d)
//     Ft = -St xi - gamma sqrt(m* St) vt,  St = 8 G* sqrt(R* d),  |Ft| <= mu Fn
//     Hertz (1882); Mindlin & Deresiewicz (1953); damping form of Tsuji et al. (1992)
//     as used in LIGGGHTS. gamma is calibrated so that the simulated coefficient of
//     restitution equals the input one (RestitutionCalibration).
// Linear spring-dashpot (linearSpringDashpot)
//     Fn = kn d - 2 zeta sqrt(m* kn) vn,  Ft = -kt xi - 2 zeta sqrt(m* kt) vt, |Ft| <= mu Fn
//     Cundall & Strack (1979).
// Overlap volume (overlapVolume), for polyhedra (and spheres among them)
//     Fn = Kn V - 2 zeta sqrt(m* kn) vn,  kn = Kn A (A: contact area, so dFn/dd = kn)
//     Ft = -kt xi - 2 zeta sqrt(m* kt) vt,  kt = ratio kn,  |Ft| <= mu Fn
//     Blaze-DEM (Govender et al. 2016); normal n = S/|S| with S = -dV/dx (Feng 2021).
//     Against a plane, Kn V n acting at the centroid of V is exactly conservative.
// Rolling resistance
//     constantTorque: M = -mu_r R* Fn w_rel/|w_rel|                 (Ai et al. 2011, type A)
//     elasticPlastic: dM_k = -k_r w_rel dt, k_r = 2.25 kn mu_r^2 R*^2, |M_k| <= mu_r R* Fn,
//                     M_d = -eta_r 2 sqrt(I_r k_r) w_rel while not fully mobilised
//                                                                    (Ai et al. 2011, type C)
// The normal force is never attractive (no cohesion): Fn >= 0.
#pragma once

#include "polyDEM/Config.hpp"
#include "polyDEM/Vec3.hpp"

namespace polydem
{

//- Per material-pair constants of the law, precomputed on the host
struct PairCoefficients
{
    double effectiveYoungs = 0;  //!< E*
    double effectiveShear = 0;   //!< G*
    double damping = 0;          //!< gamma (Hertz) or zeta (linear), from e
    double friction = 0;
    double rollingFriction = 0;
    double rollingDamping = 0;
};

//- Law constants shared by all pairs
struct LawParameters
{
    ContactLaw law = ContactLaw::hertzMindlin;
    RollingModel rolling = RollingModel::none;
    double normalStiffness = 0;        //!< linear law [N/m]
    double volumetricStiffness = 0;    //!< overlapVolume law [N/m3]
    double tangentialStiffnessRatio = 2.0 / 7.0;
    double dt = 0;
};

//- Geometry and kinematics of one contact, from body 1's point of view
struct ContactKinematics
{
    Vec3 normal;          //!< unit, from body 1 towards body 2
    double overlap = 0;   //!< > 0 in contact [m]; overlapVolume: the volume [m3]
    double contactArea = 0; //!< overlapVolume: |S| [m2]
    double rStar = 0;     //!< effective radius
    double mStar = 0;     //!< effective mass
    double rollingInertia = 0; //!< I_r for the EPSD damping
    Vec3 relVelocity;     //!< velocity of 1 relative to 2 at the contact point
    Vec3 relOmega;        //!< omega_1 - omega_2
};

struct ContactResult
{
    Vec3 force;           //!< on body 1 (body 2 gets the opposite)
    Vec3 rollingTorque;   //!< on body 1 (body 2 gets the opposite)
    double normalForce = 0;
};

//- Evaluate the law and advance the tangential/rolling history in place.
//  xi, mr: tangential spring displacement and rolling spring torque of this contact.
#if defined(__CUDACC__)
PD_HD inline ContactResult evaluateContact
#else
// Inlined into the kernels: a call per contact costs more than the law itself
__attribute__((always_inline)) inline ContactResult evaluateContact
#endif
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
    const double d = k.overlap;

    // Approach speed (> 0 when closing) and tangential slip velocity
    const double vn = dot(k.relVelocity, n);
    const Vec3 vt = k.relVelocity - vn * n;

    double kn, kt, fnElastic, cn, ct;
    if (law.law == ContactLaw::hertzMindlin)
    {
        const double sqrtRd = sqrt(k.rStar * d);
        const double Sn = 2.0 * pc.effectiveYoungs * sqrtRd;
        const double St = 8.0 * pc.effectiveShear * sqrtRd;
        fnElastic = (2.0 / 3.0) * Sn * d;
        kn = Sn;
        kt = St;
        cn = pc.damping * sqrt(k.mStar * Sn);
        ct = pc.damping * sqrt(k.mStar * St);
    }
    else if (law.law == ContactLaw::overlapVolume)
    {
        kn = law.volumetricStiffness * k.contactArea;
        kt = law.tangentialStiffnessRatio * kn;
        fnElastic = law.volumetricStiffness * d;
        cn = 2.0 * pc.damping * sqrt(k.mStar * kn);
        ct = 2.0 * pc.damping * sqrt(k.mStar * kt);
    }
    else
    {
        kn = law.normalStiffness;
        kt = law.tangentialStiffnessRatio * kn;
        fnElastic = kn * d;
        cn = 2.0 * pc.damping * sqrt(k.mStar * kn);
        ct = 2.0 * pc.damping * sqrt(k.mStar * kt);
    }

    double fn = fnElastic + cn * vn;
    if (fn < 0)
    {
        fn = 0;
    }
    res.normalForce = fn;

    // Tangential spring: keep it in the current tangent plane (the contact
    // frame rotates with the pair), preserving its length, then add the slip.
    const double xiLen = norm(xi);
    xi -= dot(xi, n) * n;
    const double xiProj = norm(xi);
    if (xiProj > 0)
    {
        xi *= xiLen / xiProj;
    }
    xi += law.dt * vt;

    Vec3 ft = -kt * xi - ct * vt;
    const double ftMag = norm(ft);
    const double ftMax = pc.friction * fn;
    if (ftMag > ftMax)
    {
        // Sliding: Coulomb cap; the spring holds the force it can carry
        if (ftMag > 0)
        {
            ft *= ftMax / ftMag;
        }
        xi = (kt > 0) ? (-1.0 / kt) * ft : Vec3();
    }

    res.force = -fn * n + ft;

    // Overlap volume (overlapVolume), for polyhedra (and spheres among them)
//     Fn = Kn V - 2 zeta sqrt(m* kn) vn,  kn = Kn A (A: contact area, so dFn/dd = kn)
//     Ft = -kt xi - 2 zeta sqrt(m* kt) vt,  kt = ratio kn,  |Ft| <= mu Fn
//     Blaze-DEM (Govender et al. 2016); normal n = S/|S| with S = -dV/dx (Feng 2021).
//     Against a plane, Kn V n acting at the centroid of V is exactly conservative.
// Rolling resistance: only the relative rolling (tangential) part of omega
    if (law.rolling != RollingModel::none && pc.rollingFriction > 0)
    {
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
                res.rollingTorque = (-m / w) * wr;
            }
        }
        else
        {
            const double kr = 2.25 * kn * pc.rollingFriction * pc.rollingFriction * k.rStar * k.rStar;
            mr -= dot(mr, n) * n;
            mr -= (kr * law.dt) * wr;
            const double mLen = norm(mr);
            Vec3 md;
            if (mLen > mMax)
            {
                mr *= (mLen > 0 ? mMax / mLen : 0.0);
            }
            else
            {
                const double cr = pc.rollingDamping * 2.0 * sqrt(k.rollingInertia * kr);
                md = -cr * wr;
            }
            res.rollingTorque = mr + md;
        }
    }

    return res;
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
        return (8.0 / 15.0) * pc.effectiveYoungs * sqrt(rStar) * pow(overlap, 2.5);
    }
    return 0.5 * law.normalStiffness * overlap * overlap;
}

} // namespace polydem

// polyDEM: volumetric contact law (overlapVolume), for polyhedra (and spheres among them).
//     Fn = Kn V - 2 zeta sqrt(m* kn) vn,  kn = Kn A (A: contact area, so dFn/dd = kn)
//     Ft = -kt xi - 2 zeta sqrt(m* kt) vt,  kt = ratio kn,  |Ft| <= mu Fn
//     Blaze-DEM (Govender et al. 2016); normal n = S/|S| with S = -dV/dx (Feng 2021).
//     Against a plane, Kn V n acting at the centroid of V is exactly conservative.
//     zeta is calibrated as for the linear law (kn is constant in a flat contact).
// Elastic energy: exact for flat contacts (V = A d): W = Kn V^2 / (2 A).
// Critical time step: 1/10 of pi sqrt(m*/k), k = Kn A_max (largest face, or the
// sphere's section), m* = m/2.
#pragma once

#include "polyDEM/contactLaws/ContactTypes.hpp"

#include <cmath>

namespace polydem
{

struct OverlapVolume
{
    static constexpr ContactLaw id = ContactLaw::overlapVolume;
    static constexpr bool volumetric = true;

    static PairCoefficients coefficients(const Material& A, const Material& B, const LawParameters& law, double damping)
    {
        PairCoefficients c;
        effectiveModuli(A, B, c.effectiveYoungs, c.effectiveShear);
        c.damping = damping;
        c.dampingRatioTangential = std::sqrt(law.tangentialStiffnessRatio);
        return c;
    }

    //- d: overlap volume, area: contact area
    PD_HD static ContactSprings springs(const LawParameters& law, const PairCoefficients& pc, double, double d, double area, double mStar)
    {
        ContactSprings s;
        s.kn = law.volumetricStiffness * area;
        s.kt = law.tangentialStiffnessRatio * s.kn;
        s.fnElastic = law.volumetricStiffness * d;
        s.cn = 2.0 * pc.damping * sqrt(mStar * s.kn);
        s.ct = s.cn * pc.dampingRatioTangential;
        return s;
    }

    //- volume V and contact area A of the overlap
    PD_HD static double elasticEnergyOfVolume(const LawParameters& law, double V, double A)
    {
        return A > 0 ? 0.5 * law.volumetricStiffness * V * V / A : 0.0;
    }

    //- Against a plane: Kn times the first moment of the overlap about the plane
    PD_HD static double elasticEnergyAgainstPlane(const LawParameters& law, double V, double depthOfCentroid)
    {
        return law.volumetricStiffness * V * depthOfCentroid;
    }

    //- contactArea: the largest contact area the particle can make
    static double criticalTimeStep(const LawParameters& law, const Material&, double, double mass, double contactArea)
    {
        const double k = law.volumetricStiffness * contactArea;
        return M_PI * std::sqrt(0.5 * mass / k) / 10;
    }

    static const char* criticalTimeStepRule() { return "1/10 of the contact duration"; }

    static double restitutionForce(double damping, double s, double v)
    {
        const double f = s + 2.0 * damping * v;
        return f > 0 ? f : 0;
    }
};

} // namespace polydem

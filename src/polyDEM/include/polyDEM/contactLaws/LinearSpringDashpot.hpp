// polyDEM: linear spring-dashpot contact law (linearSpringDashpot), spheres.
//     Fn = kn d - 2 zeta sqrt(m* kn) vn,  Ft = -kt xi - 2 zeta sqrt(m* kt) vt, |Ft| <= mu Fn
//     kt = ratio kn. Cundall & Strack (1979). zeta is calibrated for the input
//     restitution with the clamped force (dimensionless impact s'' = -s - 2 zeta s').
// Critical time step: 1/10 of the undamped contact duration pi sqrt(m*/kn), m* = m/2.
#pragma once

#include "polyDEM/contactLaws/ContactTypes.hpp"

#include <cmath>

namespace polydem
{

struct LinearSpringDashpot
{
    static constexpr ContactLaw id = ContactLaw::linearSpringDashpot;
    static constexpr bool volumetric = false;

    static PairCoefficients coefficients(const Material& A, const Material& B, const LawParameters& law, double damping)
    {
        PairCoefficients c;
        effectiveModuli(A, B, c.effectiveYoungs, c.effectiveShear);
        c.damping = damping;
        c.dampingRatioTangential = std::sqrt(law.tangentialStiffnessRatio);
        return c;
    }

    PD_HD static ContactSprings springs(const LawParameters& law, const PairCoefficients& pc, double, double d, double, double mStar)
    {
        ContactSprings s;
        s.kn = law.normalStiffness;
        s.kt = law.tangentialStiffnessRatio * s.kn;
        s.fnElastic = s.kn * d;
        s.cn = 2.0 * pc.damping * sqrt(mStar * s.kn);
        s.ct = s.cn * pc.dampingRatioTangential;
        return s;
    }

    //- W = kn d^2 / 2
    PD_HD static double elasticEnergy(const LawParameters& law, const PairCoefficients&, double, double d)
    {
        return 0.5 * law.normalStiffness * d * d;
    }

    static double criticalTimeStep(const LawParameters& law, const Material&, double, double mass, double)
    {
        return M_PI * std::sqrt(0.5 * mass / law.normalStiffness) / 10;
    }

    static const char* criticalTimeStepRule() { return "1/10 of the contact duration"; }

    static double restitutionForce(double damping, double s, double v)
    {
        const double f = s + 2.0 * damping * v;
        return f > 0 ? f : 0;
    }
};

} // namespace polydem

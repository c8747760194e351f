// polyDEM: Hertz-Mindlin contact law (hertzMindlin), spheres.
//     Fn = 4/3 E* sqrt(R*) d^(3/2) - gamma sqrt(m* Sn) vn,   Sn = 2 E* sqrt(R* d)
//     Ft = -St xi - gamma sqrt(m* St) vt,  St = 8 G* sqrt(R* d),  |Ft| <= mu Fn
//     Hertz (1882); Mindlin & Deresiewicz (1953); damping form of Tsuji et al. (1992)
//     as used in LIGGGHTS. gamma is calibrated so that the simulated coefficient of
//     restitution equals the input one (RestitutionCalibration, dimensionless
//     impact s'' = -s^(3/2) - gamma sqrt(3/2) s^(1/4) s').
// Critical time step: 20 % of the Rayleigh time pi r sqrt(rho/G) / (0.1631 nu + 0.8766).
#pragma once

#include "polyDEM/contactLaws/ContactTypes.hpp"

#include <cmath>

namespace polydem
{

struct HertzMindlin
{
    static constexpr ContactLaw id = ContactLaw::hertzMindlin;
    static constexpr bool volumetric = false;

    //- Per material-pair coefficients (damping: calibrated gamma for e)
    static PairCoefficients coefficients(const Material& A, const Material& B, const LawParameters&, double damping)
    {
        PairCoefficients c;
        effectiveModuli(A, B, c.effectiveYoungs, c.effectiveShear);
        c.damping = damping;
        // St / Sn = 4 G* / E*
        c.dampingRatioTangential = std::sqrt(4.0 * c.effectiveShear / c.effectiveYoungs);
        return c;
    }

    PD_HD static ContactSprings springs(const LawParameters&, const PairCoefficients& pc, double rStar, double d, double, double mStar)
    {
        ContactSprings s;
        const double sqrtRd = sqrt(rStar * d);
        s.kn = 2.0 * pc.effectiveYoungs * sqrtRd;
        s.kt = 8.0 * pc.effectiveShear * sqrtRd;
        s.fnElastic = (2.0 / 3.0) * s.kn * d;
        s.cn = pc.damping * sqrt(mStar * s.kn);
        s.ct = s.cn * pc.dampingRatioTangential;
        return s;
    }

    //- Elastic energy of the normal spring: W = 8/15 E* sqrt(R*) d^(5/2)
    PD_HD static double elasticEnergy(const LawParameters&, const PairCoefficients& pc, double rStar, double d)
    {
        return (8.0 / 15.0) * pc.effectiveYoungs * sqrt(rStar) * pow(d, 2.5);
    }

    //- Largest stable step for a particle of this material and radius
    static double criticalTimeStep(const LawParameters&, const Material& m, double radius, double, double)
    {
        const double G = m.youngsModulus / (2 * (1 + m.poissonsRatio));
        const double nu = m.poissonsRatio;
        const double tR = M_PI * radius * std::sqrt(m.density / G) / (0.1631 * nu + 0.8766);
        return 0.2 * tR;
    }

    static const char* criticalTimeStepRule() { return "20 % of the Rayleigh time"; }

    //- Dimensionless force of the impact used to calibrate the damping (> 0 repulsive)
    static double restitutionForce(double damping, double s, double v)
    {
        const double f = std::pow(s, 1.5) + damping * std::sqrt(1.5) * std::pow(s, 0.25) * v;
        return f > 0 ? f : 0;
    }
};

} // namespace polydem

// polyDEM: plain data shared by the contact laws (host+device): per material-pair
// coefficients, law-wide constants, the kinematics of one contact and its result.
#pragma once

#include "polyDEM/Config.hpp"
#include "polyDEM/Vec3.hpp"

namespace polydem
{

//- Per material-pair constants of the law, precomputed on the host by the law
struct PairCoefficients
{
    double effectiveYoungs = 0;  //!< E*
    double effectiveShear = 0;   //!< G*
    double damping = 0;          //!< gamma (Hertz) or zeta (linear, volumetric), from e
    double friction = 0;
    double rollingFriction = 0;
    double rollingDamping = 0;
    double twistingFriction = 0; //!< mu_t of the twisting (torsional) torque, 0 = none
    //- sqrt(kt / kn): the tangential dashpot is ct = cn sqrt(kt/kn) (one sqrt saved)
    double dampingRatioTangential = 0;
};

//- Law constants shared by all pairs
struct LawParameters
{
    ContactLaw law = ContactLaw::hertzMindlin;
    RollingModel rolling = RollingModel::none;
    bool twisting = false;             //!< twisting resistance on
    double normalStiffness = 0;        //!< linear law [N/m]
    double volumetricStiffness = 0;    //!< overlapVolume law [N/m3]
    double tangentialStiffnessRatio = 2.0 / 7.0;
    double dt = 0;
    //- Also return the energy each contact dissipates (ContactResult::dissipated):
    //  a diagnostic, off unless Engine::enableEnergyFlows asks for it
    bool accountEnergy = false;
};

//- Geometry and kinematics of one contact, from body 1's point of view
struct ContactKinematics
{
    Vec3 normal;          //!< unit, from body 1 towards body 2
    double overlap = 0;   //!< > 0 in contact [m]; overlapVolume: the volume [m3]
    double contactArea = 0; //!< overlapVolume: |S| [m2]
    double rStar = 0;     //!< effective radius
    double mStar = 0;     //!< effective mass
    double rollingInertia = 0; //!< I_r for the EPSD damping and the rolling torque limit
    double spinInertia = 0;    //!< I* about the normal, for the twisting torque limit
    Vec3 relVelocity;     //!< velocity of 1 relative to 2 at the contact point
    Vec3 relOmega;        //!< omega_1 - omega_2
};

struct ContactResult
{
    Vec3 force;           //!< on body 1 (body 2 gets the opposite)
    Vec3 rollingTorque;   //!< on body 1 (body 2 gets the opposite): rolling + twisting
    double normalForce = 0;
    //- Energy dissipated by the contact in this step [J], >= 0 up to the
    //  step's round-off (law.accountEnergy; else 0): the normal and tangential
    //  dashpots, Coulomb sliding, rolling and twisting resistance
    double dissipated = 0;
};

//- Whether a contact needs the rolling/spin inertias (rolling or twisting resistance)
PD_HD inline bool needsResistanceInertia(const LawParameters& law)
{
    return law.rolling != RollingModel::none || law.twisting;
}

//- Normal and tangential springs and dashpots of a law at one contact
struct ContactSprings
{
    double kn = 0;         //!< normal stiffness dFn/d(overlap) [N/m]
    double kt = 0;         //!< tangential stiffness [N/m]
    double fnElastic = 0;  //!< elastic normal force [N]
    double cn = 0;         //!< normal dashpot [N s/m]
    double ct = 0;         //!< tangential dashpot [N s/m]
};

//- Effective Young's and shear moduli of two materials (Hertz-Mindlin)
inline void effectiveModuli(const Material& A, const Material& B, double& E, double& G)
{
    E = 1.0 / ((1 - A.poissonsRatio * A.poissonsRatio) / A.youngsModulus
               + (1 - B.poissonsRatio * B.poissonsRatio) / B.youngsModulus);
    G = 1.0 / (2 * (2 - A.poissonsRatio) * (1 + A.poissonsRatio) / A.youngsModulus
               + 2 * (2 - B.poissonsRatio) * (1 + B.poissonsRatio) / B.youngsModulus);
}

} // namespace polydem

#include "viscousStressForce.H"
#include "addToRunTimeSelectionTable.H"
#include "fvc.H"
#include "mathematicalConstants.H"

namespace Foam
{
    makeForceModel(viscousStressForce);
}


Foam::viscousStressForce::viscousStressForce
(
    const word& modelType,
    const dictionary& dict,
    const forceModelContext& context
)
:
    forceModel(modelType, dict, context)
{}


void Foam::viscousStressForce::cacheFields(const bool store)
{
    if (store)
    {
        // Divergence of the kinematic deviatoric stress
        const volScalarField& nuEff = context_.nuEff();
        const volVectorField& U = context_.U();
        const volVectorField divTau
        (
            fvc::laplacian(nuEff, U)
          + fvc::div(nuEff*dev2(T(fvc::grad(U))))
        );
        divTauP_ = context_.sample(divTau);
    }
    else
    {
        divTauP_.clear();
    }
}


void Foam::viscousStressForce::addForce(const particleSample& s, particleForce& f) const
{
    const vector F = s.Vp*s.rho*divTauP_[s.index];
    if (context_.formulation() == couplingFormulation::setI)
    {
        f.Fparticle += F;
    }
    else
    {
        f.Fcoupled += F;
    }
}

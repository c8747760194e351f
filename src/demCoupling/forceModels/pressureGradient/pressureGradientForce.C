#include "pressureGradientForce.H"
#include "addToRunTimeSelectionTable.H"
#include "fvc.H"
#include "mathematicalConstants.H"

namespace Foam
{
    makeForceModel(pressureGradientForce);
}


Foam::pressureGradientForce::pressureGradientForce
(
    const word& modelType,
    const dictionary& dict,
    const forceModelContext& context
)
:
    forceModel(modelType, dict, context)
{}


void Foam::pressureGradientForce::cacheFields(const bool store)
{
    if (store)
    {
        // Gradient of the kinematic pressure
        const volVectorField gradP(fvc::grad(context_.p()));
        gradPP_ = context_.sample(gradP);
    }
    else
    {
        gradPP_.clear();
    }
}


void Foam::pressureGradientForce::addForce(const particleSample& s, particleForce& f) const
{
    // With a free surface p is the full pressure [Pa]: F = -Vp <grad p>
    const vector F =
        context_.freeSurface()
      ? -s.Vp*gradPP_[s.index]
      : -s.Vp*s.rho*gradPP_[s.index];
    if (context_.formulation() == couplingFormulation::setI)
    {
        f.Fparticle += F;
    }
    else
    {
        f.Fcoupled += F;
    }
}

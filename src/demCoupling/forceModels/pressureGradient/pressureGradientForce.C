#include "pressureGradientForce.H"
#include "demCloud.H"
#include "addToRunTimeSelectionTable.H"
#include "mathematicalConstants.H"

namespace Foam
{
    makeForceModel(pressureGradientForce);
}


Foam::pressureGradientForce::pressureGradientForce
(
    const word& modelType,
    const dictionary& dict,
    const demCloud& cloud
)
:
    forceModel(modelType, dict, cloud)
{}


void Foam::pressureGradientForce::addForce(const particleSample& s, particleForce& f) const
{
    const vector F = -s.Vp*s.rho*s.gradP;
    if (cloud_.formulation() == couplingFormulation::setI)
    {
        f.Fparticle += F;
    }
    else
    {
        f.Fcoupled += F;
    }
}

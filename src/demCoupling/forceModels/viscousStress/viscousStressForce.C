#include "viscousStressForce.H"
#include "demCloud.H"
#include "addToRunTimeSelectionTable.H"
#include "mathematicalConstants.H"

namespace Foam
{
    makeForceModel(viscousStressForce);
}


Foam::viscousStressForce::viscousStressForce
(
    const word& modelType,
    const dictionary& dict,
    const demCloud& cloud
)
:
    forceModel(modelType, dict, cloud)
{}


void Foam::viscousStressForce::addForce(const particleSample& s, particleForce& f) const
{
    const vector F = s.Vp*s.rho*s.divTau;
    if (cloud_.formulation() == couplingFormulation::setI)
    {
        f.Fparticle += F;
    }
    else
    {
        f.Fcoupled += F;
    }
}

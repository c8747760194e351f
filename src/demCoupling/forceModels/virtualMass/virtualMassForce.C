#include "virtualMassForce.H"
#include "demCloud.H"
#include "addToRunTimeSelectionTable.H"
#include "mathematicalConstants.H"

namespace Foam
{
    makeForceModel(virtualMassForce);
}


Foam::virtualMassForce::virtualMassForce
(
    const word& modelType,
    const dictionary& dict,
    const demCloud& cloud
)
:
    forceModel(modelType, dict, cloud),
    Cvm_(coeffs_.getOrDefault<scalar>("Cvm", 0.5))
{}


void Foam::virtualMassForce::addForce(const particleSample& s, particleForce& f) const
{
    const vector dUpdt =
        s.deltaT > 0 ? (s.Up - cloud_.previousVelocity(s.index))/s.deltaT
                     : vector::zero;
    f.Fcoupled += Cvm_*s.rho*s.Vp*(s.DUDt - dUpdt);
}

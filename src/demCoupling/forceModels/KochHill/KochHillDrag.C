#include "KochHillDrag.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
    makeForceModel(KochHillDrag);
}


Foam::KochHillDrag::KochHillDrag
(
    const word& modelType,
    const dictionary& dict,
    const forceModelContext& context
)
:
    dragModel(modelType, dict, context)
{}


Foam::scalar Foam::KochHillDrag::beta(const particleSample& s) const
{
    const scalar alpha = min(s.alpha, alphaMax_);
    const scalar phi = 1 - alpha;
    const scalar Re = this->Re(s, alpha);
    scalar F0;
    if (phi < 0.4)
    {
        F0 =
            (1 + 3*sqrt(phi/2) + 135.0/64*phi*log(phi) + 16.14*phi)
           /(1 + 0.681*phi - 8.48*sqr(phi) + 8.16*pow3(phi));
    }
    else
    {
        F0 = 10*phi/pow3(alpha);
    }
    const scalar F3 = 0.0673 + 0.212*phi + 0.0232/pow5(alpha);
    const scalar betaVol = 18*s.mu()*sqr(alpha)*phi/sqr(s.d)*(F0 + 0.5*F3*Re);
    return betaFromVolumetric(s, betaVol);
}

#include "GidaspowDrag.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
    makeForceModel(GidaspowDrag);
}


Foam::GidaspowDrag::GidaspowDrag
(
    const word& modelType,
    const dictionary& dict,
    const forceModelContext& context
)
:
    dragModel(modelType, dict, context)
{}


Foam::scalar Foam::GidaspowDrag::beta(const particleSample& s) const
{
    const scalar alpha = min(s.alpha, alphaMax_);
    const scalar magUr = mag(s.Ur());
    scalar betaVol = 0;
    if (alpha < 0.8)
    {
        betaVol =
            150*sqr(1 - alpha)*s.mu()/(alpha*sqr(s.d))
          + 1.75*(1 - alpha)*s.rho*magUr/s.d;
    }
    else
    {
        const scalar Re = max(this->Re(s, alpha), SMALL);
        const scalar Cd = Re < 1000 ? 24/Re*(1 + 0.15*pow(Re, 0.687)) : 0.44;
        betaVol =
            0.75*Cd*alpha*(1 - alpha)*s.rho*magUr/s.d*pow(alpha, -2.65);
        if (Re <= SMALL)
        {
            // Stokes limit written without |Ur|
            betaVol = 18*s.mu()*(1 - alpha)/sqr(s.d)*pow(alpha, -2.65);
        }
    }
    return betaFromVolumetric(s, betaVol);
}

#include "HaiderLevenspielDrag.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
    makeForceModel(HaiderLevenspielDrag);
}


Foam::HaiderLevenspielDrag::HaiderLevenspielDrag
(
    const word& modelType,
    const dictionary& dict,
    const forceModelContext& context
)
:
    dragModel(modelType, dict, context)
{}


Foam::scalar Foam::HaiderLevenspielDrag::beta(const particleSample& s) const
{
    const scalar phi = s.sphericity;
    const scalar Re = max(this->Re(s), SMALL);
    const scalar A = exp(2.3288 - 6.4581*phi + 2.4486*sqr(phi));
    const scalar B = 0.0964 + 0.5565*phi;
    const scalar C = exp(4.905 - 13.8944*phi + 18.4222*sqr(phi) - 10.2599*pow3(phi));
    const scalar D = exp(1.4681 + 12.2584*phi - 20.7322*sqr(phi) + 15.8855*pow3(phi));
    const scalar Cd = 24/Re*(1 + A*pow(Re, B)) + C/(1 + D/Re);
    return betaFromCd(s, Cd);
}

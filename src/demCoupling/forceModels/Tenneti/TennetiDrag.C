#include "TennetiDrag.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
    makeForceModel(TennetiDrag);
}


Foam::TennetiDrag::TennetiDrag
(
    const word& modelType,
    const dictionary& dict,
    const forceModelContext& context
)
:
    dragModel(modelType, dict, context)
{}


Foam::scalar Foam::TennetiDrag::beta(const particleSample& s) const
{
    const scalar alpha = min(s.alpha, alphaMax_);
    const scalar phi = 1 - alpha;
    const scalar Re = this->Re(s, alpha);
    const scalar F =
        (1 + 0.15*pow(Re, 0.687))/pow3(alpha)
      + 5.81*phi/pow3(alpha) + 0.48*cbrt(phi)/pow4(alpha)
      + pow3(phi)*Re*(0.95 + 0.61*pow3(phi)/sqr(alpha));
    return 3*constant::mathematical::pi*s.mu()*s.d*alpha*F;
}

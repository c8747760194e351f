#include "BeetstraDrag.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
    makeForceModel(BeetstraDrag);
}


Foam::BeetstraDrag::BeetstraDrag
(
    const word& modelType,
    const dictionary& dict,
    const forceModelContext& context
)
:
    dragModel(modelType, dict, context)
{}


Foam::scalar Foam::BeetstraDrag::beta(const particleSample& s) const
{
    const scalar alpha = min(s.alpha, alphaMax_);
    const scalar phi = 1 - alpha;
    const scalar Re = max(this->Re(s, alpha), SMALL);
    const scalar F =
        10*phi/sqr(alpha) + sqr(alpha)*(1 + 1.5*sqrt(phi))
      + 0.413*Re/(24*sqr(alpha))
       *(1/alpha + 3*phi*alpha + 8.4*pow(Re, -0.343))
       /(1 + pow(10.0, 3*phi)*pow(Re, -0.5*(1 + 4*phi)));
    return 3*constant::mathematical::pi*s.mu()*s.d*alpha*F;
}

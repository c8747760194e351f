#include "SchillerNaumannDrag.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
    makeForceModel(SchillerNaumannDrag);
}


Foam::SchillerNaumannDrag::SchillerNaumannDrag
(
    const word& modelType,
    const dictionary& dict,
    const forceModelContext& context
)
:
    dragModel(modelType, dict, context)
{}


Foam::scalar Foam::SchillerNaumannDrag::beta(const particleSample& s) const
{
    const scalar Re = this->Re(s);
    const scalar Cd =
        Re < 1000 ? 24/max(Re, SMALL)*(1 + 0.15*pow(Re, 0.687)) : 0.44;
    return Re < SMALL ? 3*constant::mathematical::pi*s.mu()*s.d : betaFromCd(s, Cd);
}

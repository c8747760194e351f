#include "GanserDrag.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
    makeForceModel(GanserDrag);
}


Foam::GanserDrag::GanserDrag
(
    const word& modelType,
    const dictionary& dict,
    const forceModelContext& context
)
:
    dragModel(modelType, dict, context)
{}


Foam::scalar Foam::GanserDrag::beta(const particleSample& s) const
{
    const scalar phi = min(s.sphericity, 1.0);
    const scalar Re = max(this->Re(s), SMALL);
    const scalar K1 = 3/(s.dnByDv + 2/sqrt(phi));
    const scalar K2 = pow(10.0, 1.8148*pow(max(-log10(phi), 0.0), 0.5743));
    const scalar ReK = Re*K1*K2;
    const scalar Cd =
        K2*(24/ReK*(1 + 0.1118*pow(ReK, 0.6567)) + 0.4305/(1 + 3305/ReK));
    return betaFromCd(s, Cd);
}

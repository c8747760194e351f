#include "DiFeliceDrag.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
    makeForceModel(DiFeliceDrag);
}


Foam::DiFeliceDrag::DiFeliceDrag
(
    const word& modelType,
    const dictionary& dict,
    const forceModelContext& context
)
:
    dragModel(modelType, dict, context)
{}


Foam::scalar Foam::DiFeliceDrag::beta(const particleSample& s) const
{
    const scalar alpha = min(s.alpha, alphaMax_);
    const scalar Re = max(this->Re(s, alpha), SMALL);
    const scalar Cd = sqr(0.63 + 4.8/sqrt(Re));
    const scalar chi = 3.7 - 0.65*exp(-sqr(1.5 - log10(Re))/2);
    return betaFromCd(s, Cd)*sqr(alpha)*pow(alpha, -chi);
}

#include "HoelzerSommerfeldDrag.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
    makeForceModel(HoelzerSommerfeldDrag);
}


Foam::HoelzerSommerfeldDrag::HoelzerSommerfeldDrag
(
    const word& modelType,
    const dictionary& dict,
    const forceModelContext& context
)
:
    dragModel(modelType, dict, context)
{}


Foam::scalar Foam::HoelzerSommerfeldDrag::beta(const particleSample& s) const
{
    const scalar phi = min(s.sphericity, 1.0);
    const scalar phiPerp = s.crosswiseSphericity;  // may exceed 1 (face-on)
    const scalar Re = max(this->Re(s), SMALL);
    const scalar Cd =
        8/(Re*sqrt(phiPerp)) + 16/(Re*sqrt(phi)) + 3/(sqrt(Re)*pow(phi, 0.75))
      + 0.42*pow(10.0, 0.4*pow(max(-log10(phi), 0.0), 0.2))/phiPerp;
    return betaFromCd(s, Cd);
}

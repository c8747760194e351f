#include "dragModel.H"

Foam::dragModel::dragModel
(
    const word& modelType,
    const dictionary& dict,
    const forceModelContext& context
)
:
    forceModel(modelType, dict, context),
    alphaMax_(coeffs_.getOrDefault<scalar>("alphaMax", 0.999))
{
    // The fluid fraction is capped at alphaMax in the drag laws; a value
    // outside (0, 1] would reverse or remove the exchange force
    if (!(alphaMax_ > 0 && alphaMax_ <= 1))
    {
        FatalIOErrorInFunction(dict)
            << "alphaMax " << alphaMax_ << " in " << modelType
            << "Coeffs of " << dict.name() << " must be in (0, 1]"
            << exit(FatalIOError);
    }
}

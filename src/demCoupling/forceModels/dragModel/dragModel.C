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
{}

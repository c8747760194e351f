#include "dragModel.H"

Foam::dragModel::dragModel
(
    const word& modelType,
    const dictionary& dict,
    const demCloud& cloud
)
:
    forceModel(modelType, dict, cloud),
    alphaMax_(coeffs_.getOrDefault<scalar>("alphaMax", 0.999))
{}

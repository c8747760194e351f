#include "smoothingModel.H"

namespace Foam
{
    defineTypeNameAndDebug(smoothingModel, 0);
    defineRunTimeSelectionTable(smoothingModel, dictionary);
}


Foam::smoothingModel::smoothingModel
(
    const word& modelType,
    const dictionary& dict,
    const fvMesh& mesh
)
:
    mesh_(mesh),
    coeffs_(dict.subOrEmptyDict(modelType + "Coeffs"))
{}


Foam::autoPtr<Foam::smoothingModel> Foam::smoothingModel::New
(
    const dictionary& dict,
    const fvMesh& mesh
)
{
    const word modelType(dict.getOrDefault<word>("smoothingModel", "none"));
    Info<< "    smoothing model: " << modelType << endl;

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);
    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict, "smoothingModel", modelType, *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }
    return autoPtr<smoothingModel>(cstrIter()(modelType, dict, mesh));
}

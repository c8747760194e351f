#include "locateModel.H"

namespace Foam
{
    defineTypeNameAndDebug(locateModel, 0);
    defineRunTimeSelectionTable(locateModel, dictionary);
}


Foam::locateModel::locateModel
(
    const word& modelType,
    const dictionary& dict,
    const fvMesh& mesh
)
:
    mesh_(mesh),
    coeffs_(dict.subOrEmptyDict(modelType + "Coeffs"))
{}


Foam::autoPtr<Foam::locateModel> Foam::locateModel::New
(
    const dictionary& dict,
    const fvMesh& mesh
)
{
    const word modelType(dict.getOrDefault<word>("locateModel", "hinted"));
    Info<< "    locate model: " << modelType << endl;

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);
    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict, "locateModel", modelType, *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }
    return autoPtr<locateModel>(cstrIter()(modelType, dict, mesh));
}

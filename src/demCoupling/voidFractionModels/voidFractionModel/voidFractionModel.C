#include "voidFractionModel.H"

namespace Foam
{
    defineTypeNameAndDebug(voidFractionModel, 0);
    defineRunTimeSelectionTable(voidFractionModel, dictionary);
}


Foam::voidFractionModel::voidFractionModel
(
    const word& modelType,
    const dictionary& dict,
    const fvMesh& mesh,
    const locateModel& locate
)
:
    mesh_(mesh),
    locate_(locate),
    coeffs_(dict.subOrEmptyDict(modelType + "Coeffs")),
    alphaMin_(coeffs_.getOrDefault<scalar>("alphaMin", 0.1))
{
    // alphaMin is the floor of the fluid fraction: 0 would divide by zero
    // in the drag laws, 1 or more would remove the particles from the fluid
    if (!(alphaMin_ > 0 && alphaMin_ < 1))
    {
        FatalIOErrorInFunction(dict)
            << "alphaMin " << alphaMin_ << " in " << modelType
            << "Coeffs of " << dict.name() << " must be in (0, 1)"
            << " (the smallest fluid fraction a cell may take)"
            << exit(FatalIOError);
    }
}


Foam::autoPtr<Foam::voidFractionModel> Foam::voidFractionModel::New
(
    const dictionary& dict,
    const fvMesh& mesh,
    const locateModel& locate
)
{
    const word modelType(dict.get<word>("voidFractionModel"));
    Info<< "    void-fraction model: " << modelType << endl;

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);
    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict, "voidFractionModel", modelType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }
    return autoPtr<voidFractionModel>(cstrIter()(modelType, dict, mesh, locate));
}

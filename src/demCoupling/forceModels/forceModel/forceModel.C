#include "forceModel.H"

namespace Foam
{
    defineTypeNameAndDebug(forceModel, 0);
    defineRunTimeSelectionTable(forceModel, dictionary);
}


Foam::forceModel::forceModel
(
    const word& modelType,
    const dictionary& dict,
    const forceModelContext& context
)
:
    context_(context),
    coeffs_(dict.subOrEmptyDict(modelType + "Coeffs"))
{}


Foam::autoPtr<Foam::forceModel> Foam::forceModel::New
(
    const word& modelType,
    const dictionary& dict,
    const forceModelContext& context
)
{
    Info<< "    force model: " << modelType << endl;

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "forceModel",
            modelType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return autoPtr<forceModel>(cstrIter()(modelType, dict, context));
}

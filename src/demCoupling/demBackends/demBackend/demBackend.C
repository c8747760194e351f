#include "demBackend.H"

namespace Foam
{
    defineTypeNameAndDebug(demBackend, 0);
    defineRunTimeSelectionTable(demBackend, dictionary);
}


Foam::demBackend::demBackend(const Time& runTime)
:
    runTime_(runTime)
{}


Foam::autoPtr<Foam::demBackend> Foam::demBackend::New
(
    const Time& runTime,
    const dictionary& dict
)
{
    const word modelType(dict.getOrDefault<word>("demBackend", "polyDEM"));
    Info<< "    DEM back end: " << modelType << endl;

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);
    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict, "demBackend", modelType, *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }
    return autoPtr<demBackend>(cstrIter()(modelType, runTime, dict));
}

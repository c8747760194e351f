#include "noSmoothing.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
    defineTypeNameAndDebug(noSmoothing, 0);
    addToRunTimeSelectionTable(smoothingModel, noSmoothing, dictionary);
}


Foam::noSmoothing::noSmoothing
(
    const word& modelType,
    const dictionary& dict,
    const fvMesh& mesh
)
:
    smoothingModel(modelType, dict, mesh)
{}

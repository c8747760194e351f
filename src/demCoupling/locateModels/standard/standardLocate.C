#include "standardLocate.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
    defineTypeNameAndDebug(standardLocate, 0);
    addToRunTimeSelectionTable(locateModel, standardLocate, dictionary);
}


Foam::standardLocate::standardLocate
(
    const word& modelType,
    const dictionary& dict,
    const fvMesh& mesh
)
:
    locateModel(modelType, dict, mesh)
{}


Foam::label Foam::standardLocate::findCell(const point& p, label) const
{
    return mesh_.findCell(p);
}

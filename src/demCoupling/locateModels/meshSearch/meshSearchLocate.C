#include "meshSearchLocate.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
    defineTypeNameAndDebug(meshSearchLocate, 0);
    addToRunTimeSelectionTable(locateModel, meshSearchLocate, dictionary);
}


Foam::meshSearchLocate::meshSearchLocate
(
    const word& modelType,
    const dictionary& dict,
    const fvMesh& mesh
)
:
    locateModel(modelType, dict, mesh),
    search_(mesh, polyMesh::CELL_TETS)
{}


Foam::label Foam::meshSearchLocate::findCell(const point& p, label hint) const
{
    if (hint >= 0 && hint < mesh_.nCells())
    {
        const label celli = search_.findCell(p, hint, false);
        if (celli >= 0)
        {
            return celli;
        }
    }
    return search_.findCell(p, -1, true);
}

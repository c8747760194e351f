#include "hintedLocate.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
    defineTypeNameAndDebug(hintedLocate, 0);
    addToRunTimeSelectionTable(locateModel, hintedLocate, dictionary);
}


Foam::hintedLocate::hintedLocate
(
    const word& modelType,
    const dictionary& dict,
    const fvMesh& mesh
)
:
    locateModel(modelType, dict, mesh)
{}


Foam::label Foam::hintedLocate::findCell(const point& p, label hint) const
{
    if (hint >= 0 && hint < mesh_.nCells())
    {
        if (mesh_.pointInCell(p, hint, polyMesh::CELL_TETS))
        {
            return hint;
        }
        for (const label nbr : mesh_.cellCells()[hint])
        {
            if (mesh_.pointInCell(p, nbr, polyMesh::CELL_TETS))
            {
                return nbr;
            }
        }
    }
    return mesh_.findCell(p);
}

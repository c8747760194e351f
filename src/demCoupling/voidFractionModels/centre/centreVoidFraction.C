#include "centreVoidFraction.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
    defineTypeNameAndDebug(centreVoidFraction, 0);
    addToRunTimeSelectionTable(voidFractionModel, centreVoidFraction, dictionary);
}


Foam::centreVoidFraction::centreVoidFraction
(
    const word& modelType,
    const dictionary& dict,
    const fvMesh& mesh,
    const locateModel& locate
)
:
    voidFractionModel(modelType, dict, mesh, locate)
{}


void Foam::centreVoidFraction::distribute
(
    const point&,
    scalar,
    label centreCell,
    DynamicList<label>& cells,
    DynamicList<scalar>& weights
) const
{
    if (centreCell >= 0)
    {
        cells.append(centreCell);
        weights.append(1);
    }
}

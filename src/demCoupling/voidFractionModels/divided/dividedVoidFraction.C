#include "dividedVoidFraction.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
    defineTypeNameAndDebug(dividedVoidFraction, 0);
    addToRunTimeSelectionTable(voidFractionModel, dividedVoidFraction, dictionary);
}


Foam::dividedVoidFraction::dividedVoidFraction
(
    const word& modelType,
    const dictionary& dict,
    const fvMesh& mesh,
    const locateModel& locate
)
:
    voidFractionModel(modelType, dict, mesh, locate),
    offsets_(),
    bounds_(mesh.points(), false)
{
    const label nShells = coeffs_.getOrDefault<label>("nShells", 2);
    if (nShells < 1)
    {
        FatalIOErrorInFunction(coeffs_)
            << "nShells must be >= 1 in " << coeffs_.name()
            << exit(FatalIOError);
    }
    List<vector> dirs;
    for (int i = 0; i < 3; ++i)
    {
        vector v(Zero);
        v[i] = 1;
        dirs.append(v);
        dirs.append(-v);
    }
    for (int sx = -1; sx <= 1; sx += 2)
    for (int sy = -1; sy <= 1; sy += 2)
    for (int sz = -1; sz <= 1; sz += 2)
    {
        dirs.append(vector(sx, sy, sz)/sqrt(3.0));
    }
    // Centre plus shells; the centre point carries one weight like the others
    offsets_.append(vector::zero);
    const scalar c45 = sqrt(0.5);
    for (label k = 0; k < nShells; ++k)
    {
        const scalar rk = cbrt((k + 0.5)/nShells);
        for (const vector& d : dirs)
        {
            vector e(d);
            if (k % 2)
            {
                e = vector(c45*(d.x() - d.y()), c45*(d.x() + d.y()), d.z());
            }
            offsets_.append(rk*e);
        }
    }
}


void Foam::dividedVoidFraction::updateMesh() const
{
    if (mesh_.moving() || mesh_.topoChanging())
    {
        bounds_ = boundBox(mesh_.points(), false);
    }
}


void Foam::dividedVoidFraction::distribute
(
    const point& c,
    scalar r,
    label centreCell,
    DynamicList<label>& cells,
    DynamicList<scalar>& weights
) const
{
    if (centreCell < 0)
    {
        // Only particles overlapping this processor's box can cover cells here
        const boundBox sphereBox(c - vector(r, r, r), c + vector(r, r, r));
        if (!bounds_.overlaps(sphereBox))
        {
            return;
        }
    }

    const scalar w = 1.0/offsets_.size();
    const label start = cells.size();
    for (const vector& o : offsets_)
    {
        const label celli =
            locate_.findCell(c + r*o, centreCell);
        if (celli < 0)
        {
            continue;
        }
        // Merge with an earlier point of the same particle in that cell
        bool merged = false;
        for (label k = start; k < cells.size(); ++k)
        {
            if (cells[k] == celli)
            {
                weights[k] += w;
                merged = true;
                break;
            }
        }
        if (!merged)
        {
            cells.append(celli);
            weights.append(w);
        }
    }
}

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
    locateModel(modelType, dict, mesh),
    facePlanesExact_(),
    localBounds_(),
    meshEventIndex_(-1)
{
    // The octree fall-back's tet base points and cell tree are built with
    // collective operations: build them here, on every processor, and not
    // at a first use that only some processors reach (a parallel deadlock)
    (void)mesh_.tetBasePtIs();
    (void)mesh_.cellTree();
}


void Foam::hintedLocate::update() const
{
    // Moving or refined meshes: recompute when the mesh has changed
    const label event = mesh_.time().timeIndex();
    if
    (
        facePlanesExact_.size() == mesh_.nCells()
     && (meshEventIndex_ == event || !(mesh_.moving() || mesh_.topoChanging()))
    )
    {
        return;
    }
    meshEventIndex_ = event;
    // Collective, see the constructor; every processor comes here at the
    // first search after a mesh change
    (void)mesh_.tetBasePtIs();
    (void)mesh_.cellTree();

    const pointField& pts = mesh_.points();
    const faceList& faces = mesh_.faces();
    const vectorField& Cf = mesh_.faceCentres();
    const vectorField& Sf = mesh_.faceAreas();

    localBounds_ = boundBox(pts, false);

    // Relative tolerance on distances to face planes (of the cell size)
    const scalar tol = 1e-8;

    facePlanesExact_.setSize(mesh_.nCells());
    forAll(facePlanesExact_, celli)
    {
        const cell& c = mesh_.cells()[celli];
        const scalar len = cbrt(mesh_.cellVolumes()[celli]);
        bool exact = true;
        for (const label facei : c)
        {
            const vector n = Sf[facei]/(mag(Sf[facei]) + VSMALL);
            // Planar face: every vertex on the face plane
            for (const label pointi : faces[facei])
            {
                if (mag((pts[pointi] - Cf[facei]) & n) > tol*len)
                {
                    exact = false;
                    break;
                }
            }
            if (!exact) break;
            // Convex cell: every vertex of the cell behind the face's plane
            const scalar sign = mesh_.faceOwner()[facei] == celli ? 1 : -1;
            for (const label pointi : c.labels(faces))
            {
                if (sign*((pts[pointi] - Cf[facei]) & n) > tol*len)
                {
                    exact = false;
                    break;
                }
            }
            if (!exact) break;
        }
        facePlanesExact_[celli] = exact;
    }
}


bool Foam::hintedLocate::inCell(const point& p, label celli) const
{
    if (!facePlanesExact_[celli])
    {
        return mesh_.pointInCell(p, celli, polyMesh::CELL_TETS);
    }
    const vectorField& Cf = mesh_.faceCentres();
    const vectorField& Sf = mesh_.faceAreas();
    const labelList& own = mesh_.faceOwner();
    for (const label facei : mesh_.cells()[celli])
    {
        const scalar d = (p - Cf[facei]) & Sf[facei];
        if (own[facei] == celli ? d > 0 : d < 0)
        {
            return false;
        }
    }
    return true;
}


Foam::label Foam::hintedLocate::findCell(const point& p, label hint) const
{
    update();
    if (hint >= 0 && hint < mesh_.nCells())
    {
        if (inCell(p, hint))
        {
            return hint;
        }
        for (const label nbr : mesh_.cellCells()[hint])
        {
            if (inCell(p, nbr))
            {
                return nbr;
            }
        }
    }
    if (!localBounds_.contains(p))
    {
        return -1;
    }
    return mesh_.findCell(p);
}

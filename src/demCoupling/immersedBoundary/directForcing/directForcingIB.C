/*---------------------------------------------------------------------------*\
  Hedra: CFD-DEM for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "directForcingIB.H"
#include "fvm.H"
#include "fvc.H"
#include "fvMatrices.H"
#include "syncTools.H"
#include "regionSplit.H"

#include <algorithm>
#include <cmath>
#include <vector>

Foam::directForcingIB::directForcingIB
(
    const volVectorField& U,
    const volScalarField& p,
    const dictionary& dict,
    const scalar nu,
    const bool variableDensity
)
:
    mesh_(U.mesh()),
    nSub_(dict.getOrDefault<label>("nSubSamples", 4)),
    exactFraction_(false),
    pressureCorrection_(dict.getOrDefault<bool>("pressureCorrection", true)),
    nCorrections_(dict.getOrDefault<label>("nCorrections", 1)),
    integral_(dict.getOrDefault<bool>("integralForcing", true)),
    integralThreshold_
    (
        dict.getOrDefault<scalar>("integralThreshold", 0.5)
    ),
    interface_(dict.getOrDefault<word>("interface", "penalised")),
    // Closed by default where it is implemented (8.): the constant-density
    // path with the kept (integral) forcing
    closed_
    (
        dict.getOrDefault<bool>
        (
            "closedSurface",
            integral_ && !variableDensity
        )
    ),
    trappedReportedAt_(-1),
    nu_(nu),
    minCrossing_(dict.getOrDefault<scalar>("minCrossing", 1e-3)),
    beta_
    (
        IOobject
        (
            "betaIB",
            mesh_.time().timeName(),
            mesh_,
            IOobject::NO_READ,
            IOobject::NO_WRITE
        ),
        mesh_,
        dimensionedScalar(dimless/dimTime, Zero),
        "zeroGradient"
    ),
    fullCell_(mesh_.nCells(), false),
    forcedBody_(mesh_.nCells(), -1),
    fIB_
    (
        IOobject
        (
            "fIB",
            mesh_.time().timeName(),
            mesh_,
            IOobject::READ_IF_PRESENT,
            IOobject::AUTO_WRITE
        ),
        mesh_,
        dimensionedVector(dimAcceleration, Zero),
        "zeroGradient"
    ),
    cellMin_(mesh_.nCells()),
    cellMax_(mesh_.nCells()),
    cellHalfDiag_(mesh_.nCells()),
    lambda_
    (
        IOobject
        (
            "lambda",
            mesh_.time().timeName(),
            mesh_,
            IOobject::NO_READ,
            IOobject::AUTO_WRITE
        ),
        mesh_,
        dimensionedScalar(dimless, Zero),
        "zeroGradient"
    ),
    Us_
    (
        IOobject
        (
            "Us",
            mesh_.time().timeName(),
            mesh_,
            IOobject::NO_READ,
            IOobject::AUTO_WRITE
        ),
        mesh_,
        dimensionedVector(dimVelocity, Zero),
        "zeroGradient"
    ),
    cellBody_(mesh_.nCells(), -1),
    phiIB_
    (
        IOobject
        (
            "phiIB",
            mesh_.time().timeName(),
            mesh_,
            IOobject::READ_IF_PRESENT,  // the solver's initial guess: a
            IOobject::AUTO_WRITE        // restart continues bit for bit
        ),
        mesh_,
        dimensionedScalar(dimArea/dimTime, Zero),
        p.boundaryField().types()
    ),
    solidVolume_(0),
    solidCentroid_(mesh_.C())
{
    if (nSub_ < 1 || nSub_ > maxSubSamples)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'nSubSamples' of " << dict.name() << " must be in [1, "
            << maxSubSamples << "], not " << nSub_ << nl
            << "    (n^3 samples per interface cell: 4 is the default, 8 is"
            << " fine; more costs n^3 and gains 1/n^2)" << exit(FatalIOError);
    }
    {
        const word sf(dict.getOrDefault<word>("solidFraction", "exact"));
        if (sf == "exact")
        {
            exactFraction_ = true;
        }
        else if (sf != "subSampled")
        {
            FatalIOErrorInFunction(dict)
                << "Entry 'solidFraction' of " << dict.name() << " is "
                << sf << ", not one of subSampled, exact" << nl
                << "    (exact: the cell boxes clipped by the polyhedra's"
                << " faces; spheres are sub-sampled either way)"
                << exit(FatalIOError);
        }
    }
    if (nCorrections_ < 1)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'nCorrections' of " << dict.name()
            << " must be >= 1 (forcing-pressure corrections per step), not "
            << nCorrections_ << exit(FatalIOError);
    }
    if (!(integralThreshold_ > 0 && integralThreshold_ <= 1))
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'integralThreshold' of " << dict.name()
            << " must be in (0, 1] (the solid fraction from which a cell is"
            << " forced to the body velocity), not " << integralThreshold_
            << exit(FatalIOError);
    }
    if (!(minCrossing_ > 0 && minCrossing_ < 0.5))
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'minCrossing' of " << dict.name()
            << " must be in (0, 0.5) (a fraction of the cell-centre"
            << " distance), not " << minCrossing_ << exit(FatalIOError);
    }
    if
    (
        interface_ != "explicit" && interface_ != "penalised"
     && interface_ != "none"
    )
    {
        FatalIOErrorInFunction(dict)
            << "interface " << interface_ << " is not one of explicit, "
            << "penalised, none" << exit(FatalIOError);
    }
    if (interface_ != "explicit" && !integral_)
    {
        FatalIOErrorInFunction(dict)
            << "interface " << interface_ << " needs integralForcing true "
            << "(only the explicit interface has a one-step form)"
            << exit(FatalIOError);
    }
    if (closed_ && !integral_)
    {
        FatalIOErrorInFunction(dict)
            << "closedSurface true needs integralForcing true (the full"
            << " cells carry the kept forcing)" << exit(FatalIOError);
    }
    if (closed_ && variableDensity)
    {
        // Measured in demInterFoam (docs/models.md, "Closed surface"); the
        // open surface, this mode's default, runs the same cases through
        IOWarningInFunction(dict)
            << "closedSurface true in " << dict.name() << ": bodies a few"
            << " cells apart (rocks in a pile, blocks side by side) may be"
            << " pushed apart by fluid forces growing from step to step (the"
            << " added-mass instability of the explicit coupling in a narrow"
            << " gap; the rock pile tutorial: bursts up to 7.3 kN). Leave it"
            << " false (the default) unless the bodies stay apart" << endl;
    }
    mesh_.setFluxRequired(phiIB_.name());
    updateCellBoxes();
}


void Foam::directForcingIB::updateCellBoxes()
{
    const pointField& pts = mesh_.points();
    const labelListList& cp = mesh_.cellPoints();
    cellMin_.setSize(mesh_.nCells());
    cellMax_.setSize(mesh_.nCells());
    cellHalfDiag_.setSize(mesh_.nCells());
    cellBody_.setSize(mesh_.nCells());
    fullCell_.setSize(mesh_.nCells());
    forcedBody_.setSize(mesh_.nCells());
    solidCentroid_ = mesh_.C();
    forAll(cp, celli)
    {
        point lo(GREAT, GREAT, GREAT), hi(-GREAT, -GREAT, -GREAT);
        for (const label pi : cp[celli])
        {
            lo = min(lo, pts[pi]);
            hi = max(hi, pts[pi]);
        }
        cellMin_[celli] = lo;
        cellMax_[celli] = hi;
        cellHalfDiag_[celli] = 0.5*mag(hi - lo);
    }
}


namespace
{

using namespace Foam;

//- A convex polyhedron as its faces, each a vertex loop counter-clockwise
//  seen from outside, stored flat (face f: points off[f] .. off[f+1]-1) so
//  that clipping reuses its buffers instead of allocating per face
struct flatPolyhedron
{
    std::vector<point> p;
    std::vector<int> off;

    void clear()
    {
        p.clear();
        off.assign(1, 0);
    }

    int nFaces() const
    {
        return int(off.size()) - 1;
    }
};

//- A key growing monotonically with the angle of (x, y) (no atan2)
inline scalar pseudoAngle(scalar x, scalar y)
{
    const scalar r = mag(x) + mag(y);
    if (r <= 0)
    {
        return 0;
    }
    const scalar t = y/r;           // in [-1, 1]
    return x >= 0 ? t : (y >= 0 ? 2 - t : -2 - t);
}

//- Clip the convex polyhedron 'in' to n.x <= o into 'out': each face by
//  Sutherland-Hodgman, the cut closed by the polygon of the cut points on
//  the plane (ordered by angle about their mean, counter-clockwise seen
//  along +n, i.e. from outside the clipped part). tol: distance counted as
//  on the plane. A face lying in the plane already closes the clipped part
//  there (a body face on a cell face): no cap then
void clipConvex
(
    const flatPolyhedron& in,
    flatPolyhedron& out,
    const vector& n,
    scalar o,
    scalar tol
)
{
    static thread_local std::vector<point> cut;
    static thread_local std::vector<std::pair<scalar, int>> order;
    out.clear();
    cut.clear();
    bool faceOnPlane = false;
    for (int f = 0; f < in.nFaces(); ++f)
    {
        const int b = in.off[f];
        const int m = in.off[f + 1] - b;
        const size_t start = out.p.size();
        bool allOn = true;
        for (int k = 0; k < m; ++k)
        {
            allOn = allOn && mag((n & in.p[b + k]) - o) <= tol;
        }
        if (allOn)
        {
            faceOnPlane = true;
            out.p.insert(out.p.end(), in.p.begin() + b, in.p.begin() + b + m);
            out.off.push_back(int(out.p.size()));
            continue;
        }
        for (int k = 0; k < m; ++k)
        {
            const point& pa = in.p[b + k];
            const point& pb = in.p[b + (k + 1) % m];
            const scalar ha = (n & pa) - o;
            const scalar hb = (n & pb) - o;
            const bool ina = ha <= tol;
            const bool inb = hb <= tol;
            if (ina)
            {
                out.p.push_back(pa);
                if (ha >= -tol)
                {
                    cut.push_back(pa);
                }
            }
            if (ina != inb && mag(ha - hb) > VSMALL)
            {
                const point x = pa + (ha/(ha - hb))*(pb - pa);
                out.p.push_back(x);
                cut.push_back(x);
            }
        }
        if (out.p.size() - start >= 3)
        {
            out.off.push_back(int(out.p.size()));
        }
        else
        {
            out.p.resize(start);
        }
    }
    if (cut.size() >= 3 && !faceOnPlane)
    {
        point c(Zero);
        for (const point& x : cut)
        {
            c += x;
        }
        c /= scalar(cut.size());
        // A basis of the plane, (e1, e2, n) right-handed
        const vector t =
            mag(n.x()) < 0.9 ? vector(1, 0, 0) : vector(0, 1, 0);
        const vector e1 = (t - (t & n)*n)/mag(t - (t & n)*n);
        const vector e2 = n ^ e1;
        order.clear();
        for (size_t k = 0; k < cut.size(); ++k)
        {
            const vector d = cut[k] - c;
            order.emplace_back(pseudoAngle(d & e1, d & e2), int(k));
        }
        std::sort(order.begin(), order.end());
        for (const auto& ok : order)
        {
            out.p.push_back(cut[ok.second]);
        }
        out.off.push_back(int(out.p.size()));
    }
}

} // End anonymous namespace


Foam::scalar Foam::directForcingIB::exactBoxFraction
(
    const point& lo,
    const point& hi,
    const ibBody& b,
    point& centroid
)
{
    centroid = 0.5*(lo + hi);
    const vector span = hi - lo;
    const scalar Vbox = span.x()*span.y()*span.z();
    if (Vbox <= 0)
    {
        return 0;
    }
    const scalar tol = 1e-12*max(mag(span), b.radius);

    // The box's faces, counter-clockwise from outside
    auto P = [&](int i, int j, int k)
    {
        return point(i ? hi.x() : lo.x(), j ? hi.y() : lo.y(), k ? hi.z() : lo.z());
    };
    static thread_local flatPolyhedron bufA, bufB;
    flatPolyhedron* cur = &bufA;
    flatPolyhedron* nxt = &bufB;
    cur->p =
    {
        P(0,0,0), P(0,0,1), P(0,1,1), P(0,1,0),   // -x
        P(1,0,0), P(1,1,0), P(1,1,1), P(1,0,1),   // +x
        P(0,0,0), P(1,0,0), P(1,0,1), P(0,0,1),   // -y
        P(0,1,0), P(0,1,1), P(1,1,1), P(1,1,0),   // +y
        P(0,0,0), P(0,1,0), P(1,1,0), P(1,0,0),   // -z
        P(0,0,1), P(1,0,1), P(1,1,1), P(0,1,1)    // +z
    };
    cur->off = {0, 4, 8, 12, 16, 20, 24};

    // The body's face planes in the world frame: n_w . x <= n_w . x_p + d.
    // Only the planes that cut the box clip it (the clipped part stays in
    // the box): most of a body's planes leave a cell it cuts whole
    forAll(b.faceNormals, f)
    {
        const vector nw = b.orientation & b.faceNormals[f];
        const scalar o = (nw & b.position) + b.faceOffsets[f];
        bool anyOut = false, allOut = true;
        for (int k = 0; k < 8; ++k)
        {
            const scalar h = (nw & P(k & 1, k & 2, k & 4)) - o;
            anyOut = anyOut || h > tol;
            allOut = allOut && h > -tol;
        }
        if (!anyOut)
        {
            continue;
        }
        if (allOut)
        {
            return 0;
        }
        clipConvex(*cur, *nxt, nw, o, tol);
        std::swap(cur, nxt);
        if (cur->nFaces() < 4)
        {
            return 0;
        }
    }
    const flatPolyhedron& poly = *cur;

    // Volume and first moment: tetrahedra from the mean vertex to the
    // faces' fan triangles
    point r(Zero);
    for (const point& x : poly.p)
    {
        r += x;
    }
    r /= scalar(poly.p.size());
    scalar V = 0;
    vector M(Zero);
    for (int f = 0; f < poly.nFaces(); ++f)
    {
        const int b0 = poly.off[f];
        for (int k = b0 + 1; k + 1 < poly.off[f + 1]; ++k)
        {
            const vector a = poly.p[b0] - r;
            const vector bb = poly.p[k] - r;
            const vector c = poly.p[k + 1] - r;
            const scalar v = (a & (bb ^ c))/6;
            V += v;
            M += v*(a + bb + c)/4;
        }
    }
    if (V <= 0)
    {
        return 0;
    }
    centroid = r + M/V;
    return min(V/Vbox, scalar(1));
}


Foam::scalar Foam::directForcingIB::cellFraction
(
    label celli,
    const ibBody& b,
    point& centroid
) const
{
    const point& lo = cellMin_[celli];
    const point& hi = cellMax_[celli];
    centroid = 0.5*(lo + hi);

    // All corners inside a convex body: the whole box is inside
    bool allIn = true;
    for (label k = 0; k < 8 && allIn; ++k)
    {
        const point c
        (
            (k & 1) ? hi.x() : lo.x(),
            (k & 2) ? hi.y() : lo.y(),
            (k & 4) ? hi.z() : lo.z()
        );
        allIn = b.inside(c);
    }
    if (allIn)
    {
        return 1;
    }

    if (exactFraction_ && b.polyhedron)
    {
        return exactBoxFraction(lo, hi, b, centroid);
    }

    const vector h = (hi - lo)/scalar(nSub_);
    label nIn = 0;
    vector sum(Zero);
    for (label i = 0; i < nSub_; ++i)
    {
        for (label j = 0; j < nSub_; ++j)
        {
            for (label k = 0; k < nSub_; ++k)
            {
                const point x
                (
                    lo.x() + (i + 0.5)*h.x(),
                    lo.y() + (j + 0.5)*h.y(),
                    lo.z() + (k + 0.5)*h.z()
                );
                if (b.inside(x))
                {
                    ++nIn;
                    sum += x;
                }
            }
        }
    }
    if (nIn > 0)
    {
        centroid = sum/scalar(nIn);
    }
    return scalar(nIn)/scalar(nSub_*nSub_*nSub_);
}


void Foam::directForcingIB::update(const UList<ibBody>& bodies)
{
    // Refined or moved mesh (dynamicFvMesh): new cells, new boxes
    if (cellMin_.size() != mesh_.nCells() || mesh_.changing())
    {
        updateCellBoxes();
    }

    scalarField& lam = lambda_.primitiveFieldRef();
    vectorField& us = Us_.primitiveFieldRef();
    lam = 0;
    us = Zero;
    cellBody_ = -1;
    solidCentroid_ = mesh_.C();

    const vectorField& C = mesh_.C();

    // Penalised interface: signed distance of each cell centre from the
    // nearest surface, found in the same sweep as the solid fraction
    const bool penalised = (interface_ == "penalised");
    scalarField sMin(penalised ? C.size() : 0, GREAT);
    labelList nearest(penalised ? C.size() : 0, -1);

    forAll(bodies, bi)
    {
        const ibBody& b = bodies[bi];
        forAll(C, celli)
        {
            const scalar reach = b.radius + cellHalfDiag_[celli];
            if (magSqr(C[celli] - b.position) > reach*reach)
            {
                continue;
            }
            if (penalised)
            {
                const scalar sd = b.signedDistance(C[celli]);
                if (sd < sMin[celli])
                {
                    sMin[celli] = sd;
                    nearest[celli] = bi;
                }
            }
            point centroid;
            const scalar f = cellFraction(celli, b, centroid);
            // Overlapping bodies (contact): the larger share owns the cell
            if (f > lam[celli])
            {
                lam[celli] = f;
                solidCentroid_[celli] = centroid;
                cellBody_[celli] = bi;
                us[celli] = b.rigidVelocity(C[celli]);
            }
        }
    }

    // Cells forced fully (kept forcing) and, penalised interface, the
    // interface cells outside the surface with their penalisation rate
    scalarField& beta = beta_.primitiveFieldRef();
    beta = 0;
    fullCell_ = false;
    forcedBody_ = -1;
    if (penalised)
    {
        // Full cells: centre inside a body (the nearest surface's body)
        const scalarField& V = mesh_.V();
        // Body of each full cell, -1 elsewhere (also across coupled faces)
        labelList fullBody(C.size(), -1);
        forAll(C, celli)
        {
            if (nearest[celli] >= 0 && sMin[celli] <= 0)
            {
                fullBody[celli] = nearest[celli];
                fullCell_[celli] = true;
                forcedBody_[celli] = nearest[celli];
                us[celli] = bodies[nearest[celli]].rigidVelocity(C[celli]);
            }
        }

        // Interface cells: a fluid cell next to a full one across face f
        // sees the wall at the fraction theta of the way to that cell's
        // centre instead of at the centre itself; the sink
        //     beta_f = nu |S_f|/(|d| V_c) (1 - theta)/theta
        // is the difference between the two one-sided gradients (a
        // Shortley-Weller wall), so that the no-slip point of the linear
        // profile falls on the surface
        const labelUList& own = mesh_.owner();
        const labelUList& nei = mesh_.neighbour();
        const vectorField& Sf = mesh_.Sf();
        auto addFace = [&]
        (
            const label c, const point& xNbr, const label bi, const scalar magSf
        )
        {
            const ibBody& b = bodies[bi];
            const scalar magD = mag(xNbr - C[c]);
            const scalar theta =
                max(b.entryFraction(C[c], xNbr), minCrossing_);
            beta[c] += nu_*magSf/(magD*V[c])*(1 - theta)/theta;
            forcedBody_[c] = bi;
            us[c] = b.rigidVelocity(C[c]);
        };
        forAll(nei, facei)
        {
            const label o = own[facei], n = nei[facei];
            if (fullBody[o] >= 0 && fullBody[n] < 0)
            {
                addFace(n, C[o], fullBody[o], mag(Sf[facei]));
            }
            else if (fullBody[n] >= 0 && fullBody[o] < 0)
            {
                addFace(o, C[n], fullBody[n], mag(Sf[facei]));
            }
        }
        labelList nbrFullBody;
        syncTools::swapBoundaryCellList(mesh_, fullBody, nbrFullBody);
        pointField nbrC;
        syncTools::swapBoundaryCellPositions(mesh_, C, nbrC);
        const polyBoundaryMesh& pbm = mesh_.boundaryMesh();
        for (const polyPatch& pp : pbm)
        {
            if (!pp.coupled())
            {
                continue;
            }
            forAll(pp, i)
            {
                const label facei = pp.start() + i;
                const label bFacei = facei - mesh_.nInternalFaces();
                const label c = own[facei];
                if (fullBody[c] < 0 && nbrFullBody[bFacei] >= 0)
                {
                    addFace
                    (
                        c,
                        nbrC[bFacei],
                        nbrFullBody[bFacei],
                        mag(mesh_.faceAreas()[facei])
                    );
                }
            }
        }
    }
    else if (integral_)
    {
        const bool explicitInterface = (interface_ == "explicit");
        forAll(C, celli)
        {
            if (cellBody_[celli] >= 0 && lam[celli] >= integralThreshold_)
            {
                fullCell_[celli] = true;
                forcedBody_[celli] = cellBody_[celli];
            }
            else if (cellBody_[celli] >= 0 && explicitInterface)
            {
                forcedBody_[celli] = cellBody_[celli];
            }
        }
    }
    else
    {
        forcedBody_ = cellBody_;
    }
    beta_.correctBoundaryConditions();

    lambda_.correctBoundaryConditions();
    Us_.correctBoundaryConditions();

    // Cells a body has left (or that are no longer forced fully) carry no
    // kept forcing
    vectorField& fib = fIB_.primitiveFieldRef();
    forAll(fib, celli)
    {
        if (!fullCell_[celli])
        {
            fib[celli] = Zero;
        }
    }
    fIB_.correctBoundaryConditions();

    solidVolume_ = gSum(lam*mesh_.V().field());
}


template<class RhoOf, class PenalOf>
void Foam::directForcingIB::correctVelocityWith
(
    volVectorField& U,
    const RhoOf& rhoOf,
    const PenalOf& penalOf,
    const UList<ibBody>& bodies
)
{
    force_.setSize(bodies.size());
    torque_.setSize(bodies.size());
    force_ = Zero;
    torque_ = Zero;

    const scalar dt = mesh_.time().deltaTValue();
    const vectorField& C = mesh_.C();
    const scalarField& V = mesh_.V();
    const scalarField& lam = lambda_.primitiveField();
    const vectorField& us = Us_.primitiveField();
    vectorField& u = U.primitiveFieldRef();
    vectorField& fib = fIB_.primitiveFieldRef();

    const scalarField& beta = beta_.primitiveField();

    forAll(u, celli)
    {
        const label bi = forcedBody_[celli];
        if (bi < 0)
        {
            continue;
        }
        vector f(Zero);     // force on the fluid
        if (fullCell_[celli])
        {
            // Kept forcing drives U to Us exactly
            const vector du = us[celli] - u[celli];
            fib[celli] += du/dt;
            f = rhoOf(celli)*fib[celli]*V[celli];
            u[celli] += du;
        }
        else if (beta[celli] > 0)
        {
            // Penalised interface cell: the implicit source of the
            // momentum equation, evaluated with the solved velocity
            f = penalOf(celli)*beta[celli]*(us[celli] - u[celli])*V[celli];
        }
        else
        {
            // Explicit interface: one-step correction weighted by lambda
            const vector du = lam[celli]*(us[celli] - u[celli]);
            f = rhoOf(celli)*du*V[celli]/dt;
            u[celli] += du;
        }
        force_[bi] -= f;
        torque_[bi] -= (C[celli] - bodies[bi].position) ^ f;
    }
    U.correctBoundaryConditions();
    fIB_.correctBoundaryConditions();

    // Bodies spanning processors: sum the parts
    Pstream::listCombineGather(force_, plusEqOp<vector>());
    Pstream::listCombineScatter(force_);
    Pstream::listCombineGather(torque_, plusEqOp<vector>());
    Pstream::listCombineScatter(torque_);
}


void Foam::directForcingIB::correctVelocity
(
    volVectorField& U,
    scalar rhoFluid,
    const UList<ibBody>& bodies
)
{
    const auto rhoOf = [rhoFluid](const label) { return rhoFluid; };
    correctVelocityWith(U, rhoOf, rhoOf, bodies);
}


void Foam::directForcingIB::correctVelocity
(
    volVectorField& U,
    const volScalarField& rho,
    const volScalarField& mu,
    const UList<ibBody>& bodies
)
{
    // Closed surface (8.) in the variable-density path: the solver's
    // pressure equation closes the full cells' faces (demInterFoam pEqn.H)
    const scalarField& r = rho.primitiveField();
    const scalarField& m = mu.primitiveField();
    const scalar nu = nu_;
    correctVelocityWith
    (
        U,
        [&r](const label c) { return r[c]; },
        [&m, nu](const label c) { return m[c]/nu; },
        bodies
    );
}


Foam::tmp<Foam::fvVectorMatrix> Foam::directForcingIB::source
(
    const volVectorField& U,
    const volScalarField& rho,
    const volScalarField& mu
) const
{
    tmp<fvVectorMatrix> tS(new fvVectorMatrix(U, dimForce));
    fvVectorMatrix& S = tS.ref();
    S += rho*fIB_;
    if (interface_ == "penalised")
    {
        // beta is per nu_ (built with the constructor's nu): mu beta/nu
        const volScalarField muBeta
        (
            "muBetaIB",
            mu/dimensionedScalar("nu", dimViscosity, nu_)*beta_
        );
        S += muBeta*Us_ - fvm::Sp(muBeta, U);
    }
    return tS;
}


void Foam::directForcingIB::bodyMomentum
(
    const volVectorField& U,
    const volScalarField& rho,
    const UList<ibBody>& bodies,
    List<vector>& P,
    List<vector>& L,
    List<scalar>& M,
    List<vector>& S
) const
{
    P.setSize(bodies.size());
    L.setSize(bodies.size());
    M.setSize(bodies.size());
    S.setSize(bodies.size());
    P = Zero;
    L = Zero;
    M = Zero;
    S = Zero;

    const vectorField& C = mesh_.C();
    const scalarField& V = mesh_.V();
    const scalarField& lam = lambda_.primitiveField();
    const scalarField& r = rho.primitiveField();
    const vectorField& u = U.primitiveField();

    forAll(u, celli)
    {
        const label bi = cellBody_[celli];
        if (bi < 0)
        {
            continue;
        }
        const scalar m = r[celli]*lam[celli]*V[celli];
        const vector rc = C[celli] - bodies[bi].position;
        M[bi] += m;
        // The first moment at the solid part's centroid, not the cell's:
        // the hydrostatic moment is a small difference of such moments
        S[bi] += m*(solidCentroid_[celli] - bodies[bi].position);
        P[bi] += m*u[celli];
        L[bi] += rc ^ (m*u[celli]);
    }

    Pstream::listCombineGather(P, plusEqOp<vector>());
    Pstream::listCombineScatter(P);
    Pstream::listCombineGather(L, plusEqOp<vector>());
    Pstream::listCombineScatter(L);
    Pstream::listCombineGather(M, plusEqOp<scalar>());
    Pstream::listCombineScatter(M);
    Pstream::listCombineGather(S, plusEqOp<vector>());
    Pstream::listCombineScatter(S);
}


void Foam::directForcingIB::fillSolidCells
(
    volScalarField& f,
    const vector& g
) const
{
    const scalarField& lam = lambda_.primitiveField();
    boolList known(mesh_.nCells(), true);
    forAll(lam, celli)
    {
        if (cellBody_[celli] >= 0 && lam[celli] >= 1)
        {
            known[celli] = false;
        }
    }
    fillCells(f, g, known);
}


void Foam::directForcingIB::fillBodyCells
(
    volScalarField& f,
    const vector& g
) const
{
    // Only the fully forced cells: an interface cell's fluid part is at
    // least half of it (its centre is outside the convex body), and the
    // level continued into it from a sheet of water running along the
    // floor would give the body's part water under air there (a heavy
    // cell among light ones, accelerated by gh grad rho and held only by
    // the penalisation: the rock pile's air blew up beside the rocks)
    boolList known(notFullCells());
    fillCells(f, g, known);
}


Foam::boolList Foam::directForcingIB::notFullCells() const
{
    boolList notFull(mesh_.nCells(), true);
    forAll(fullCell_, celli)
    {
        notFull[celli] = !fullCell_[celli];
    }
    return notFull;
}


void Foam::directForcingIB::fillSolidPressure(volScalarField& p) const
{
    boolList known(notFullCells());
    // g = 0: every face counts from the first pass on
    fillCells(p, vector::zero, known);
}


void Foam::directForcingIB::fillCells
(
    volScalarField& f,
    const vector& g,
    boolList& known
) const
{
    scalarField& v = f.primitiveFieldRef();
    label nUnknown = 0;
    forAll(known, celli)
    {
        if (!known[celli])
        {
            ++nUnknown;
        }
    }
    if (returnReduce(nUnknown, sumOp<label>()) == 0)
    {
        return;
    }

    const vector gHat = g/max(mag(g), VSMALL);
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const vectorField& Sf = mesh_.Sf();
    const polyBoundaryMesh& pbm = mesh_.boundaryMesh();

    // Pass 0: across faces normal to g only (the level continues
    // horizontally); pass 1: across any face
    for (label pass = 0; pass < 2; ++pass)
    {
        while (true)
        {
            // Sums of the known neighbours' values (Jacobi sweep: the cells
            // found in this sweep are used from the next one on)
            scalarField sum(mesh_.nCells(), Zero);
            labelList n(mesh_.nCells(), Zero);
            auto useFace = [&](const vector& S)
            {
                return pass == 1 || mag(S & gHat) < 0.5*mag(S);
            };
            forAll(nei, facei)
            {
                if (!useFace(Sf[facei]))
                {
                    continue;
                }
                const label o = own[facei], ne = nei[facei];
                if (!known[o] && known[ne])
                {
                    sum[o] += v[ne];
                    ++n[o];
                }
                else if (!known[ne] && known[o])
                {
                    sum[ne] += v[o];
                    ++n[ne];
                }
            }
            // Across processor boundaries
            boolList nbrKnown;
            syncTools::swapBoundaryCellList(mesh_, known, nbrKnown);
            scalarField nbrV;
            syncTools::swapBoundaryCellList(mesh_, v, nbrV);
            for (const polyPatch& pp : pbm)
            {
                if (!pp.coupled())
                {
                    continue;
                }
                forAll(pp, i)
                {
                    const label facei = pp.start() + i;
                    const label bFacei = facei - mesh_.nInternalFaces();
                    const label c = own[facei];
                    if
                    (
                        !known[c] && nbrKnown[bFacei]
                     && useFace(mesh_.faceAreas()[facei])
                    )
                    {
                        sum[c] += nbrV[bFacei];
                        ++n[c];
                    }
                }
            }

            label nSet = 0;
            forAll(v, celli)
            {
                if (!known[celli] && n[celli] > 0)
                {
                    v[celli] = sum[celli]/n[celli];
                    known[celli] = true;
                    ++nSet;
                    --nUnknown;
                }
            }
            if (returnReduce(nSet, sumOp<label>()) == 0)
            {
                break;
            }
        }
        if (returnReduce(nUnknown, sumOp<label>()) == 0)
        {
            break;
        }
    }
    f.correctBoundaryConditions();
}


Foam::tmp<Foam::fvVectorMatrix> Foam::directForcingIB::source
(
    const volVectorField& U
) const
{
    tmp<fvVectorMatrix> tS(new fvVectorMatrix(U, dimVolume*dimAcceleration));
    fvVectorMatrix& S = tS.ref();
    S += fIB_;
    if (interface_ == "penalised")
    {
        S += beta_*Us_ - fvm::Sp(beta_, U);
    }
    return tS;
}


void Foam::directForcingIB::bodyMomentum
(
    const volVectorField& U,
    const UList<ibBody>& bodies,
    List<vector>& P,
    List<vector>& L
) const
{
    P.setSize(bodies.size());
    L.setSize(bodies.size());
    P = Zero;
    L = Zero;

    const vectorField& C = mesh_.C();
    const scalarField& V = mesh_.V();
    const scalarField& lam = lambda_.primitiveField();
    const vectorField& u = U.primitiveField();

    forAll(u, celli)
    {
        const label bi = cellBody_[celli];
        if (bi < 0)
        {
            continue;
        }
        const vector m = lam[celli]*V[celli]*u[celli];
        P[bi] += m;
        L[bi] += (C[celli] - bodies[bi].position) ^ m;
    }

    Pstream::listCombineGather(P, plusEqOp<vector>());
    Pstream::listCombineScatter(P);
    Pstream::listCombineGather(L, plusEqOp<vector>());
    Pstream::listCombineScatter(L);
}


void Foam::directForcingIB::correctPressure
(
    volVectorField& U,
    volScalarField& p,
    surfaceScalarField& phi
)
{
    if (!pressureCorrection_)
    {
        phi = fvc::flux(U);
        return;
    }

    const surfaceScalarField phiU(fvc::flux(U));

    fvScalarMatrix phiIBEqn
    (
        fvm::laplacian(phiIB_) == fvc::div(phiU)
    );
    if (phiIB_.needReference())
    {
        phiIBEqn.setReference(0, 0);
    }
    phiIBEqn.solve();

    phi = phiU - phiIBEqn.flux();
    U -= fvc::grad(phiIB_);
    U.correctBoundaryConditions();
    p += phiIB_/mesh_.time().deltaT();
    p.correctBoundaryConditions();
}


Foam::boolList Foam::directForcingIB::trappedFluidCells
(
    const volScalarField& p
) const
{
    // Fluid regions as the closed faces leave them: every face between a
    // full cell and a fluid cell is a wall (the full cells make regions of
    // their own, one per group of touching bodies, which are not looked at;
    // so the lists below stay as short as the regions are few)
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    boolList nbrFull;
    syncTools::swapBoundaryCellList(mesh_, fullCell_, nbrFull);
    boolList blocked(mesh_.nFaces(), false);
    forAll(nei, facei)
    {
        blocked[facei] = fullCell_[own[facei]] != fullCell_[nei[facei]];
    }
    for (label facei = mesh_.nInternalFaces(); facei < mesh_.nFaces(); ++facei)
    {
        blocked[facei] =
            fullCell_[own[facei]] != nbrFull[facei - mesh_.nInternalFaces()];
    }
    const regionSplit regions(mesh_, blocked);
    const label nRegions = regions.nRegions();

    // Each fluid region's size and whether a patch fixes its pressure
    labelList nFluidCells(nRegions, Zero);
    labelList fixed(nRegions, Zero);
    forAll(fullCell_, celli)
    {
        if (!fullCell_[celli])
        {
            ++nFluidCells[regions[celli]];
        }
    }
    forAll(p.boundaryField(), patchi)
    {
        const fvPatchScalarField& pp = p.boundaryField()[patchi];
        if (pp.coupled() || !pp.fixesValue())
        {
            continue;
        }
        for (const label celli : pp.patch().faceCells())
        {
            if (!fullCell_[celli])
            {
                fixed[regions[celli]] = 1;
            }
        }
    }
    Pstream::listCombineGather(nFluidCells, plusEqOp<label>());
    Pstream::listCombineScatter(nFluidCells);
    Pstream::listCombineGather(fixed, maxEqOp<label>());
    Pstream::listCombineScatter(fixed);

    // Open: every region a patch fixes; where none does (a closed box, the
    // level set by a reference cell), the largest one
    boolList open(nRegions, false);
    bool anyFixed = false;
    label largest = -1;
    forAll(open, regioni)
    {
        open[regioni] = fixed[regioni] > 0;
        anyFixed = anyFixed || open[regioni];
        if
        (
            nFluidCells[regioni] > 0
         && (largest < 0 || nFluidCells[regioni] > nFluidCells[largest])
        )
        {
            largest = regioni;
        }
    }
    if (!anyFixed && largest >= 0)
    {
        open[largest] = true;
    }

    boolList trapped(mesh_.nCells(), false);
    forAll(trapped, celli)
    {
        trapped[celli] = !fullCell_[celli] && !open[regions[celli]];
    }
    return trapped;
}


void Foam::directForcingIB::closeSurface
(
    surfaceScalarField& phiHbyA,
    surfaceScalarField& rAUf,
    const UList<ibBody>& bodies,
    const volScalarField& p
) const
{
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const vectorField& Sf = mesh_.Sf();
    const vectorField& Cf = mesh_.Cf();

    // Body of a face touching a full cell (-1: none; two bodies: the lower
    // index, the same on both sides of a processor face)
    auto faceBody = [](const label bA, const label bB)
    {
        if (bA >= 0 && bB >= 0)
        {
            return min(bA, bB);
        }
        return max(bA, bB);
    };
    labelList fullBody(mesh_.nCells(), -1);
    forAll(fullCell_, celli)
    {
        if (fullCell_[celli])
        {
            fullBody[celli] = forcedBody_[celli];
        }
    }

    // Fluid that the closed faces would cut off keeps its faces open: the
    // held pressure of the bodies' full cells then sets its level (as
    // with the open surface), where closed it would have none
    const boolList trapped(trappedFluidCells(p));
    label nTrapped = 0;
    forAll(trapped, celli)
    {
        if (trapped[celli])
        {
            ++nTrapped;
        }
    }
    reduce(nTrapped, sumOp<label>());
    if (nTrapped > 0 && trappedReportedAt_ != mesh_.time().timeIndex())
    {
        trappedReportedAt_ = mesh_.time().timeIndex();
        Info<< "Closed surface: " << nTrapped << " fluid cells trapped between"
            << " bodies (and walls) keep their faces to the bodies open"
            << endl;
    }

    forAll(nei, facei)
    {
        const label bi = faceBody(fullBody[own[facei]], fullBody[nei[facei]]);
        if (bi >= 0 && !trapped[own[facei]] && !trapped[nei[facei]])
        {
            phiHbyA[facei] = bodies[bi].rigidVelocity(Cf[facei]) & Sf[facei];
            rAUf[facei] = 0;
        }
    }

    labelList nbrFullBody;
    syncTools::swapBoundaryCellList(mesh_, fullBody, nbrFullBody);
    boolList nbrTrapped;
    syncTools::swapBoundaryCellList(mesh_, trapped, nbrTrapped);
    forAll(mesh_.boundary(), patchi)
    {
        const fvPatch& pp = mesh_.boundary()[patchi];
        if (!pp.coupled())
        {
            continue;
        }
        const labelUList& fc = pp.faceCells();
        fvsPatchScalarField& pPhi = phiHbyA.boundaryFieldRef()[patchi];
        fvsPatchScalarField& pRAU = rAUf.boundaryFieldRef()[patchi];
        forAll(pp, i)
        {
            const label bFacei = pp.start() + i - mesh_.nInternalFaces();
            const label bi = faceBody(fullBody[fc[i]], nbrFullBody[bFacei]);
            if (bi >= 0 && !trapped[fc[i]] && !nbrTrapped[bFacei])
            {
                pPhi[i] = bodies[bi].rigidVelocity(pp.Cf()[i]) & pp.Sf()[i];
                pRAU[i] = 0;
            }
        }
    }

    balanceClosedFaces(phiHbyA, fullBody, nbrFullBody, trapped, nbrTrapped, bodies.size());
}


void Foam::directForcingIB::balanceClosedFaces
(
    surfaceScalarField& phiHbyA,
    const labelUList& fullBody,
    const labelUList& nbrFullBody,
    const boolList& trapped,
    const boolList& nbrTrapped,
    const label nBodies
) const
{
    // A body's closed faces to the fluid: the full cell on one side, a
    // fluid cell (not trapped: its faces are open) on the other
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const scalarField& magSf = mesh_.magSf();
    auto fluidFace = [&](const label fullB, const label otherB, const bool t1, const bool t2)
    {
        return fullB >= 0 && otherB < 0 && !t1 && !t2;
    };

    // Net outflow and area of each body's closed fluid faces (each
    // processor face counted on the side of the full cell)
    scalarList netOut(nBodies, Zero);
    scalarList area(nBodies, Zero);
    forAll(nei, facei)
    {
        const label o = own[facei], n = nei[facei];
        if (fluidFace(fullBody[o], fullBody[n], trapped[o], trapped[n]))
        {
            netOut[fullBody[o]] += phiHbyA[facei];
            area[fullBody[o]] += magSf[facei];
        }
        else if (fluidFace(fullBody[n], fullBody[o], trapped[o], trapped[n]))
        {
            netOut[fullBody[n]] -= phiHbyA[facei];
            area[fullBody[n]] += magSf[facei];
        }
    }
    forAll(mesh_.boundary(), patchi)
    {
        const fvPatch& pp = mesh_.boundary()[patchi];
        if (!pp.coupled())
        {
            continue;
        }
        const labelUList& fc = pp.faceCells();
        const fvsPatchScalarField& pPhi = phiHbyA.boundaryField()[patchi];
        forAll(pp, i)
        {
            const label bFacei = pp.start() + i - mesh_.nInternalFaces();
            if (fluidFace(fullBody[fc[i]], nbrFullBody[bFacei], trapped[fc[i]], nbrTrapped[bFacei]))
            {
                netOut[fullBody[fc[i]]] += pPhi[i];
                area[fullBody[fc[i]]] += pp.magSf()[i];
            }
        }
    }
    Pstream::listCombineGather(netOut, plusEqOp<scalar>());
    Pstream::listCombineScatter(netOut);
    Pstream::listCombineGather(area, plusEqOp<scalar>());
    Pstream::listCombineScatter(area);

    // Take each body's net outflow off its faces in proportion to their area
    scalarList perArea(nBodies, Zero);
    forAll(perArea, bi)
    {
        perArea[bi] = area[bi] > 0 ? netOut[bi]/area[bi] : 0;
    }
    forAll(nei, facei)
    {
        const label o = own[facei], n = nei[facei];
        if (fluidFace(fullBody[o], fullBody[n], trapped[o], trapped[n]))
        {
            phiHbyA[facei] -= perArea[fullBody[o]]*magSf[facei];
        }
        else if (fluidFace(fullBody[n], fullBody[o], trapped[o], trapped[n]))
        {
            phiHbyA[facei] += perArea[fullBody[n]]*magSf[facei];
        }
    }
    forAll(mesh_.boundary(), patchi)
    {
        const fvPatch& pp = mesh_.boundary()[patchi];
        if (!pp.coupled())
        {
            continue;
        }
        const labelUList& fc = pp.faceCells();
        fvsPatchScalarField& pPhi = phiHbyA.boundaryFieldRef()[patchi];
        forAll(pp, i)
        {
            const label bFacei = pp.start() + i - mesh_.nInternalFaces();
            if (fluidFace(fullBody[fc[i]], nbrFullBody[bFacei], trapped[fc[i]], nbrTrapped[bFacei]))
            {
                pPhi[i] -= perArea[fullBody[fc[i]]]*pp.magSf()[i];
            }
            else if (fluidFace(nbrFullBody[bFacei], fullBody[fc[i]], trapped[fc[i]], nbrTrapped[bFacei]))
            {
                pPhi[i] += perArea[nbrFullBody[bFacei]]*pp.magSf()[i];
            }
        }
    }
}


void Foam::directForcingIB::closeSurface
(
    fvScalarMatrix& pEqn,
    const volScalarField& rAU
) const
{
    // The full cells' rows are empty (rAUf = 0 on all their faces): give
    // them a diagonal of the Laplacian's sign, 1e-6 of the one they would
    // have had, and hold the value. A full-size diagonal is summed into
    // the multigrid's coarse cells that also hold fluid cells and acts
    // there like a fixed pressure: in a closed box (pure Neumann) the
    // final pressure solve then took 100-150 GAMG iterations instead of
    // 15 (settlingCube)
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const scalarField& magSf = mesh_.magSf();
    const scalarField& dc = mesh_.deltaCoeffs();
    scalarField geo(mesh_.nCells(), Zero);
    forAll(nei, facei)
    {
        geo[own[facei]] += magSf[facei]*dc[facei];
        geo[nei[facei]] += magSf[facei]*dc[facei];
    }
    forAll(mesh_.boundary(), patchi)
    {
        const fvPatch& pp = mesh_.boundary()[patchi];
        const labelUList& fc = pp.faceCells();
        forAll(pp, i)
        {
            geo[fc[i]] += pp.magSf()[i]*pp.deltaCoeffs()[i];
        }
    }

    DynamicList<label> cells;
    DynamicList<scalar> values;
    scalarField& diag = pEqn.diag();
    const scalarField& p = pEqn.psi().primitiveField();
    const scalarField& r = rAU.primitiveField();
    forAll(fullCell_, celli)
    {
        if (fullCell_[celli])
        {
            diag[celli] = -1e-6*r[celli]*geo[celli];
            cells.append(celli);
            values.append(p[celli]);
        }
    }
    pEqn.setValues(cells, values);
}


void Foam::directForcingIB::setWallGhosts
(
    volVectorField& U,
    const UList<ibBody>& bodies
) const
{
    if (!closed_)
    {
        return;
    }
    // The old time level first: a field that has none yet (the first step
    // after a restart) would take it from the first oldTime() call, after
    // the ghosts below, and the restart would not continue the run bit for
    // bit (ibRestartContinuation)
    U.oldTime();
    vectorField& u = U.primitiveFieldRef();
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const vectorField& Cf = mesh_.Cf();
    vectorField sum(mesh_.nCells(), Zero);
    labelList n(mesh_.nCells(), Zero);

    // A full cell next to fluid: the mean over its surface faces of
    // 2 Us(x_f) - U_out, so that the interpolate on the face is the wall's
    // velocity
    forAll(nei, facei)
    {
        const label o = own[facei], ne = nei[facei];
        if (fullCell_[o] == fullCell_[ne])
        {
            continue;
        }
        const label in = fullCell_[o] ? o : ne;
        const label out = fullCell_[o] ? ne : o;
        sum[in] += 2*bodies[forcedBody_[in]].rigidVelocity(Cf[facei]) - u[out];
        ++n[in];
    }
    boolList nbrFull;
    syncTools::swapBoundaryCellList(mesh_, fullCell_, nbrFull);
    vectorField nbrU;
    syncTools::swapBoundaryCellList(mesh_, u, nbrU);
    forAll(mesh_.boundary(), patchi)
    {
        const fvPatch& pp = mesh_.boundary()[patchi];
        if (!pp.coupled())
        {
            continue;
        }
        const labelUList& fc = pp.faceCells();
        forAll(pp, i)
        {
            const label bFacei = pp.start() + i - mesh_.nInternalFaces();
            const label c = fc[i];
            if (fullCell_[c] && !nbrFull[bFacei])
            {
                sum[c] +=
                    2*bodies[forcedBody_[c]].rigidVelocity(pp.Cf()[i])
                  - nbrU[bFacei];
                ++n[c];
            }
        }
    }
    forAll(u, celli)
    {
        if (n[celli] > 0)
        {
            u[celli] = sum[celli]/n[celli];
        }
    }
    U.correctBoundaryConditions();
}


Foam::tmp<Foam::volVectorField> Foam::directForcingIB::wallGrad
(
    const volScalarField& p
) const
{
    if (!closed_)
    {
        return fvc::grad(p);
    }
    tmp<volVectorField> tg(new volVectorField("wallGrad(p)", fvc::grad(p)));
    vectorField& g = tg.ref().primitiveFieldRef();
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const vectorField& Sf = mesh_.Sf();
    const scalarField& w = mesh_.weights();
    const scalarField& V = mesh_.V();
    const scalarField& pc = p.primitiveField();

    // Surface face (full cell on one side only): the fluid cell's value in
    // place of the interpolate, on both sides
    forAll(nei, facei)
    {
        const label o = own[facei], n = nei[facei];
        if (fullCell_[o] == fullCell_[n])
        {
            continue;
        }
        const scalar pWall = fullCell_[o] ? pc[n] : pc[o];
        const scalar dp = pWall - (w[facei]*pc[o] + (1 - w[facei])*pc[n]);
        g[o] += dp*Sf[facei]/V[o];
        g[n] -= dp*Sf[facei]/V[n];
    }
    boolList nbrFull;
    syncTools::swapBoundaryCellList(mesh_, fullCell_, nbrFull);
    forAll(mesh_.boundary(), patchi)
    {
        const fvPatch& pp = mesh_.boundary()[patchi];
        if (!pp.coupled())
        {
            continue;
        }
        const labelUList& fc = pp.faceCells();
        const scalarField pNbr(p.boundaryField()[patchi].patchNeighbourField());
        const scalarField& pw = pp.weights();
        forAll(pp, i)
        {
            const label bFacei = pp.start() + i - mesh_.nInternalFaces();
            const label c = fc[i];
            if (fullCell_[c] == nbrFull[bFacei])
            {
                continue;
            }
            const scalar pWall = fullCell_[c] ? pNbr[i] : pc[c];
            const scalar dp = pWall - (pw[i]*pc[c] + (1 - pw[i])*pNbr[i]);
            g[c] += dp*pp.Sf()[i]/V[c];
        }
    }
    tg.ref().correctBoundaryConditions();
    return tg;
}


void Foam::directForcingIB::correct
(
    volVectorField& U,
    volScalarField& p,
    surfaceScalarField& phi,
    scalar rhoFluid,
    const UList<ibBody>& bodies
)
{
    if (closed_)
    {
        // 8.: phi is the pressure equation's, rigid on the full cells'
        // faces; the correction changes U only in the full cells
        correctVelocity(U, rhoFluid, bodies);
        return;
    }
    List<vector> F(bodies.size(), Zero);
    List<vector> T(bodies.size(), Zero);
    for (label k = 0; k < max(nCorrections_, label(1)); ++k)
    {
        correctVelocity(U, rhoFluid, bodies);
        correctPressure(U, p, phi);
        forAll(F, i)
        {
            // integral forcing: force_ already holds the whole of fIB
            F[i] = integral_ ? force_[i] : F[i] + force_[i];
            T[i] = integral_ ? torque_[i] : T[i] + torque_[i];
        }
    }
    force_ = F;
    torque_ = T;
}


// ************************************************************************* //

#include "submergedVolume.H"
#include "mathematicalConstants.H"

// * * * * * * * * * * * * * * * Local helpers * * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

template<class T, class Op>
void allCombine(List<T>& l, const Op& op)
{
    if (Pstream::parRun())
    {
        Pstream::listCombineGather(l, op);
        Pstream::listCombineScatter(l);
    }
}

//- Clip the polygon p (n points, heights h) to h <= t; returns the points
void clipBelow
(
    const DynamicList<point>& p,
    const DynamicList<scalar>& h,
    scalar t,
    DynamicList<point>& out
)
{
    out.clear();
    const label n = p.size();
    for (label k = 0; k < n; ++k)
    {
        const label k1 = (k + 1) % n;
        const bool in0 = h[k] <= t;
        const bool in1 = h[k1] <= t;
        if (in0)
        {
            out.append(p[k]);
        }
        if (in0 != in1)
        {
            const scalar a = (t - h[k])/(h[k1] - h[k]);
            out.append(p[k] + a*(p[k1] - p[k]));
        }
    }
}

//- Area vector (outward for counter-clockwise loops seen from outside)
vector areaVector(const DynamicList<point>& q)
{
    vector S(Zero);
    for (label k = 1; k + 1 < q.size(); ++k)
    {
        S += 0.5*((q[k] - q[0]) ^ (q[k + 1] - q[0]));
    }
    return S;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::submergedVolume::submergedVolume
(
    const fvMesh& mesh,
    const dictionary& dict
)
:
    mesh_(mesh),
    method_(method::interfacePlane),
    planeBelowSizeRatio_
    (
        dict.getOrDefault<scalar>("interfacePlaneBelowSizeRatio", 2.5)
    ),
    zb_(),
    zt_(),
    geometryTimeIndex_(-1)
{
    const word m(dict.getOrDefault<word>("submergedVolume", "interfacePlane"));
    if (m == "cellWeights")
    {
        method_ = method::cellWeights;
    }
    else if (m == "interfacePlane")
    {
        method_ = method::interfacePlane;
    }
    else if (m != "auto")
    {
        FatalIOErrorInFunction(dict)
            << "Unknown submergedVolume '" << m << "' in " << dict.name()
            << nl << "Valid submergedVolume values: "
            << "(cellWeights interfacePlane auto)" << exit(FatalIOError);
    }
    if (planeBelowSizeRatio_ < 0)
    {
        FatalIOErrorInFunction(dict)
            << "interfacePlaneBelowSizeRatio must be >= 0 in " << dict.name()
            << exit(FatalIOError);
    }
    Info<< "    submerged volume of the particles: " << m;
    if (method_ == method::automatic)
    {
        Info<< " (interfacePlane below a particle/cell height ratio of "
            << planeBelowSizeRatio_ << ", cellWeights above)";
    }
    Info<< endl;
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::submergedVolume::updateCellHeights(const vector& up)
{
    if (zb_.size() == mesh_.nCells() && !mesh_.changing())
    {
        return;
    }
    zb_.setSize(mesh_.nCells());
    zt_.setSize(mesh_.nCells());
    const labelListList& cp = mesh_.cellPoints();
    const pointField& pts = mesh_.points();
    forAll(cp, c)
    {
        scalar lo = GREAT, hi = -GREAT;
        for (const label p : cp[c])
        {
            const scalar z = up & pts[p];
            lo = min(lo, z);
            hi = max(hi, z);
        }
        zb_[c] = lo;
        zt_[c] = hi;
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::submergedVolume::fractionBelow
(
    const point& position,
    const tensor& orientation,
    scalar radius,
    const demShape* shape,
    const vector& up,
    scalar s
)
{
    vector arm;
    return partBelow(position, orientation, radius, shape, up, s, arm);
}


Foam::scalar Foam::submergedVolume::partBelow
(
    const point& position,
    const tensor& orientation,
    scalar radius,
    const demShape* shape,
    const vector& up,
    scalar s,
    vector& arm
)
{
    arm = Zero;
    const scalar t = s - (up & position);

    if (!shape)
    {
        const scalar R = radius;
        if (t <= -R) return 0;
        if (t >= R) return 1;
        return sqr(R + t)*(2*R - t)/(4*pow3(R));
    }

    // Vertices relative to the centre, in the world frame
    const label nv = shape->vertices.size();
    List<point> r(nv);
    scalarList h(nv);
    scalar hMin = GREAT, hMax = -GREAT;
    forAll(r, v)
    {
        r[v] = orientation & shape->vertices[v];
        h[v] = up & r[v];
        hMin = min(hMin, h[v]);
        hMax = max(hMax, h[v]);
    }
    if (t >= hMax) return 1;
    if (t <= hMin) return 0;

    // V = 1/3 sum_faces x_f . S_f (divergence theorem), the clipped faces
    // plus the cap on the plane, whose area vector closes the surface.
    // First moment M = int x dV = 1/4 oint x (x.n) dA: on a clipped face
    // (x.S) c_f, on the cap t int_cap x dA = t (Vbelow up - sum c_f (S_f.up))
    DynamicList<point> poly, clipped;
    DynamicList<scalar> ph;
    scalar V = 0, Vbelow = 0;
    vector Sbelow(Zero), Mfaces(Zero), capMoment(Zero);
    for (const face& fc : shape->faces)
    {
        poly.clear();
        ph.clear();
        for (const label v : fc)
        {
            poly.append(r[v]);
            ph.append(h[v]);
        }
        const vector S = areaVector(poly);
        V += (poly[0] & S)/3;
        clipBelow(poly, ph, t, clipped);
        if (clipped.size() >= 3)
        {
            const vector Sc = areaVector(clipped);
            const scalar magSc = mag(Sc);
            Vbelow += (clipped[0] & Sc)/3;
            Sbelow += Sc;
            if (magSc > 0)
            {
                // Centroid of the (convex) clipped face: its fan's triangles
                // weighted by their areas
                const vector nf = Sc/magSc;
                vector cf(Zero);
                scalar af = 0;
                for (label k = 1; k + 1 < clipped.size(); ++k)
                {
                    const scalar a =
                        0.5*(((clipped[k] - clipped[0]) ^ (clipped[k + 1] - clipped[0])) & nf);
                    cf += a*(clipped[0] + clipped[k] + clipped[k + 1])/3;
                    af += a;
                }
                cf /= max(af, VSMALL);
                Mfaces += (clipped[0] & Sc)*cf;
                capMoment -= cf*(Sc & up);
            }
        }
    }
    Vbelow += ((t*up) & (-Sbelow))/3;

    if (V <= 0)
    {
        return 0;
    }
    if (Vbelow > 0)
    {
        capMoment += Vbelow*up;
        arm = (Mfaces + t*capMoment)/(4*Vbelow);
    }
    return min(max(Vbelow/V, scalar(0)), scalar(1));
}


Foam::vector Foam::submergedVolume::armAtFraction
(
    const point& position,
    const tensor& orientation,
    scalar radius,
    const demShape* shape,
    const vector& up,
    scalar f
)
{
    if (!shape || f <= 0 || f >= 1)
    {
        return Zero;
    }
    // The plane between the lowest and the highest vertex that cuts the
    // fraction f off the shape (fractionBelow grows with s)
    scalar lo = GREAT, hi = -GREAT;
    for (const point& v : shape->vertices)
    {
        const scalar z = up & (orientation & v);
        lo = min(lo, z);
        hi = max(hi, z);
    }
    lo += up & position;
    hi += up & position;
    for (label iter = 0; iter < 50; ++iter)
    {
        const scalar s = 0.5*(lo + hi);
        if (fractionBelow(position, orientation, radius, shape, up, s) > f)
        {
            hi = s;
        }
        else
        {
            lo = s;
        }
    }
    vector arm;
    partBelow(position, orientation, radius, shape, up, 0.5*(lo + hi), arm);
    return arm;
}


Foam::scalar Foam::submergedVolume::height
(
    const tensor& orientation,
    scalar radius,
    const demShape* shape,
    const vector& up
)
{
    if (!shape)
    {
        return 2*radius;
    }
    scalar lo = GREAT, hi = -GREAT;
    for (const point& v : shape->vertices)
    {
        const scalar z = up & (orientation & v);
        lo = min(lo, z);
        hi = max(hi, z);
    }
    return hi - lo;
}


void Foam::submergedVolume::fractions
(
    const demParticleArrays& particles,
    const List<scalar>& volume,
    const List<demShape>& shapes,
    const demCouplingWeights& weights,
    const volScalarField& voidfraction,
    const bool particlesDisplaceFluid,
    const volScalarField& alpha1,
    const vector& g,
    List<scalar>& f,
    List<bool>& usedPlane,
    List<vector>& arm
)
{
    const label n = particles.size();
    const vector up = -g/max(mag(g), VSMALL);
    const scalarField& V = mesh_.V();

    auto shapeOf = [&](label i) -> const demShape*
    {
        const label t = particles.type[i];
        return t < shapes.size() && shapes[t].polyhedron() ? &shapes[t] : nullptr;
    };

    const List<label>& cell = weights.cells();
    const List<label>& wStart = weights.start();
    const List<label>& wCell = weights.cellIndex();
    const List<scalar>& wWeight = weights.weight();

    // cellWeights: f = sum w alpha1
    f = weights.average(alpha1.primitiveField());

    usedPlane.setSize(n);
    usedPlane = false;
    arm.setSize(n);
    arm = Zero;
    // The arm of the cellWeights particles (the plane particles' follows
    // from their plane below)
    auto cellWeightsArms = [&]()
    {
        forAll(arm, i)
        {
            if (!usedPlane[i])
            {
                arm[i] = armAtFraction
                (
                    particles.position[i], particles.orientation[i],
                    particles.radius[i], shapeOf(i), up, f[i]
                );
            }
        }
    };
    if (method_ == method::cellWeights || n == 0)
    {
        cellWeightsArms();
        return;
    }

    updateCellHeights(up);

    // Which particles take the plane: height of the centre cell
    List<scalar> hCell(n, scalar(0));
    forAll(cell, i)
    {
        if (cell[i] >= 0)
        {
            hCell[i] = zt_[cell[i]] - zb_[cell[i]];
        }
    }
    allCombine(hCell, maxEqOp<scalar>());
    labelList planeParticles;
    {
        DynamicList<label> pl;
        forAll(hCell, i)
        {
            if (hCell[i] <= 0)
            {
                continue;   // outside the mesh
            }
            const scalar hp =
                height(particles.orientation[i], particles.radius[i], shapeOf(i), up);
            if
            (
                method_ == method::interfacePlane
             || hp < planeBelowSizeRatio_*hCell[i]
            )
            {
                pl.append(i);
            }
        }
        planeParticles.transfer(pl);
    }
    const label np = planeParticles.size();
    if (np == 0)
    {
        cellWeightsArms();
        return;
    }

    // The local part of S for each plane particle: cells, capacities, water
    const labelListList& cc = mesh_.cellCells();
    const scalarField& eps = voidfraction.primitiveField();
    const scalarField& a1 = alpha1.primitiveField();
    // One-way coupling: the water does not make room for the particle
    const scalar solidShare = particlesDisplaceFluid ? 1 : 0;
    List<DynamicList<label>> Scells(np);
    List<DynamicList<scalar>> Scap(np);
    List<scalar> water(np, scalar(0)), capacity(np, scalar(0));
    List<scalar> zlo(np, GREAT), zhi(np, -GREAT);
    forAll(planeParticles, j)
    {
        const label i = planeParticles[j];
        Map<scalar> own;
        for (label k = wStart[i]; k < wStart[i + 1]; ++k)
        {
            own.set(wCell[k], own.lookup(wCell[k], 0) + wWeight[k]);
        }
        labelHashSet S;
        forAllConstIters(own, it)
        {
            S.set(it.key());
            for (const label nb : cc[it.key()])
            {
                S.set(nb);
            }
        }
        for (const label c : S)
        {
            // The solver's fluid volume (eps at least alphaMin, so it may
            // hold more than V - solid) plus the particle's own solid
            const scalar cap =
                eps[c]*V[c] + solidShare*own.lookup(c, 0)*volume[i];
            Scells[j].append(c);
            Scap[j].append(cap);
            water[j] += a1[c]*eps[c]*V[c];
            capacity[j] += cap;
            zlo[j] = min(zlo[j], zb_[c]);
            zhi[j] = max(zhi[j], zt_[c]);
        }
    }
    allCombine(water, plusEqOp<scalar>());
    allCombine(capacity, plusEqOp<scalar>());
    allCombine(zlo, minEqOp<scalar>());
    allCombine(zhi, maxEqOp<scalar>());

    // Bisection on s, all particles at once (one reduction per iteration)
    List<scalar> lo(zlo), hi(zhi);
    const label nIter = 60;
    for (label iter = 0; iter < nIter; ++iter)
    {
        List<scalar> F(np, scalar(0));
        forAll(planeParticles, j)
        {
            const scalar s = 0.5*(lo[j] + hi[j]);
            forAll(Scells[j], k)
            {
                const label c = Scells[j][k];
                const scalar dz = max(zt_[c] - zb_[c], VSMALL);
                F[j] += Scap[j][k]*min(max((s - zb_[c])/dz, scalar(0)), scalar(1));
            }
        }
        allCombine(F, plusEqOp<scalar>());
        forAll(planeParticles, j)
        {
            const label i = planeParticles[j];
            const scalar s = 0.5*(lo[j] + hi[j]);
            const scalar Fj =
                F[j] - water[j]
              - solidShare*volume[i]
               *fractionBelow
                (
                    particles.position[i], particles.orientation[i],
                    particles.radius[i], shapeOf(i), up, s
                );
            if (Fj > 0)
            {
                hi[j] = s;
            }
            else
            {
                lo[j] = s;
            }
        }
    }

    forAll(planeParticles, j)
    {
        const label i = planeParticles[j];
        usedPlane[i] = true;
        if (water[j] <= 0)
        {
            f[i] = 0;
        }
        else if (water[j] >= capacity[j] - solidShare*volume[i])
        {
            f[i] = 1;   // S full of water: submerged
        }
        else
        {
            f[i] =
                partBelow
                (
                    particles.position[i], particles.orientation[i],
                    particles.radius[i], shapeOf(i), up, 0.5*(lo[j] + hi[j]),
                    arm[i]
                );
        }
    }
    cellWeightsArms();
}


// ************************************************************************* //

#include "exactOverlapVoidFraction.H"
#include "addToRunTimeSelectionTable.H"
#include "mathematicalConstants.H"
#include "volMesh.H"
#include "treeBoundBox.H"
#include "Random.H"
#include "polyDEM/PolyhedronOverlap.hpp"
#include <algorithm>

namespace Foam
{
    defineTypeNameAndDebug(exactOverlapVoidFraction, 0);
    addToRunTimeSelectionTable
    (
        voidFractionModel,
        exactOverlapVoidFraction,
        dictionary
    );
}


// * * * * * * * * * * * * * * * Local helpers * * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;
using polydem::Vec3;
namespace od = polydem::overlapDetail;

constexpr int nBuf = od::kClipBuffer;

//- Planes of a cell; the most a cell may have (clip buffers)
constexpr int maxCellPlanes = polydem::kMaxPolyhedronFaces;

inline Vec3 toP(const vector& v)
{
    return Vec3{v.x(), v.y(), v.z()};
}


//- Outward planes n.x <= d of a cell (centre and area normal of each face;
//  coplanar faces, e.g. split faces, give one plane). False if too many.
bool cellPlanes
(
    const fvMesh& mesh,
    label celli,
    scalar tol,
    Vec3* n,
    double* d,
    int& np
)
{
    const cell& cFaces = mesh.cells()[celli];
    const vectorField& Sf = mesh.faceAreas();
    const vectorField& Cf = mesh.faceCentres();
    const labelList& own = mesh.faceOwner();
    np = 0;
    for (const label f : cFaces)
    {
        vector s = Sf[f];
        if (own[f] != celli)
        {
            s = -s;
        }
        const scalar ms = mag(s);
        if (ms < VSMALL)
        {
            continue;
        }
        const vector u = s/ms;
        const scalar off = u & Cf[f];
        bool dup = false;
        for (int j = 0; j < np; ++j)
        {
            if
            (
                polydem::dot(n[j], toP(u)) > 1 - 1e-12
             && mag(d[j] - off) <= tol
            )
            {
                dup = true;
                break;
            }
        }
        if (dup)
        {
            continue;
        }
        if (np == maxCellPlanes)
        {
            return false;
        }
        n[np] = toP(u);
        d[np] = off;
        ++np;
    }
    return true;
}


//- Unit vectors e1, e2 with (e1, e2, n) right-handed
void planeFrame(const Vec3& n, Vec3& e1, Vec3& e2)
{
    const Vec3 a =
        (std::abs(n.x) < 0.6) ? Vec3{1, 0, 0}
      : (std::abs(n.y) < 0.6) ? Vec3{0, 1, 0} : Vec3{0, 0, 1};
    e1 = polydem::cross(a, n);
    e1 = e1/polydem::norm(e1);
    e2 = polydem::cross(n, e1);
}


//- Square of half size h centred at o in the plane of unit normal n,
//  counter-clockwise seen from the side n points to
void square(const Vec3& o, const Vec3& n, double h, Vec3* out)
{
    Vec3 e1, e2;
    planeFrame(n, e1, e2);
    out[0] = o - h*e1 - h*e2;
    out[1] = o + h*e1 - h*e2;
    out[2] = o + h*e1 + h*e2;
    out[3] = o - h*e1 + h*e2;
}


//- Clip poly (in a, n vertices, a/b scratch) by planes; result pointer
int clipPoly
(
    Vec3* a,
    Vec3* b,
    int n,
    const Vec3* pn,
    const double* pd,
    int np,
    const Vec3& normal,
    bool dropSameCoplanar,
    double tol,
    Vec3*& out
)
{
    return od::clipPolygon
    (
        a, b, n, pn, pd, np, normal, dropSameCoplanar, tol, out
    );
}


//- Signed area of disc(0, R) n triangle(0, a, b) (2-D)
double discTriangle(double ax, double ay, double bx, double by, double R)
{
    auto sector = [R](double ux, double uy, double vx, double vy)
    {
        return 0.5*R*R*std::atan2(ux*vy - uy*vx, ux*vx + uy*vy);
    };
    const double dx = bx - ax, dy = by - ay;
    const double A = dx*dx + dy*dy;
    if (A <= 0)
    {
        return 0;
    }
    const double B = ax*dx + ay*dy;
    const double C = ax*ax + ay*ay - R*R;
    const double disc = B*B - A*C;
    if (disc <= 0)
    {
        return sector(ax, ay, bx, by);
    }
    const double s = std::sqrt(disc);
    const double t1 = std::max((-B - s)/A, 0.0);
    const double t2 = std::min((-B + s)/A, 1.0);
    if (t2 <= t1)
    {
        return sector(ax, ay, bx, by);
    }
    const double p1x = ax + t1*dx, p1y = ay + t1*dy;
    const double p2x = ax + t2*dx, p2y = ay + t2*dy;
    return
        sector(ax, ay, p1x, p1y)
      + 0.5*(p1x*p2y - p1y*p2x)
      + sector(p2x, p2y, bx, by);
}


// Gauss-Kronrod 7/15 on [-1, 1]
const double xgk[8] =
{
    0.991455371120812639206854697526329,
    0.949107912342758524526189684047851,
    0.864864423359769072789712788640926,
    0.741531185599394439863864773280788,
    0.586087235467691130294144845693013,
    0.405845151377397166906606412076961,
    0.207784955007898467600689403773245,
    0.0
};
const double wgk[8] =
{
    0.022935322010529224963732008058970,
    0.063092092629978553290700663189204,
    0.104790010322250183839876322541518,
    0.140653259715525918745189590510238,
    0.169004726639267902826583426598550,
    0.190350578064785409913256402421014,
    0.204432940075298892414161999234649,
    0.209482141084727828012999174891714
};
const double wg[4] =
{
    0.129484966168869693270611432679082,
    0.279705391489276667901467771423780,
    0.381830050505118944950369775488975,
    0.417959183673469387755102040816327
};

//- Adaptive Gauss-Kronrod of f over [a, b] to absolute error tol
template<class F>
double integrate(const F& f, double a, double b, double tol, int depth = 0)
{
    const double c = 0.5*(a + b), h = 0.5*(b - a);
    const double fc = f(c);
    double k = wgk[7]*fc, g = wg[3]*fc;
    for (int j = 0; j < 7; ++j)
    {
        const double f1 = f(c - h*xgk[j]);
        const double f2 = f(c + h*xgk[j]);
        k += wgk[j]*(f1 + f2);
        if (j % 2 == 1)
        {
            g += wg[j/2]*(f1 + f2);
        }
    }
    k *= h;
    g *= h;
    if (std::abs(k - g) <= tol || depth >= 40)
    {
        return k;
    }
    return
        integrate(f, a, c, 0.5*tol, depth + 1)
      + integrate(f, c, b, 0.5*tol, depth + 1);
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::exactOverlapVoidFraction::exactOverlapVoidFraction
(
    const word& modelType,
    const dictionary& dict,
    const fvMesh& mesh,
    const locateModel& locate
)
:
    voidFractionModel(modelType, dict, mesh, locate),
    sphereTolerance_(coeffs_.getOrDefault<scalar>("sphereTolerance", 1e-10)),
    meshFaces_(coeffs_.getOrDefault<bool>("meshFaces", true)),
    bounds_(),
    tree_(),
    meshEventIndex_(-1)
{
    if (!(sphereTolerance_ > 0) || sphereTolerance_ > 0.01)
    {
        FatalIOErrorInFunction(coeffs_)
            << "sphereTolerance must be in (0, 0.01] in " << coeffs_.name()
            << ", got " << sphereTolerance_ << exit(FatalIOError);
    }
    updateSearch();
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::exactOverlapVoidFraction::updateSearch() const
{
    meshEventIndex_ = mesh_.time().timeIndex();

    // Build the mesh's lazily computed search structures now, on every
    // processor: the tet base points are a collective computation, and a
    // processor that first needs them while the others wait elsewhere
    // (e.g. in the sum of the weights) would hang
    (void)mesh_.tetBasePtIs();
    (void)mesh_.cellPoints();

    bounds_ = boundBox(mesh_.points(), false);

    treeBoundBox overallBb(mesh_.points());
    Random rndGen(261782);
    overallBb = overallBb.extend(rndGen, 1e-4);
    overallBb.min() -= point::uniform(ROOTVSMALL);
    overallBb.max() += point::uniform(ROOTVSMALL);
    tree_.reset
    (
        new indexedOctree<treeDataCell>
        (
            treeDataCell(true, mesh_, polyMesh::CELL_TETS),
            overallBb,
            8,      // maxLevel
            10,     // leafsize
            5.0     // duplicity
        )
    );
}


void Foam::exactOverlapVoidFraction::updateMesh() const
{
    // The tree caches the cells' bounding boxes: stale once the points move
    if
    (
        (mesh_.moving() || mesh_.topoChanging())
     && meshEventIndex_ != mesh_.time().timeIndex()
    )
    {
        updateSearch();
    }
}


Foam::labelList Foam::exactOverlapVoidFraction::candidates
(
    const boundBox& bb
) const
{
    const vector grow(1e-9*bb.span() + vector::one*VSMALL);
    return tree_().findBox
    (
        treeBoundBox(bb.min() - grow, bb.max() + grow)
    );
}


Foam::scalar Foam::exactOverlapVoidFraction::polyhedronOverlap
(
    label celli,
    const demShape& shape,
    const List<point>& xv,
    const List<vector>& xn,
    const List<scalar>& xd,
    scalar scale
) const
{
    const pointField& pts = mesh_.points();
    const labelList& cPoints = mesh_.cellPoints()[celli];
    const boundBox cellBb(pts, cPoints, false);
    const scalar L = max(scale, mag(cellBb.span()));
    const double tol = polydem::kOverlapPlaneTolerance*L;

    Vec3 cn[maxCellPlanes];
    double cd[maxCellPlanes];
    int ncp = 0;
    if (!cellPlanes(mesh_, celli, tol, cn, cd, ncp))
    {
        FatalErrorInFunction
            << "Cell " << celli << " has more than " << maxCellPlanes
            << " face planes" << exit(FatalError);
    }

    // Particle planes
    const label npf = shape.faces.size();
    const label npv = xv.size();
    Vec3 pn[polydem::kMaxPolyhedronFaces];
    double pd[polydem::kMaxPolyhedronFaces];
    Vec3 pv[polydem::kMaxPolyhedronVertices];
    for (label f = 0; f < npf; ++f)
    {
        pn[f] = toP(xn[f]);
        pd[f] = xd[f];
    }
    for (label i = 0; i < npv; ++i)
    {
        pv[i] = toP(xv[i]);
    }

    // Early outs (separating planes of the cell and of the particle, the
    // particle wholly inside the cell)
    bool allInside = true;
    for (int j = 0; j < ncp; ++j)
    {
        double lo = GREAT, hi = -GREAT;
        for (label i = 0; i < npv; ++i)
        {
            const double sd = polydem::dot(cn[j], pv[i]) - cd[j];
            lo = min(lo, sd);
            hi = max(hi, sd);
        }
        if (lo >= -tol)
        {
            return 0;
        }
        allInside = allInside && hi <= 0;
    }
    if (allInside)
    {
        return shape.volume;
    }
    for (label f = 0; f < npf; ++f)
    {
        double lo = GREAT;
        for (const label p : cPoints)
        {
            lo = min(lo, polydem::dot(pn[f], toP(pts[p])) - pd[f]);
        }
        if (lo >= -tol)
        {
            return 0;
        }
    }

    od::BoundaryIntegrals acc;
    Vec3 bufA[nBuf], bufB[nBuf];

    // Faces of P inside C (kept where they coincide with a face of C)
    for (label f = 0; f < npf; ++f)
    {
        const face& fc = shape.faces[f];
        forAll(fc, k)
        {
            bufA[k] = pv[fc[k]];
        }
        Vec3* out = nullptr;
        const int n =
            clipPoly(bufA, bufB, fc.size(), cn, cd, ncp, pn[f], false, tol, out);
        if (n >= 3)
        {
            od::addPolygon(acc, out, n, true);
        }
    }

    // Faces of C inside P (dropped where they coincide with a face of P of
    // the same orientation: counted once, above). A cell whose faces are
    // all planar (within tol) is bounded by its mesh faces; otherwise its
    // faces are built from its planes (a large square in each plane,
    // clipped by the cell's planes), so that they close the region of the
    // planes exactly
    const cell& cFaces = mesh_.cells()[celli];
    const faceList& faces = mesh_.faces();
    const labelList& own = mesh_.faceOwner();
    bool planar = meshFaces_ && cFaces.size() == ncp;
    for (const label fi : cFaces)
    {
        if (!planar)
        {
            break;
        }
        const face& f = faces[fi];
        if (f.size() + npf > nBuf)
        {
            planar = false;
            break;
        }
        const vector& S = mesh_.faceAreas()[fi];
        const vector u = S/mag(S);
        const scalar off = u & mesh_.faceCentres()[fi];
        for (const label p : f)
        {
            if (mag((u & pts[p]) - off) > tol)
            {
                planar = false;
                break;
            }
        }
    }

    if (planar)
    {
        for (const label fi : cFaces)
        {
            const face& f = faces[fi];
            const bool owner = own[fi] == celli;
            const label m = f.size();
            for (label k = 0; k < m; ++k)
            {
                bufA[k] = toP(pts[f[owner ? k : m - 1 - k]]);
            }
            vector u = mesh_.faceAreas()[fi];
            u /= (owner ? 1 : -1)*mag(u);
            Vec3* out = nullptr;
            const int n =
                clipPoly(bufA, bufB, m, pn, pd, npf, toP(u), true, tol, out);
            if (n >= 3)
            {
                od::addPolygon(acc, out, n, false);
            }
        }
    }
    else
    {
        const Vec3 cc = toP(cellBb.centre());
        const double h = 2*mag(cellBb.span()) + 2*scale;
        for (int j = 0; j < ncp; ++j)
        {
            // Square in plane j around the cell centre's projection
            const Vec3 o = cc - (polydem::dot(cn[j], cc) - cd[j])*cn[j];
            square(o, cn[j], h, bufA);
            Vec3* out = nullptr;
            int n = clipPoly(bufA, bufB, 4, cn, cd, ncp, cn[j], false, tol, out);
            if (n < 3)
            {
                continue;
            }
            Vec3* a = out;
            Vec3* b = (out == bufA) ? bufB : bufA;
            n = clipPoly(a, b, n, pn, pd, npf, cn[j], true, tol, out);
            if (n >= 3)
            {
                od::addPolygon(acc, out, n, false);
            }
        }
    }

    return acc.sixVolume/6.0;
}


Foam::scalar Foam::exactOverlapVoidFraction::sphereOverlap
(
    label celli,
    const point& c,
    scalar r
) const
{
    const labelList& cPoints = mesh_.cellPoints()[celli];
    const pointField& pts = mesh_.points();
    const boundBox cellBb(pts, cPoints, false);
    const scalar L = max(r, mag(cellBb.span()));
    const double tol = polydem::kOverlapPlaneTolerance*L;

    Vec3 cn[maxCellPlanes];
    double cd[maxCellPlanes];
    int ncp = 0;
    if (!cellPlanes(mesh_, celli, tol, cn, cd, ncp))
    {
        FatalErrorInFunction
            << "Cell " << celli << " has more than " << maxCellPlanes
            << " face planes" << exit(FatalError);
    }

    // A separating plane of the cell; the sphere inside the cell
    bool sphereInside = true;
    for (int j = 0; j < ncp; ++j)
    {
        const double sd = polydem::dot(cn[j], toP(c)) - cd[j];
        if (sd >= r)
        {
            return 0;
        }
        sphereInside = sphereInside && sd <= -r;
    }
    const scalar Vs = 4.0/3.0*constant::mathematical::pi*pow3(r);
    if (sphereInside)
    {
        return Vs;
    }

    // Whole cell inside the sphere
    bool allIn = true;
    for (const label p : cPoints)
    {
        if (magSqr(pts[p] - c) > r*r)
        {
            allIn = false;
            break;
        }
    }
    if (allIn)
    {
        return mesh_.V()[celli];
    }

    const scalar za = max(c.z() - r, cellBb.min().z());
    const scalar zb = min(c.z() + r, cellBb.max().z());
    if (!(zb > za))
    {
        return 0;
    }

    // Section of the cell at height z, relative to the centre
    const Vec3 ez{0, 0, 1};
    const double h = 2*mag(cellBb.span()) + 2*r;
    const Vec3 cc = toP(cellBb.centre());
    // The section polygon C(z) (out: one of the two buffers)
    auto section = [&](double z, Vec3* bufA, Vec3* bufB, Vec3*& out) -> int
    {
        square(Vec3{cc.x, cc.y, z}, ez, h, bufA);
        return clipPoly(bufA, bufB, 4, cn, cd, ncp, ez, false, tol, out);
    };

    // A cell whose planes are all vertical or horizontal (blockMesh's
    // hexahedra) has one section polygon at every height inside it: clip it
    // once, not at every quadrature point
    bool prismatic = true;
    for (int j = 0; j < ncp && prismatic; ++j)
    {
        prismatic =
            std::abs(cn[j].z) <= 1e-14
         || (std::abs(cn[j].x) <= 1e-14 && std::abs(cn[j].y) <= 1e-14);
    }
    Vec3 prismA[nBuf], prismB[nBuf];
    Vec3* prism = nullptr;
    const int nPrism =
        prismatic ? section(cellBb.centre().z(), prismA, prismB, prism) : 0;

    auto area = [&](double z) -> double
    {
        const double rho2 = r*r - sqr(z - c.z());
        if (rho2 <= 0)
        {
            return 0;
        }
        const double R = std::sqrt(rho2);
        Vec3 bufA[nBuf], bufB[nBuf];
        Vec3* out = prism;
        const int n = prismatic ? nPrism : section(z, bufA, bufB, out);
        double A = 0;
        for (int i = 0; i < n; ++i)
        {
            const Vec3& p = out[i];
            const Vec3& q = out[(i + 1) % n];
            A += discTriangle
            (
                p.x - c.x(), p.y - c.y(), q.x - c.x(), q.y - c.y(), R
            );
        }
        return A;
    };

    // Break points: the cell's vertex heights and the centre's (kinks)
    DynamicList<scalar> zs(cPoints.size() + 3);
    zs.append(za);
    zs.append(zb);
    if (c.z() > za && c.z() < zb)
    {
        zs.append(c.z());
    }
    for (const label p : cPoints)
    {
        const scalar z = pts[p].z();
        if (z > za && z < zb)
        {
            zs.append(z);
        }
    }
    Foam::sort(zs);

    // Between two vertex heights the section of a cell with vertical sides
    // (blockMesh, snappyHexMesh's background) is one polygon, and A(z) is
    // smooth but where the circle of radius rho(z) touches an edge or passes
    // a vertex of it: there A has a (rho - d)^(3/2) kink, which an adaptive
    // rule refines towards at length. Those heights are break points too,
    // and each piece is integrated in s, z = a + (b - a)(3s^2 - 2s^3), whose
    // zero slope at both ends makes the kinks smooth in s. Oblique sections
    // (sheared cells) move their kinks within a piece: the adaptive rule
    // still meets the tolerance there, as before.
    const double tolAbs = sphereTolerance_*Vs;
    const double r2 = r*r;
    DynamicList<double> zk(16);
    double V = 0;
    for (label k = 0; k + 1 < zs.size(); ++k)
    {
        const double z0 = zs[k], z1 = zs[k + 1];
        if (!(z1 > z0))
        {
            continue;
        }

        zk.clear();
        zk.append(z0);
        auto addKink = [&](double d2)
        {
            if (d2 < r2)
            {
                const double w = std::sqrt(r2 - d2);
                for (const double z : {c.z() - w, c.z() + w})
                {
                    if (z > z0 && z < z1)
                    {
                        zk.append(z);
                    }
                }
            }
        };
        Vec3 bufA[nBuf], bufB[nBuf];
        Vec3* out = prism;
        const int n =
            prismatic ? nPrism : section(0.5*(z0 + z1), bufA, bufB, out);
        for (int i = 0; i < n; ++i)
        {
            const double px = out[i].x - c.x(), py = out[i].y - c.y();
            const Vec3& q = out[(i + 1) % n];
            const double ex = q.x - out[i].x, ey = q.y - out[i].y;
            addKink(px*px + py*py);
            const double e2 = ex*ex + ey*ey;
            const double t = e2 > 0 ? -(px*ex + py*ey)/e2 : 0;
            if (t > 0 && t < 1)
            {
                addKink(sqr(px + t*ex) + sqr(py + t*ey));
            }
        }
        zk.append(z1);
        std::sort(zk.begin(), zk.end());

        for (label j = 0; j + 1 < zk.size(); ++j)
        {
            const double a = zk[j], dz = zk[j + 1] - zk[j];
            if (!(dz > 0))
            {
                continue;
            }
            auto mapped = [&](double s)
            {
                return 6*dz*s*(1 - s)*area(a + dz*s*s*(3 - 2*s));
            };
            V += integrate(mapped, 0, 1, tolAbs*dz/(zb - za));
        }
    }
    return V;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::exactOverlapVoidFraction::distribute
(
    const point& c,
    scalar r,
    label centreCell,
    DynamicList<label>& cells,
    DynamicList<scalar>& weights
) const
{
    distributeShape(c, r, tensor::I, nullptr, centreCell, cells, weights);
}


void Foam::exactOverlapVoidFraction::distributeShape
(
    const point& c,
    scalar r,
    const tensor& R,
    const demShape* shape,
    label centreCell,
    DynamicList<label>& cells,
    DynamicList<scalar>& weights
) const
{
    const bool poly = shape && shape->polyhedron();

    // World-frame geometry and bounding box
    List<point> xv;
    List<vector> xn;
    List<scalar> xd;
    boundBox bb;
    if (poly)
    {
        xv.setSize(shape->vertices.size());
        forAll(xv, i)
        {
            xv[i] = c + (R & shape->vertices[i]);
        }
        xn.setSize(shape->normals.size());
        xd.setSize(xn.size());
        forAll(xn, f)
        {
            xn[f] = R & shape->normals[f];
            xd[f] = shape->offsets[f] + (xn[f] & c);
        }
        bb = boundBox(xv, false);
    }
    else
    {
        bb = boundBox(c - vector(r, r, r), c + vector(r, r, r));
    }
    if (!bounds_.overlaps(bb))
    {
        return;
    }

    const scalar Vp =
        poly ? shape->volume : 4.0/3.0*constant::mathematical::pi*pow3(r);
    const scalar scale = poly ? 0.5*mag(bb.span()) : r;

    // Wholly inside the centre's cell: weight 1, no clipping
    if (centreCell >= 0)
    {
        Vec3 cn[maxCellPlanes];
        double cd[maxCellPlanes];
        int ncp = 0;
        const double tol = polydem::kOverlapPlaneTolerance*scale;
        if (cellPlanes(mesh_, centreCell, tol, cn, cd, ncp))
        {
            bool inside = true;
            for (int j = 0; j < ncp && inside; ++j)
            {
                if (poly)
                {
                    for (const point& p : xv)
                    {
                        if (polydem::dot(cn[j], toP(p)) > cd[j])
                        {
                            inside = false;
                            break;
                        }
                    }
                }
                else
                {
                    inside = polydem::dot(cn[j], toP(c)) + r <= cd[j];
                }
            }
            if (inside)
            {
                cells.append(centreCell);
                weights.append(1);
                return;
            }
        }
    }

    for (const label celli : candidates(bb))
    {
        const scalar V =
            poly
          ? polyhedronOverlap(celli, *shape, xv, xn, xd, scale)
          : sphereOverlap(celli, c, r);
        if (V > 0)
        {
            cells.append(celli);
            weights.append(V/Vp);
        }
    }
}


// ************************************************************************* //

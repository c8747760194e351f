// polyDEM: overlap (intersection) of convex polyhedra with polyhedra, planes,
// spheres and wall triangles, for the overlap-volume contact law.
//
// Polyhedron-polyhedron: the intersection I = A n B of two convex polyhedra is
// bounded by (faces of A clipped to B) u (faces of B clipped to A). Each face
// polygon is clipped by the other shape's half-spaces with the re-entrant
// polygon clipper of Sutherland & Hodgman (1974, "Reentrant polygon clipping",
// Comm. ACM 17:32-42). The volume and centroid of I follow from the divergence
// theorem, as a sum of signed tetrahedra from a point of I to the fan
// triangles of the clipped polygons (cancellation stays at the size of I, not
// of the particles). The contact normal is Feng's energy-conserving normal
// (Feng, Y.T. 2021, "An energy-conserving contact theory for discrete element
// modelling of arbitrarily shaped particles: basic framework and general
// contact model", CMAME 373:113454):
//     S = -dV/dx_B = (area vector of the part of A's surface inside B)
//                  = -(area vector of the part of B's surface inside A),
// n = S/|S| points from A to B and is continuous when the contact switches
// between vertex-face, edge-edge and face-face. |S| (the projected contact
// area) is returned as contactArea, S as areaVector.
//
// Robustness: a vertex within tol = 1e-12 * (bounding radius) of a clipping
// plane counts as on it (no near-duplicate vertices are created); a face of B
// lying in a face plane of A with the same orientation is counted once (on A's
// side); a contact with V <= 1e-14 * min(V_A, V_B) is reported as not
// touching, so exactly touching shapes give touching = false and no NaN.
//
// Early outs, cheapest first: bounding spheres; a cached separating axis from
// the previous step (in/out, world frame); the face normals of A and B
// (separating axis theorem, Gottschalk et al. 1996); optionally the cross
// products of edge pairs. The edge axes are off by default: they cost
// O(E_A E_B (V_A + V_B)), more than the clipping itself, which is exact and
// returns touching = false for shapes that only the edge axes separate.
//
// Clipping cost: I lies in the slab S where the projections of A and B on an
// axis overlap: the pair's last contact normal when it touched at its last
// evaluation (I is thin along it), else the line of centres. A face that misses S is not clipped, and a face is
// clipped only by S's two planes and the planes of those faces of the other
// shape that reach into S: for convex B with B n S non-empty,
// B n S = S n {half-spaces of the faces of B that meet S} (a point of S outside
// B but inside all of those would leave B through a face that meets S). For
// the rocks of bench/polyhedraCpu that is about 11 planes of 22 (the slab's
// two included). A finer cull (the planes that the hull of A n S reaches)
// halved the plane visits but cost more dot products than it saved, as did
// sorting each face's planes into cutting, inside and outside ones first.
// A pair that touched at its last evaluation skips the separating-axis tests.
//
// Walls: a plane is treated as the solid half-space below it and a wall
// triangle as the part of the body below it that is the triangle's: bounded
// by the bisector planes with its neighbours' planes at its edges and at its
// vertices (WallSidePlanes.hpp), so that the triangles' solids partition the
// body at convex edges (a bilge, the edge of a box) and concave ones (an
// inside corner) alike, and down to the triangle's wall depth: half the
// thickness of the body behind it, so that the solids of a thin closed body
// (a ship hull, a lifter) stop at its middle and do not come out through its
// far side onto particles there. Only the particle's faces are clipped, by
// the wall plane and the side planes (halfSpaceClipOverlap), plus, for each
// side plane tilted against the wall's normal, the particle's section by it;
// the floor is the same clip moved down to it, taken away. Volume and
// centroid follow from fields that vanish on the wall's top and carry no flux
// through sides parallel to its normal, so the wall is never built as a
// polyhedron. Exact to round-off: a particle over several triangles overlaps
// them by its overlap with the body (polyhedraOverlap
// convexEdgesAndCornersOfClosedBody, concaveEdgesAndCornersOfContainer).
// Limits (WallSidePlanes.hpp): at a saddle vertex the vertex bisectors that
// would cut a triangle are left out; only faces touching a triangle bound its
// solid (a long triangle across a flat face can reach below a face it does
// not touch); and a body's solids are cut at the floor depth, not at its
// medial surface.
//
// Sphere-polyhedron: distance based (not an exact volume). The deepest point
// and the normal come from the closest feature of the polyhedron (face, edge
// or vertex; the face of least penetration when the centre is inside), the
// volume and centroid are those of the spherical cap of that depth. This is
// exact for a face contact and an upper bound for edge and vertex contacts.
//
// All functions are host+device, allocate nothing, and use fixed stack
// buffers sized by the caps of ConvexPolyhedron.hpp (ptxas, sm_90: a kernel
// calling all four uses a 9.7 kB stack frame per thread, 166 registers).
#pragma once

#include "polyDEM/ConvexPolyhedron.hpp"
#include "polyDEM/TriangleMesh.hpp"
#include "polyDEM/Macros.hpp"
#include "polyDEM/Quaternion.hpp"
#include "polyDEM/Vec3.hpp"

namespace polydem
{

//- Result of an overlap query; all vectors in the world frame
struct OverlapResult
{
    bool touching = false;
    double volume = 0;      //!< overlap volume V
    Vec3 centroid;          //!< centroid of the intersection (the contact point)
    Vec3 normal{0, 0, 1};   //!< unit, from A to B: S/|S|, S = -dV/dx_B
    Vec3 areaVector;        //!< S = -dV/dx_B (Feng 2021)
    double contactArea = 0; //!< |S|, the contact area projected on the normal plane
};

//- Relative tolerances (times the bounding radius / the smaller volume)
constexpr double kOverlapPlaneTolerance = 1e-12;
constexpr double kOverlapTouchingVolume = 1e-14;

namespace overlapDetail
{

//  (a clip by one plane adds at most one vertex; + 2 for the slab's planes)
constexpr int kClipBuffer = kMaxFaceVertices + kMaxPolyhedronFaces + 2;

//- Uninitialised stack storage for N Vec3. Vec3's members have default
//  initialisers, so a plain Vec3 array is zeroed at every call: about 15 kB
//  per polyhedron pair for the clip buffers and B's vertices, 3-9 % of the
//  pair's time (bench/polyhedraCpu). Every element is written before it is read.
template<int N>
struct Vec3Scratch
{
    alignas(Vec3) unsigned char bytes[N * sizeof(Vec3)];
    PD_INLINE Vec3* data() { return reinterpret_cast<Vec3*>(bytes); }
};

//- Surface integrals over the boundary of the intersection, relative to a
//  reference point o on the intersection (the first clipped vertex)
struct BoundaryIntegrals
{
    bool haveOrigin = false;
    Vec3 origin;
    double sixVolume = 0;     //!< 6 V
    Vec3 volumeMoment;        //!< sum 6 V_t (q0 + q1 + q2), centroid = / (4 sixVolume)
    Vec3 twiceAreaA;          //!< 2 x area vector of A's clipped faces
    Vec3 twiceAreaB;          //!< 2 x area vector of B's clipped faces
    double twiceSurface = 0;  //!< 2 x area of all clipped faces
};

PD_INLINE void addPolygon(BoundaryIntegrals& acc, const Vec3* poly, int n, bool fromA)
{
    if (!acc.haveOrigin)
    {
        acc.haveOrigin = true;
        acc.origin = poly[0];
    }
    const Vec3 q0 = poly[0] - acc.origin;
    Vec3 twiceArea;
    for (int i = 1; i + 1 < n; ++i)
    {
        const Vec3 q1 = poly[i] - acc.origin;
        const Vec3 q2 = poly[i + 1] - acc.origin;
        const double v6 = dot(q0, cross(q1, q2));
        acc.sixVolume += v6;
        acc.volumeMoment += v6 * (q0 + q1 + q2);
        twiceArea += cross(q1 - q0, q2 - q0);
    }
    // A convex planar polygon: its fan triangles' area vectors are parallel, so
    // its area is the length of their sum (one square root per polygon)
    acc.twiceSurface += norm(twiceArea);
    if (fromA)
    {
        acc.twiceAreaA += twiceArea;
    }
    else
    {
        acc.twiceAreaB += twiceArea;
    }
}

//- Clip the convex polygon in[0..n) by the half-spaces dot(pn[j], x) <= pd[j]
//  (Sutherland-Hodgman). Returns the vertex count (0 if empty) and sets out to
//  the buffer holding the result. With dropSameCoplanar, a polygon lying in a
//  clipping plane of index >= firstDropPlane with the same orientation as
//  faceNormal is dropped (so that coincident faces of A and B are counted
//  once; the planes before firstDropPlane are not faces of a shape).
//  rejectedBy (may be null): set to the plane that left nothing of the polygon
//  outside it, or -1.
inline PD_HD int clipPolygon(Vec3* bufA, Vec3* bufB, int n, const Vec3* pn, const double* pd,
                             int nPlanes, const Vec3& faceNormal, bool dropSameCoplanar,
                             double tol, Vec3*& out, int firstDropPlane = 0,
                             int* rejectedBy = nullptr)
{
    if (rejectedBy) *rejectedBy = -1;
    Vec3* cur = bufA;
    Vec3* nxt = bufB;
    double s[kClipBuffer];
    for (int j = 0; j < nPlanes && n >= 3; ++j)
    {
        bool anyIn = false, anyOut = false;
        for (int i = 0; i < n; ++i)
        {
            s[i] = dot(pn[j], cur[i]) - pd[j];
            anyIn = anyIn || s[i] < -tol;
            anyOut = anyOut || s[i] > tol;
        }
        if (!anyOut)
        {
            // Inside or on: unchanged, unless the whole polygon lies in the plane
            if (!anyIn && dropSameCoplanar && j >= firstDropPlane && dot(pn[j], faceNormal) > 0)
            {
                n = 0;
            }
            continue;
        }
        if (!anyIn)
        {
            n = 0; // outside, or touching along a point/edge only
            if (rejectedBy) *rejectedBy = j;
            break;
        }
        int m = 0;
        for (int i = 0; i < n; ++i)
        {
            const int k = (i + 1 == n) ? 0 : i + 1;
            const double sp = s[i], sq = s[k];
            const bool crosses = (sp < -tol && sq > tol) || (sp > tol && sq < -tol);
            if (crosses && m < kClipBuffer)
            {
                const double t = sp / (sp - sq);
                nxt[m++] = cur[i] + t * (cur[k] - cur[i]);
            }
            if (sq <= tol && m < kClipBuffer)
            {
                nxt[m++] = cur[k];
            }
        }
        n = m;
        Vec3* tmp = cur;
        cur = nxt;
        nxt = tmp;
    }
    out = cur;
    return n >= 3 ? n : 0;
}

//- For each face of X: does its projection range (proj: the vertices'
//  projections on the slab's axis) meet the slab [slabLo, slabHi]?
PD_INLINE void facesMeetingSlab(const ConvexPolyhedron& X, const double* proj, double slabLo,
                                double slabHi, bool* meets)
{
    for (int f = 0; f < X.nFaces; ++f)
    {
        const int f0 = X.faceStart[f];
        const int m = X.faceSize(f);
        double pMin = proj[X.faceVertex[f0]], pMax = pMin;
        for (int i = 1; i < m; ++i)
        {
            const double p = proj[X.faceVertex[f0 + i]];
            pMin = p < pMin ? p : pMin;
            pMax = p > pMax ? p : pMax;
        }
        meets[f] = !(pMax < slabLo || pMin > slabHi);
    }
}

//- The planes that bound Y n slab: the slab's two (first), then the planes
//  (yn, yd) of the faces of Y that meet the slab. Returns their count.
PD_INLINE int planesBoundingSlabPart(const ConvexPolyhedron& Y, const Vec3* yn, const double* yd,
                                     const bool* yMeets, const Vec3& axis, double slabLo,
                                     double slabHi, Vec3* pn, double* pd)
{
    pn[0] = axis;
    pd[0] = slabHi;
    pn[1] = -axis;
    pd[1] = -slabLo;
    int n = 2;
    for (int f = 0; f < Y.nFaces; ++f)
    {
        if (yMeets[f])
        {
            pn[n] = yn[f];
            pd[n] = yd[f];
            ++n;
        }
    }
    return n;
}

//- Clip every face of X that meets the slab (xMeets) by the planes (pn, pd)
//  of Y n slab (planesBoundingSlabPart) and add the pieces to the boundary
//  integrals. A face whose plane Y's bounding sphere (yCentre, yRadius) lies
//  wholly behind cannot meet Y and is skipped as well. About half the faces
//  clipped give nothing, most of them rejected whole by one plane after being
//  clipped by several others; the plane that rejected the last such face is
//  tried on the face first (one dot product per vertex), since neighbouring
//  faces tend to lie beyond the same far plane of Y.
inline PD_HD void addClippedFaces(BoundaryIntegrals& acc, const ConvexPolyhedron& X,
                                  const Vec3* xv, const Vec3* xn, const bool* xMeets,
                                  const Vec3* pn, const double* pd, int nPlanes, bool fromA,
                                  double tol, const Vec3& yCentre, double yRadius)
{
    Vec3Scratch<kClipBuffer> scratchA, scratchB;
    Vec3* bufA = scratchA.data();
    Vec3* bufB = scratchB.data();
    int lastRejecting = -1;
    for (int f = 0; f < X.nFaces; ++f)
    {
        if (!xMeets[f])
        {
            continue;
        }
        const Vec3& first = xv[X.faceVertex[X.faceStart[f]]];
        if (dot(xn[f], yCentre - first) < -(yRadius + tol))
        {
            continue;
        }
        const int m = X.faceSize(f);
        for (int i = 0; i < m; ++i)
        {
            bufA[i] = xv[X.faceVertex[X.faceStart[f] + i]];
        }
        if (lastRejecting >= 0)
        {
            // clipPolygon's own test for a whole polygon outside a plane
            bool anyIn = false, anyOut = false;
            for (int i = 0; i < m; ++i)
            {
                const double d = dot(pn[lastRejecting], bufA[i]) - pd[lastRejecting];
                anyIn = anyIn || d < -tol;
                anyOut = anyOut || d > tol;
            }
            if (anyOut && !anyIn)
            {
                continue;
            }
        }
        Vec3* poly = nullptr;
        int rejectedBy = -1;
        const int n = clipPolygon(bufA, bufB, m, pn, pd, nPlanes, xn[f], !fromA, tol, poly, 2, &rejectedBy);
        if (n >= 3)
        {
            addPolygon(acc, poly, n, fromA);
        }
        else if (rejectedBy >= 0)
        {
            lastRejecting = rejectedBy;
        }
    }
}

//- The range [lo, hi] of offset + dot(axis, p[i]) over the n points p
PD_INLINE void projectedRange(const Vec3& axis, double offset, const Vec3* p, int n, double& lo, double& hi)
{
    lo = 1e300;
    hi = -1e300;
    for (int i = 0; i < n; ++i)
    {
        const double s = offset + dot(axis, p[i]);
        lo = s < lo ? s : lo;
        hi = s > hi ? s : hi;
    }
}

//- True if the projections of the point sets a and b on axis are disjoint
PD_INLINE bool separatedAlong(const Vec3& axis, const Vec3* a, int na, const Vec3* b, int nb)
{
    double minA, maxA, minB, maxB;
    projectedRange(axis, 0.0, a, na, minA, maxA);
    projectedRange(axis, 0.0, b, nb, minB, maxB);
    return maxA <= minB || maxB <= minA;
}

//- True if the projections on axis of the point sets a and b are disjoint,
//  b given in a frame of its own: b's projections are
//  bOffset + dot(axisInB, b[i])
PD_INLINE bool separatedAlong(const Vec3& axis, const Vec3* a, int na,
                              const Vec3& axisInB, double bOffset, const Vec3* b, int nb)
{
    double minA, maxA, minB, maxB;
    projectedRange(axis, 0.0, a, na, minA, maxA);
    projectedRange(axisInB, bOffset, b, nb, minB, maxB);
    return maxA <= minB || maxB <= minA;
}

//- Overlap of A and B, B given by its pose in A's body frame; result in A's frame.
//  cachedAxis (A frame, may be null) is tried first and updated. With
//  touchedBefore (the pair touched at its last evaluation, so cachedAxis is
//  its contact normal) the separating-axis tests are skipped: they would
//  almost always fail, and the clipping finds a separation all the same;
//  and the clipping slab is taken along that normal.
inline PD_HD OverlapResult overlapInFrameOfA(const ConvexPolyhedron& A, const ConvexPolyhedron& B,
                                             const Quaternion& qB, const Vec3& posB,
                                             Vec3* cachedAxis, bool testEdgeAxes,
                                             bool touchedBefore = false)
{
    OverlapResult r;
    const double rA = A.boundingRadius, rB = B.boundingRadius;
    if (normSqr(posB) >= (rA + rB) * (rA + rB))
    {
        return r;
    }
    const double scale = rA > rB ? rA : rB;
    const double tol = kOverlapPlaneTolerance * scale;

    const bool haveAxis = cachedAxis && normSqr(*cachedAxis) > 0;
    const bool separatingTests = !(touchedBefore && haveAxis);

    // The cached axis first, on each shape's own vertices: a pair that stays
    // apart is rejected before B is moved into A's frame
    if (separatingTests && haveAxis)
    {
        const Vec3 axisInB = rotateInverse(qB, *cachedAxis);
        if (separatedAlong(*cachedAxis, A.vertices, A.nVertices, axisInB, dot(*cachedAxis, posB),
                           B.vertices, B.nVertices))
        {
            return r;
        }
    }

    // B in A's frame
    Vec3Scratch<kMaxPolyhedronVertices> scratchBv;
    Vec3Scratch<kMaxPolyhedronFaces> scratchBn;
    Vec3* bv = scratchBv.data();
    Vec3* bn = scratchBn.data();
    double bd[kMaxPolyhedronFaces];
    for (int i = 0; i < B.nVertices; ++i)
    {
        bv[i] = posB + rotate(qB, B.vertices[i]);
    }
    for (int f = 0; f < B.nFaces; ++f)
    {
        bn[f] = rotate(qB, B.faceNormals[f]);
        bd[f] = B.faceOffsets[f] + dot(bn[f], posB);
    }

    // Separating axes: faces of A, faces of B, (edges)
    for (int f = 0; separatingTests && f < A.nFaces; ++f)
    {
        double minB = 1e300;
        for (int i = 0; i < B.nVertices; ++i)
        {
            const double p = dot(A.faceNormals[f], bv[i]);
            minB = p < minB ? p : minB;
        }
        if (minB >= A.faceOffsets[f])
        {
            if (cachedAxis) *cachedAxis = A.faceNormals[f];
            return r;
        }
    }
    for (int f = 0; separatingTests && f < B.nFaces; ++f)
    {
        double minA = 1e300;
        for (int i = 0; i < A.nVertices; ++i)
        {
            const double p = dot(bn[f], A.vertices[i]);
            minA = p < minA ? p : minA;
        }
        if (minA >= bd[f])
        {
            if (cachedAxis) *cachedAxis = bn[f];
            return r;
        }
    }
    if (separatingTests && testEdgeAxes)
    {
        for (int i = 0; i < A.nEdges; ++i)
        {
            const Vec3 ea = A.vertices[A.edges[i].b] - A.vertices[A.edges[i].a];
            for (int j = 0; j < B.nEdges; ++j)
            {
                const Vec3 eb = bv[B.edges[j].b] - bv[B.edges[j].a];
                const Vec3 axis = cross(ea, eb);
                if (normSqr(axis) <= 1e-20 * normSqr(ea) * normSqr(eb))
                {
                    continue; // parallel edges: covered by the face axes
                }
                if (separatedAlong(axis, A.vertices, A.nVertices, bv, B.nVertices))
                {
                    if (cachedAxis) *cachedAxis = axis / norm(axis);
                    return r;
                }
            }
        }
    }

    // The slab's axis: any axis bounds the intersection. A pair that touched
    // at its last evaluation takes its contact normal, along which the overlap
    // is thin, so fewer faces meet the slab; others the line of centres. The
    // result depends on the choice at round-off, so the engine keeps the
    // normal with the pair's springs through neighbour rebuilds and restarts
    // (PairHistory::normal): a run continues bit for bit.
    Vec3 axis;
    const double dCentres = norm(posB);
    if (touchedBefore && haveAxis)
    {
        axis = *cachedAxis / norm(*cachedAxis);
    }
    else
    {
        axis = dCentres > 0 ? posB / dCentres : Vec3(0, 0, 1);
    }
    double pa[kMaxPolyhedronVertices], pb[kMaxPolyhedronVertices];
    double aMin = 1e300, aMax = -1e300, bMin = 1e300, bMax = -1e300;
    for (int i = 0; i < A.nVertices; ++i)
    {
        pa[i] = dot(axis, A.vertices[i]);
        aMin = pa[i] < aMin ? pa[i] : aMin;
        aMax = pa[i] > aMax ? pa[i] : aMax;
    }
    for (int i = 0; i < B.nVertices; ++i)
    {
        pb[i] = dot(axis, bv[i]);
        bMin = pb[i] < bMin ? pb[i] : bMin;
        bMax = pb[i] > bMax ? pb[i] : bMax;
    }
    // Widened by 1000 tol: the slab's planes clip faces, and a vertex they make
    // must lie clearly outside the shape plane that bounds I there (at 1 tol
    // it would count as on it: an aligned cube pair overlapping by 1e-9 of its
    // edge came out 1.4e-4 too large, its centroid off by 3.6e-5 of the edge)
    const double margin = 1e3 * tol;
    const double slabLo = (aMin > bMin ? aMin : bMin) - margin;
    const double slabHi = (aMax < bMax ? aMax : bMax) + margin;

    // Boundary of A n B: faces of A inside B n slab, faces of B inside A n slab
    bool aMeets[kMaxPolyhedronFaces], bMeets[kMaxPolyhedronFaces];
    facesMeetingSlab(A, pa, slabLo, slabHi, aMeets);
    facesMeetingSlab(B, pb, slabLo, slabHi, bMeets);
    Vec3Scratch<kMaxPolyhedronFaces + 2> scratchPn;
    Vec3* pn = scratchPn.data();
    double pd[kMaxPolyhedronFaces + 2];
    BoundaryIntegrals acc;
    int nPlanes = planesBoundingSlabPart(B, bn, bd, bMeets, axis, slabLo, slabHi, pn, pd);
    addClippedFaces(acc, A, A.vertices, A.faceNormals, aMeets, pn, pd, nPlanes, true, tol, posB, rB);
    nPlanes = planesBoundingSlabPart(A, A.faceNormals, A.faceOffsets, aMeets, axis, slabLo, slabHi, pn, pd);
    addClippedFaces(acc, B, bv, bn, bMeets, pn, pd, nPlanes, false, tol, Vec3(), rA);

    const double volume = acc.sixVolume / 6.0;
    const double minVolume = A.volume < B.volume ? A.volume : B.volume;
    if (!(volume > kOverlapTouchingVolume * minVolume))
    {
        return r;
    }
    r.touching = true;
    r.volume = volume;
    r.centroid = acc.origin + acc.volumeMoment / (4.0 * acc.sixVolume);
    // S = -dV/dx_B; A's part and minus B's part agree on a closed surface
    r.areaVector = 0.25 * (acc.twiceAreaA - acc.twiceAreaB);
    r.contactArea = norm(r.areaVector);
    // One shape inside the other: S = 0 up to round-off of the whole surface
    if (r.contactArea > 1e-9 * 0.5 * acc.twiceSurface)
    {
        r.normal = r.areaVector / r.contactArea;
    }
    else
    {
        // Coincident shapes: no preferred direction; fall back to centre line
        const double d = norm(posB);
        r.normal = d > 1e-300 ? posB / d : Vec3(0, 0, 1);
    }
    if (cachedAxis) *cachedAxis = r.normal;
    return r;
}

//- Result from A's frame (rotation qA, origin posA) to the world frame
PD_INLINE OverlapResult toWorld(OverlapResult r, const Vec3& posA, const Quaternion& qA)
{
    if (r.touching)
    {
        r.centroid = posA + rotate(qA, r.centroid);
        r.normal = rotate(qA, r.normal);
        r.areaVector = rotate(qA, r.areaVector);
    }
    return r;
}

//- Overlap of polyhedron P (pose pos, q, world frame) with the wall solid
//  W = {x : n.(x - o) <= 0} n {x : m_k.x <= d_k, k < nSide} (o on the wall
//  plane; side planes in coordinates relative to o: a triangle's prism or its
//  edges' bisectors, WallSidePlanes.hpp; none for a plane). Only P's faces are
//  clipped (by at most 1 + nSide planes, against a six-plane box or a
//  five-plane prism clipped both ways before). Volume and centroid by the
//  divergence theorem with fields parallel to n that vanish on the wall plane,
//  h = n.(x - o):
//      V = surf h (n.N) dA,  int h dV = surf h^2/2 (n.N) dA,
//      int t dV = surf h t (n.N) dA   (t: the part of x - o normal to n),
//  so the wall's top (h = 0) and its sides parallel to n (n.N = 0) add
//  nothing and are never built. A side plane tilted against n (a bisector)
//  does carry flux: its part inside P (P's section by the plane, clipped by
//  the other planes of W) is added as one more face. Each integral is exact
//  on a fan triangle (edge-midpoint rule). S = -(area vector of P's part of
//  the boundary). tol, fallback normal and touching threshold as in
//  overlapInFrameOfA.
struct ClipIntegrals
{
    double volume = 0;   //!< V
    Vec3 moment;         //!< first moment about o, int (x - o) dV
    Vec3 twiceArea;      //!< twice the area vector of P's boundary inside W
    double surface = 0;  //!< area of P's boundary inside W
};

//- Adds the flux integrals of the fields above through the planar polygon
//  poly (nv vertices relative to o, counter-clockwise about its outward
//  normal) to volume, hMoment and tMoment; returns twice its area vector
PD_INLINE Vec3 addClipFan
(
    const Vec3* poly, int nv, const Vec3& n, double& volume, double& hMoment, Vec3& tMoment
)
{
    Vec3 polyArea;
    const Vec3 x0 = poly[0];
    const double h0 = dot(n, x0);
    const Vec3 t0 = x0 - h0 * n;
    for (int i = 1; i + 1 < nv; ++i)
    {
        const Vec3 x1 = poly[i], x2 = poly[i + 1];
        const Vec3 a2 = cross(x1 - x0, x2 - x0);
        polyArea += a2;
        const double w = 0.5 * dot(n, a2);   // projected, signed area
        const double h1 = dot(n, x1), h2 = dot(n, x2);
        const Vec3 t1 = x1 - h1 * n, t2 = x2 - h2 * n;
        // Edge midpoints: exact for the quadratic integrands
        const double ha = 0.5 * (h0 + h1), hb = 0.5 * (h1 + h2), hc = 0.5 * (h2 + h0);
        const Vec3 ta = 0.5 * (t0 + t1), tb = 0.5 * (t1 + t2), tc = 0.5 * (t2 + t0);
        volume += w * (h0 + h1 + h2) * (1.0 / 3.0);
        hMoment += w * (ha * ha + hb * hb + hc * hc) * (1.0 / 6.0);
        tMoment += (w * (1.0 / 3.0)) * (ha * ta + hb * tb + hc * tc);
    }
    return polyArea;
}

//- The section of P (vertices v, signed distances s to a plane) by that
//  plane: the points where P's faces leave the plane's inner side, one per
//  face that crosses it, written to out unordered. Returns their number.
PD_INLINE int planeSection(const ConvexPolyhedron& P, const Vec3* v, const double* s, Vec3* out)
{
    int np = 0;
    for (int f = 0; f < P.nFaces; ++f)
    {
        const int f0 = P.faceStart[f];
        const int fm = P.faceSize(f);
        for (int i = 0; i < fm; ++i)
        {
            const int a = P.faceVertex[f0 + i];
            const int b = P.faceVertex[f0 + (i + 1 == fm ? 0 : i + 1)];
            if (s[a] <= 0 && s[b] > 0)
            {
                out[np++] = v[a] + (s[a] / (s[a] - s[b])) * (v[b] - v[a]);
                break;   // a convex face leaves once
            }
        }
    }
    return np;
}

//- Orders the np points of a convex polygon in a plane of unit normal m
//  counter-clockwise about m (a sort about their mean by a pseudo-angle in
//  [0, 4): monotone in the angle, with no trigonometry)
PD_INLINE void orderAbout(const Vec3& m, Vec3* out, int np)
{
    Vec3 mean;
    for (int i = 0; i < np; ++i) mean += out[i];
    mean = (1.0 / np) * mean;
    // A basis (u, w) of the plane with u x w = m
    const Vec3 a = fabs(m.x) < 0.6 ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
    Vec3 u = cross(a, m);
    u = u / norm(u);
    const Vec3 w = cross(m, u);
    double angle[kClipBuffer];
    for (int i = 0; i < np; ++i)
    {
        const Vec3 d = out[i] - mean;
        const double x = dot(d, u), y = dot(d, w);
        const double l1 = fabs(x) + fabs(y);
        const double r = l1 > 0 ? y / l1 : 0;   // sin-like, in [-1, 1]
        angle[i] = x >= 0 ? (y >= 0 ? r : 4 + r) : 2 - r;
    }
    for (int i = 1; i < np; ++i)   // insertion sort: a few points
    {
        const Vec3 x = out[i];
        const double t = angle[i];
        int j = i;
        while (j > 0 && angle[j - 1] > t)
        {
            out[j] = out[j - 1];
            angle[j] = angle[j - 1];
            --j;
        }
        out[j] = x;
        angle[j] = t;
    }
}

PD_INLINE ClipIntegrals halfSpaceClipIntegrals
(
    const ConvexPolyhedron& P, const Vec3& pos, const Quaternion& q, const Vec3& o, const Vec3& n,
    const Vec3* sideNormal, const double* sideOffset, int nSide, double tol
)
{
    // The planes: those tilted against n first (nTilted), then the top and
    // the sides parallel to n. A face of P lying in the top or a parallel
    // side carries no flux and is dropped, so that the area vector is that
    // of the wall's surface; one lying in a tilted side carries flux and is
    // kept (the section below then finds nothing beyond that plane)
    Vec3 pn[1 + kMaxWallSidePlanes];
    double pd[1 + kMaxWallSidePlanes];
    int nTilted = 0;
    for (int k = 0; k < nSide; ++k)
    {
        if (fabs(dot(sideNormal[k], n)) >= 1e-12)
        {
            pn[nTilted] = sideNormal[k];
            pd[nTilted++] = sideOffset[k];
        }
    }
    pn[nTilted] = n;
    pd[nTilted] = 0;
    int nPlanes = nTilted + 1;
    for (int k = 0; k < nSide; ++k)
    {
        if (fabs(dot(sideNormal[k], n)) < 1e-12)
        {
            pn[nPlanes] = sideNormal[k];
            pd[nPlanes++] = sideOffset[k];
        }
    }

    const Vec3 c = pos - o;
    Vec3Scratch<kMaxPolyhedronVertices> scratchV;
    Vec3* v = scratchV.data();
    double hv[kMaxPolyhedronVertices];
    for (int i = 0; i < P.nVertices; ++i)
    {
        v[i] = c + rotate(q, P.vertices[i]);
        hv[i] = dot(n, v[i]);
    }

    double volume = 0, hMoment = 0, surface = 0;
    Vec3 tMoment, twiceArea;
    Vec3Scratch<kClipBuffer> scratchA, scratchB;
    Vec3* bufA = scratchA.data();
    Vec3* bufB = scratchB.data();
    for (int f = 0; f < P.nFaces; ++f)
    {
        const int f0 = P.faceStart[f];
        const int m = P.faceSize(f);
        // A face wholly above the wall plane cannot meet the wall solid
        double hMin = hv[P.faceVertex[f0]];
        for (int i = 1; i < m; ++i)
        {
            const double h = hv[P.faceVertex[f0 + i]];
            hMin = h < hMin ? h : hMin;
        }
        if (hMin >= -tol) continue;
        for (int i = 0; i < m; ++i)
        {
            bufA[i] = v[P.faceVertex[f0 + i]];
        }
        Vec3* poly = nullptr;
        const Vec3 faceNormal = rotate(q, P.faceNormals[f]);
        const int nv = clipPolygon(bufA, bufB, m, pn, pd, nPlanes, faceNormal, true, tol, poly, nTilted);
        if (nv < 3) continue;
        const Vec3 polyArea = addClipFan(poly, nv, n, volume, hMoment, tMoment);
        twiceArea += polyArea;
        surface += 0.5 * norm(polyArea);
    }
    // Side planes tilted against n: their part inside P is a face of P n W
    // (outward normal m_k) through which the fields carry flux. It can be
    // all there is (P holding the whole of a small triangle's solid), so it
    // is looked for whenever P reaches below the wall plane.
    bool below = false;   // (no tilted side: nothing to look for)
    for (int i = 0; i < P.nVertices && nTilted > 0 && !below; ++i) below = hv[i] < -tol;
    if (below)
    {
        for (int k = 0; k < nTilted; ++k)
        {
            double s[kMaxPolyhedronVertices];
            bool anyOut = false;
            for (int i = 0; i < P.nVertices; ++i)
            {
                s[i] = dot(pn[k], v[i]) - pd[k];
                anyOut = anyOut || s[i] > tol;
            }
            if (!anyOut) continue;   // P wholly on the inner side (or on it)
            const int ns = planeSection(P, v, s, bufA);
            if (ns < 3) continue;
            bool sectionBelow = false;   // else it misses the wall solid
            for (int i = 0; i < ns && !sectionBelow; ++i) sectionBelow = dot(n, bufA[i]) < -tol;
            if (!sectionBelow) continue;
            orderAbout(pn[k], bufA, ns);
            // Clipped by W's other planes
            Vec3 qn[kMaxWallSidePlanes];
            double qd[kMaxWallSidePlanes];
            int nq = 0;
            for (int j = 0; j < nPlanes; ++j)
            {
                if (j == k) continue;
                qn[nq] = pn[j];
                qd[nq++] = pd[j];
            }
            Vec3* poly = nullptr;
            const int nv = clipPolygon(bufA, bufB, ns, qn, qd, nq, pn[k], false, tol, poly);
            if (nv < 3) continue;
            addClipFan(poly, nv, n, volume, hMoment, tMoment);
        }
    }
    ClipIntegrals I;
    I.volume = volume;
    I.moment = tMoment + hMoment * n;
    I.twiceArea = twiceArea;
    I.surface = surface;
    return I;
}

//- The overlap from the integrals about o (c: the particle's centre - o)
PD_INLINE OverlapResult clipOverlapResult
(
    const ClipIntegrals& I, const ConvexPolyhedron& P, const Vec3& o, const Vec3& c
)
{
    OverlapResult r;
    const double volume = I.volume;
    const double surface = I.surface;
    if (!(volume > kOverlapTouchingVolume * P.volume))
    {
        return r;
    }
    r.touching = true;
    r.volume = volume;
    r.centroid = o + (1.0 / volume) * I.moment;
    r.areaVector = -0.5 * I.twiceArea;
    r.contactArea = norm(r.areaVector);
    if (r.contactArea > 1e-9 * (surface + r.contactArea))
    {
        r.normal = r.areaVector / r.contactArea;
    }
    else
    {
        // P wholly inside the wall: no preferred direction; centre line
        const double d = norm(c);
        r.normal = d > 1e-300 ? c / d : Vec3(0, 0, 1);
    }
    return r;
}

PD_INLINE OverlapResult halfSpaceClipOverlap
(
    const ConvexPolyhedron& P, const Vec3& pos, const Quaternion& q, const Vec3& o, const Vec3& n,
    const Vec3* sideNormal, const double* sideOffset, int nSide, double tol
)
{
    return clipOverlapResult
    (
        halfSpaceClipIntegrals(P, pos, q, o, n, sideNormal, sideOffset, nSide, tol), P, o, pos - o
    );
}

} // namespace overlapDetail


//- polyhedronOverlap takes touchedBefore (for drivers that build against
//  several engine versions, such as bench/polyhedraCpu/pairOverlapBench.cpp)
#define PD_OVERLAP_HAS_TOUCHED_BEFORE 1

//- Overlap of convex polyhedra A and B at poses (posA, qA), (posB, qB).
//  separatingAxis (world frame, may be null): tried first when non-zero; set
//  to the separating axis found, or to the contact normal when touching.
//  touchedBefore: the pair touched when separatingAxis was set (it holds the
//  contact normal), so the separating-axis tests are skipped.
inline PD_HD OverlapResult polyhedronOverlap(const ConvexPolyhedron& A, const Vec3& posA,
                                             const Quaternion& qA, const ConvexPolyhedron& B,
                                             const Vec3& posB, const Quaternion& qB,
                                             Vec3* separatingAxis = nullptr,
                                             bool testEdgeAxes = false,
                                             bool touchedBefore = false)
{
    const Quaternion qAinv = conjugate(qA);
    const Vec3 posBinA = rotate(qAinv, posB - posA);
    const Quaternion qBinA = qAinv * qB;
    Vec3 axisInA;
    if (separatingAxis)
    {
        axisInA = rotate(qAinv, *separatingAxis);
    }
    const OverlapResult r = overlapDetail::overlapInFrameOfA(
        A, B, qBinA, posBinA, separatingAxis ? &axisInA : nullptr, testEdgeAxes, touchedBefore);
    if (separatingAxis)
    {
        *separatingAxis = rotate(qA, axisInA);
    }
    return overlapDetail::toWorld(r, posA, qA);
}

//- Overlap of a polyhedron with the solid half-space dot(planeNormal, x - planePoint) <= 0.
//  planeNormal: unit, pointing out of the wall; the result's normal points from
//  the wall to the particle (= planeNormal for a flat contact).
inline PD_HD OverlapResult polyhedronPlaneOverlap(const ConvexPolyhedron& P, const Vec3& pos,
                                                  const Quaternion& q, const Vec3& planePoint,
                                                  const Vec3& planeNormal)
{
    const double r = P.boundingRadius;
    const double dist = dot(planeNormal, pos - planePoint);
    if (dist >= r)
    {
        return OverlapResult();
    }
    // Directly against the half-space (same tolerance as the former box of
    // half sizes 2r, 2r, depth/2 under the particle)
    const Vec3 origin = pos - dist * planeNormal; // on the plane
    const double depth = 2.0 * r + (dist < 0 ? -dist : 0.0);
    const double boxRadius = sqrt(8.0 * r * r + 0.25 * depth * depth);
    const double tol = kOverlapPlaneTolerance * (boxRadius > r ? boxRadius : r);
    return overlapDetail::halfSpaceClipOverlap(P, pos, q, origin, planeNormal, nullptr, nullptr, 0, tol);
}

//- Overlap of a polyhedron with the wall triangle (t0, t1, t2), counter-clockwise
//  seen from the fluid side; the wall is the triangle's solid below it, down
//  to wallDepth under the triangle's plane (see top; WallDepths.hpp), bounded
//  by the nSides planes sideNormal[k].(x - t0) <= sideOffset[k]
//  (WallSidePlanes.hpp: the bisectors with its neighbours' planes; at most
//  kMaxWallSidePlanes); sideNormal null: the triangle's normal prism.
inline PD_HD OverlapResult polyhedronTriangleOverlap(const ConvexPolyhedron& P, const Vec3& pos,
                                                     const Quaternion& q, const Vec3& t0,
                                                     const Vec3& t1, const Vec3& t2,
                                                     double wallDepth = kUnboundedWallDepth,
                                                     const Vec3* sideNormal = nullptr,
                                                     const double* sideOffset = nullptr,
                                                     int nSides = 0)
{
    Vec3 n = cross(t1 - t0, t2 - t0);
    const double twiceArea = norm(n);
    const double r = P.boundingRadius;
    if (!(twiceArea > 0))
    {
        return OverlapResult();
    }
    n = n / twiceArea;
    const double dist = dot(n, pos - t0);
    if (dist >= r || dist + r <= -wallDepth)
    {
        return OverlapResult();
    }
    // Work relative to the triangle's centroid for accuracy. The wall is the
    // triangle's solid below it: the plane and its side planes.
    const Vec3 origin = (t0 + t1 + t2) / 3.0;
    const double depth = 2.0 * r + (dist < 0 ? -dist : 0.0);
    const Vec3 t[3] = {t0 - origin, t1 - origin, t2 - origin};
    double radius = 0;
    for (int i = 0; i < 3; ++i)
    {
        const double ri = norm(t[i] - depth * n);
        radius = ri > radius ? ri : radius;
        const double rt = norm(t[i]);
        radius = rt > radius ? rt : radius;
    }
    Vec3 m[kMaxWallSidePlanes];
    double d[kMaxWallSidePlanes];
    int nm = 0;
    if (sideNormal)
    {
        nm = nSides < kMaxWallSidePlanes ? nSides : kMaxWallSidePlanes;
        for (int k = 0; k < nm; ++k)
        {
            m[k] = sideNormal[k];
            d[k] = sideOffset[k] + dot(m[k], t[0]);   // about the centroid
        }
    }
    else
    {
        // The normal prism: the side through edge (i, i+1), counter-clockwise about n
        nm = 3;
        for (int i = 0; i < 3; ++i)
        {
            const Vec3 e = t[(i + 1) % 3] - t[i];
            m[i] = cross(e, n);
            m[i] = m[i] / norm(m[i]);
            d[i] = dot(m[i], t[i]);
        }
    }
    const double tol = kOverlapPlaneTolerance * (radius > r ? radius : r);
    overlapDetail::ClipIntegrals I =
        overlapDetail::halfSpaceClipIntegrals(P, pos, q, origin, n, m, d, nm, tol);
    if (dist - r < -wallDepth)
    {
        // The floor: take away the part of P below it (the same solid, its
        // top moved down to the floor; the side offsets taken about the
        // floor's origin, which moves them where a side is tilted against n)
        const Vec3 floorOrigin = origin - wallDepth * n;
        double floorOffset[kMaxWallSidePlanes];
        for (int k = 0; k < nm; ++k)
        {
            floorOffset[k] = d[k] + wallDepth * dot(m[k], n);
        }
        const overlapDetail::ClipIntegrals below = overlapDetail::halfSpaceClipIntegrals(
            P, pos, q, floorOrigin, n, m, floorOffset, nm, tol);
        I.volume -= below.volume;
        I.moment -= below.moment - (wallDepth * below.volume) * n;
        I.twiceArea -= below.twiceArea;
    }
    return overlapDetail::clipOverlapResult(I, P, origin, pos - origin);
}

//- Overlap of a polyhedron (A) with a sphere (B), distance based (see top):
//  normal from the polyhedron to the sphere, volume/centroid of the spherical
//  cap whose depth is the penetration of the sphere past the closest feature.
inline PD_HD OverlapResult polyhedronSphereOverlap(const ConvexPolyhedron& P, const Vec3& pos,
                                                   const Quaternion& q, const Vec3& centre,
                                                   double radius)
{
    OverlapResult res;
    const Vec3 c = rotateInverse(q, centre - pos);
    if (normSqr(c) >= (P.boundingRadius + radius) * (P.boundingRadius + radius))
    {
        return res;
    }
    // Signed distance to the face planes
    int deepFace = 0;
    double sMax = -1e300;
    for (int f = 0; f < P.nFaces; ++f)
    {
        const double s = dot(P.faceNormals[f], c) - P.faceOffsets[f];
        if (s > sMax)
        {
            sMax = s;
            deepFace = f;
        }
    }
    double depth;
    Vec3 normal;
    if (sMax <= 0)
    {
        // Centre inside: leave through the nearest face
        depth = radius - sMax;
        normal = P.faceNormals[deepFace];
    }
    else
    {
        // Closest point: on one of the faces the centre is in front of
        double bestSqr = 1e300;
        Vec3 closest;
        for (int f = 0; f < P.nFaces; ++f)
        {
            const Vec3& nf = P.faceNormals[f];
            const double s = dot(nf, c) - P.faceOffsets[f];
            if (s <= 0)
            {
                continue;
            }
            const Vec3 p = c - s * nf;
            const int m = P.faceSize(f);
            bool inside = true;
            for (int i = 0; i < m && inside; ++i)
            {
                const Vec3& a = P.faceVertexPoint(f, i);
                const Vec3& b = P.faceVertexPoint(f, i + 1 == m ? 0 : i + 1);
                inside = dot(cross(b - a, p - a), nf) >= 0;
            }
            if (inside)
            {
                if (s * s < bestSqr)
                {
                    bestSqr = s * s;
                    closest = p;
                }
                continue;
            }
            for (int i = 0; i < m; ++i)
            {
                const Vec3& a = P.faceVertexPoint(f, i);
                const Vec3& b = P.faceVertexPoint(f, i + 1 == m ? 0 : i + 1);
                const Vec3 ab = b - a;
                double t = dot(c - a, ab) / normSqr(ab);
                t = t < 0 ? 0 : (t > 1 ? 1 : t);
                const Vec3 x = a + t * ab;
                const double d2 = normSqr(c - x);
                if (d2 < bestSqr)
                {
                    bestSqr = d2;
                    closest = x;
                }
            }
        }
        const double dist = sqrt(bestSqr);
        if (dist >= radius || !(dist > 0))
        {
            return res;
        }
        depth = radius - dist;
        normal = (c - closest) / dist;
    }
    depth = depth < 2.0 * radius ? depth : 2.0 * radius;
    const double pi = 3.14159265358979323846;
    res.volume = pi * depth * depth * (3.0 * radius - depth) / 3.0;
    const double sphereVolume = 4.0 / 3.0 * pi * radius * radius * radius;
    const double minVolume = P.volume < sphereVolume ? P.volume : sphereVolume;
    if (!(res.volume > kOverlapTouchingVolume * minVolume))
    {
        return OverlapResult();
    }
    res.touching = true;
    // Cap centroid: 3 (2R - h)^2 / (4 (3R - h)) from the sphere centre
    const double zBar = 3.0 * (2.0 * radius - depth) * (2.0 * radius - depth)
                        / (4.0 * (3.0 * radius - depth));
    res.centroid = c - zBar * normal;
    res.contactArea = pi * depth * (2.0 * radius - depth);
    res.normal = normal;
    res.areaVector = res.contactArea * normal;
    return overlapDetail::toWorld(res, pos, q);
}

} // namespace polydem

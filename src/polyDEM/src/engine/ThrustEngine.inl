// polyDEM: the DEM engine, written once on Thrust and compiled twice:
// by nvcc for the CUDA back end (BackendCuda.cu) and by g++ with Thrust's
// OpenMP device system for the CPU back end (BackendCpu.cpp).
//
// Per step (velocity Verlet):
//   half kick (v, L) -> drift (x, q) -> [rebuild neighbour lists if some particle
//   moved more than half the skin] -> forces -> half kick.
// Forces are gathered per particle (no atomics): each particle walks its own
// full neighbour list and evaluates every pair with the particle of smaller id
// as body 1, so both copies of a pair agree to the bit and the sums are
// deterministic — the two back ends then give the same trajectories.
//
// The including file defines PD_BACKEND_NAME ("cpu"/"cuda") and
// PD_BACKEND_NS (a namespace private to the back end).

#include "polyDEM/ContactLaws.hpp"
#include "polyDEM/Engine.hpp"
#include "polyDEM/Error.hpp"
#include "polyDEM/PolyhedronOverlap.hpp"
#include "polyDEM/RestitutionCalibration.hpp"

#include "DeviceGeometry.hpp"

#include <limits>

#include <thrust/copy.h>
#include <thrust/device_vector.h>
#include <thrust/execution_policy.h>
#include <thrust/fill.h>
#include <thrust/functional.h>
#include <thrust/transform.h>
#include <thrust/for_each.h>
#include <thrust/gather.h>
#include <thrust/host_vector.h>
#include <thrust/iterator/counting_iterator.h>
#include <thrust/reduce.h>
#include <thrust/sequence.h>
#include <thrust/sort.h>
#include <thrust/transform_reduce.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <vector>

namespace polydem
{
namespace PD_BACKEND_NS
{

using detail::RigidMotion;
using std::int64_t;

template<class T>
using dvec = thrust::device_vector<T>;

template<class T>
T* ptr(dvec<T>& v)
{
    return thrust::raw_pointer_cast(v.data());
}

template<class T>
const T* ptr(const dvec<T>& v)
{
    return thrust::raw_pointer_cast(v.data());
}

template<class T>
std::vector<T> toHost(const dvec<T>& d)
{
    thrust::host_vector<T> h(d);
    return std::vector<T>(h.begin(), h.end());
}

template<class T>
void toDevice(dvec<T>& d, const std::vector<T>& h)
{
    d.assign(h.begin(), h.end());
}

// ---------------------------------------------------------------------------
// Plain device views of the state, passed by value into the functors
// ---------------------------------------------------------------------------

struct ParticleView
{
    int n;
    const int64_t* id;
    const int* type;
    const double* radius;
    const double* mass;
    const Vec3* inertia;
    Vec3* pos;
    Quaternion* q;
    Vec3* vel;
    Vec3* omega;
    Vec3* force;
    Vec3* torque;
    const Vec3* extForce;  //!< null when none
    const Vec3* extTorque;
};

struct PlaneDevice
{
    Vec3 point;
    Vec3 normal;
    int material;
    RigidMotion motion;
};

//- One triangle-mesh wall, its triangles in the body (t = 0) frame, binned
//  once into a uniform grid: particles are moved into the body frame instead
//  of the triangles into the world frame, so a moving wall is never re-binned.
struct MeshDevice
{
    int material;
    RigidMotion motion;
    int firstTriangle;     //!< into the global triangle arrays
    Vec3 gridOrigin;
    double cellSize;
    int nx, ny, nz;
    int firstCell;         //!< into the global cell-start array (nx*ny*nz + 1 entries)
};

struct MeshSlot
{
    int mesh;              //!< -1 = empty
    int triangle;
    Vec3 normal;
    Vec3 xi;
    Vec3 mr;
};

constexpr int maxMeshSlots = 6;
constexpr int maxMeshCandidates = 24;

struct LawView
{
    LawParameters law;
    const PairCoefficients* pairs;
    int nMaterials;
    const int* typeMaterial;
    const int* typeShape;       //!< -1: sphere, else index into shapes
    PolyhedronTable shapes;     //!< device copies of the convex shapes

    PD_HD const PairCoefficients& pair(int ma, int mb) const
    {
        return pairs[ma * nMaterials + mb];
    }
};

PD_HD inline double rollingInertiaOf(double I, double m, double r)
{
    return I + m * r * r;
}

// ---------------------------------------------------------------------------
// Integration
// ---------------------------------------------------------------------------

//- Angular momentum <-> angular velocity through the rotated inertia tensor
PD_HD inline Vec3 worldInertiaTimes(const Quaternion& q, const Vec3& I, const Vec3& w)
{
    return rotate(q, cmul(I, rotateInverse(q, w)));
}

PD_HD inline Vec3 worldInverseInertiaTimes(const Quaternion& q, const Vec3& I, const Vec3& L)
{
    const Vec3 b = rotateInverse(q, L);
    return rotate(q, Vec3(b.x / I.x, b.y / I.y, b.z / I.z));
}

//- First half kick and drift; returns the squared displacement since the last
//  neighbour-list build, so that the rebuild check needs no pass of its own
struct KickDrift
{
    ParticleView p;
    const int* typeShape;   //!< -1 for spheres
    const Vec3* ref;
    double dt;

    PD_HD double operator()(int i) const
    {
        const double m = p.mass[i];
        const Vec3 v = p.vel[i] + (0.5 * dt / m) * p.force[i];
        const Vec3 x = p.pos[i] + dt * v;
        p.pos[i] = x;
        p.vel[i] = v;

        const Vec3 I = p.inertia[i];
        if (typeShape[p.type[i]] < 0)
        {
            // A sphere: its orientation changes nothing, so it is not integrated
            p.omega[i] += (0.5 * dt / I.x) * p.torque[i];
            return normSqr(x - ref[i]);
        }

        const Quaternion q0 = p.q[i];
        const Vec3 L = worldInertiaTimes(q0, I, p.omega[i]) + (0.5 * dt) * p.torque[i];
        Quaternion q1;
        Vec3 w;
        if (I.x == I.y && I.y == I.z)
        {
            // Isotropic inertia (a cube, a regular solid): omega is constant over the drift
            w = L / I.x;
            q1 = normalised(fromRotationVector(dt * w) * q0);
        }
        else
        {
            // Implicit midpoint for the free rotation at constant L: the angular
            // velocity of the mid orientation rotates the start one by dt.
            Vec3 wMid = worldInverseInertiaTimes(q0, I, L);
            for (int it = 0; it < 4; ++it)
            {
                const Quaternion qMid = normalised(fromRotationVector((0.5 * dt) * wMid) * q0);
                wMid = worldInverseInertiaTimes(qMid, I, L);
            }
            q1 = normalised(fromRotationVector(dt * wMid) * q0);
            w = worldInverseInertiaTimes(q1, I, L);
        }
        p.q[i] = q1;
        p.omega[i] = w;
        return normSqr(x - ref[i]);
    }
};

struct FinalKick
{
    ParticleView p;
    const int* typeShape;
    double dt;

    PD_HD void operator()(int i) const
    {
        p.vel[i] += (0.5 * dt / p.mass[i]) * p.force[i];
        const Vec3 I = p.inertia[i];
        if (typeShape[p.type[i]] < 0)
        {
            p.omega[i] += (0.5 * dt / I.x) * p.torque[i];
        }
        else
        {
            const Vec3 L = worldInertiaTimes(p.q[i], I, p.omega[i]) + (0.5 * dt) * p.torque[i];
            p.omega[i] = worldInverseInertiaTimes(p.q[i], I, L);
        }
    }
};

// ---------------------------------------------------------------------------
// Broad phase: hashed uniform grid, sorted by cell
// ---------------------------------------------------------------------------

struct Grid
{
    double cellSize;
    unsigned tableMask;

    PD_HD void cellOf(const Vec3& x, int64_t& ix, int64_t& iy, int64_t& iz) const
    {
        ix = int64_t(floor(x.x / cellSize));
        iy = int64_t(floor(x.y / cellSize));
        iz = int64_t(floor(x.z / cellSize));
    }

    PD_HD unsigned hash(int64_t ix, int64_t iy, int64_t iz) const
    {
        const uint64_t h = uint64_t(ix) * 73856093ULL ^ uint64_t(iy) * 19349663ULL ^ uint64_t(iz) * 83492791ULL;
        return unsigned(h) & tableMask;
    }
};

struct CellKey
{
    Grid grid;
    const Vec3* ref;

    PD_HD unsigned operator()(int i) const
    {
        int64_t ix, iy, iz;
        grid.cellOf(ref[i], ix, iy, iz);
        return grid.hash(ix, iy, iz);
    }
};

struct InsideDomain
{
    const Vec3* ref;
    Vec3 lo, hi;

    PD_HD bool operator()(int i) const
    {
        const Vec3 x = ref[i];
        return x.x >= lo.x && x.x <= hi.x && x.y >= lo.y && x.y <= hi.y && x.z >= lo.z && x.z <= hi.z;
    }
};

struct MarkCellRanges
{
    const unsigned* keys;
    int n;
    int* cellStart;
    int* cellEnd;

    PD_HD void operator()(int k) const
    {
        const unsigned key = keys[k];
        if (k == 0 || keys[k - 1] != key) cellStart[key] = k;
        if (k == n - 1 || keys[k + 1] != key) cellEnd[key] = k + 1;
    }
};

//- Walks the 27 cells around a particle; with `out` null it only counts.
//  A hash collision can bring a particle of another cell into the range: it is
//  skipped unless it really lies in the cell being scanned, so nobody is listed twice.
struct BuildNeighbours
{
    Grid grid;
    const Vec3* ref;
    const double* radius;
    const int64_t* id;
    const int* cellStart;
    const int* cellEnd;
    double skin;
    int* count;
    int* owned;     //!< how many of the list's first entries have a larger id
    int* out;       //!< null for the counting pass
    int maxNbr;

    //- Scan the 27 cells; pass 0: all (counting) or larger ids, pass 1: smaller ids
    PD_HD int scan(int i, int pass, int c) const
    {
        int64_t cx, cy, cz;
        const Vec3 xi = ref[i];
        grid.cellOf(xi, cx, cy, cz);
        for (int dz = -1; dz <= 1; ++dz)
        for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
        {
            const int64_t ix = cx + dx, iy = cy + dy, iz = cz + dz;
            const unsigned h = grid.hash(ix, iy, iz);
            const int start = cellStart[h];
            if (start < 0) continue;
            const int end = cellEnd[h];
            for (int j = start; j < end; ++j)
            {
                if (j == i) continue;
                if (out && ((pass == 0) != (id[j] > id[i]))) continue;
                int64_t jx, jy, jz;
                grid.cellOf(ref[j], jx, jy, jz);
                if (jx != ix || jy != iy || jz != iz) continue;
                const double reach = radius[i] + radius[j] + skin;
                if (normSqr(ref[j] - xi) < reach * reach)
                {
                    if (out) out[size_t(i) * maxNbr + c] = j;
                    ++c;
                }
            }
        }
        return c;
    }

    PD_HD void operator()(int i) const
    {
        if (!out)
        {
            count[i] = scan(i, 0, 0);
            return;
        }
        // The pairs this particle evaluates (partner of larger id) come first
        const int nOwned = scan(i, 0, 0);
        owned[i] = nOwned;
        count[i] = scan(i, 1, nOwned);
    }
};

//- Carries each pair's springs over to the new lists (matched by particle id)
struct TransferPairHistory
{
    const int* perm;          //!< new index -> old index
    int oldN;
    const int* newCount;
    const int* newNbr;
    int newMax;
    const int64_t* newId;     //!< ids in the new order
    const int* oldCount;
    const int64_t* oldPartner;
    const Vec3* oldXi;
    const Vec3* oldMr;
    int oldMax;
    int64_t* partner;
    Vec3* xi;
    Vec3* mr;
    unsigned char* touching;  //!< set where a spring came over (release() must clear it)

    PD_HD void operator()(int i) const
    {
        const int o = perm[i];
        const int nOld = (o < oldN && oldCount) ? oldCount[o] : 0;
        for (int k = 0; k < newCount[i]; ++k)
        {
            const size_t s = size_t(i) * newMax + k;
            const int64_t pid = newId[newNbr[s]];
            partner[s] = pid;
            Vec3 x, m;
            for (int l = 0; l < nOld; ++l)
            {
                const size_t so = size_t(o) * oldMax + l;
                if (oldPartner[so] == pid)
                {
                    x = oldXi[so];
                    m = oldMr[so];
                    break;
                }
            }
            xi[s] = x;
            mr[s] = m;
            touching[s] = (normSqr(x) > 0 || normSqr(m) > 0) ? 1 : 0;
        }
    }
};

//- For every pair slot a particle owns (partner of larger id, first in its
//  list): the slot in the partner's list that points back, where PairKernel
//  leaves the partner's share of the result
struct LinkMirrorSlots
{
    const int* nbrOwned;
    const int* nbrCount;
    const int* nbr;
    int maxNbr;
    int* mirror;

    PD_HD void operator()(int i) const
    {
        for (int k = 0; k < nbrOwned[i]; ++k)
        {
            const size_t s = size_t(i) * maxNbr + k;
            const int j = nbr[s];
            for (int l = nbrOwned[j]; l < nbrCount[j]; ++l)
            {
                if (nbr[size_t(j) * maxNbr + l] == i)
                {
                    mirror[s] = int(size_t(j) * maxNbr + l);
                    break;
                }
            }
        }
    }
};

// ---------------------------------------------------------------------------
// Forces
// ---------------------------------------------------------------------------

//- Overlap of two spheres as the volumetric law sees it: lens volume, area of
//  the intersection disc, lens centroid (on the line of centres); n from a to b
PD_HD inline OverlapResult sphereSphereOverlap
(
    const Vec3& xa, double ra, const Vec3& xb, double rb
)
{
    OverlapResult res;
    const Vec3 d = xb - xa;
    const double dist = norm(d);
    const double h = ra + rb - dist;
    if (h <= 0 || dist <= 0) return res;
    const double pi = 3.14159265358979323846;
    res.touching = true;
    res.normal = d / dist;
    // Distance from a's centre to the plane of the intersection circle
    const double xPlane = (dist * dist - rb * rb + ra * ra) / (2 * dist);
    const double ha = ra - xPlane, hb = rb - (dist - xPlane);  // cap heights
    const double va = pi * ha * ha * (3 * ra - ha) / 3, vb = pi * hb * hb * (3 * rb - hb) / 3;
    res.volume = va + vb;
    const double a2 = ra * ra - xPlane * xPlane;
    res.contactArea = pi * (a2 > 0 ? a2 : 0);
    // Cap centroids measured from their sphere centres
    const double za = 3 * (2 * ra - ha) * (2 * ra - ha) / (4 * (3 * ra - ha));
    const double zb = 3 * (2 * rb - hb) * (2 * rb - hb) / (4 * (3 * rb - hb));
    const double s = res.volume > 0 ? (va * za + vb * (dist - zb)) / res.volume : xPlane;
    res.centroid = xa + s * res.normal;
    res.areaVector = res.contactArea * res.normal;
    return res;
}

//- A sphere against the half-space behind a plane (normal n out of the wall):
//  cap volume, section area, cap centroid; result normal from the wall to the sphere
PD_HD inline OverlapResult sphereHalfSpaceOverlap(const Vec3& x, double r, const Vec3& foot, const Vec3& n)
{
    OverlapResult res;
    const double h = r - dot(x - foot, n);
    if (h <= 0) return res;
    const double hh = h < 2 * r ? h : 2 * r;
    const double pi = 3.14159265358979323846;
    res.touching = true;
    res.normal = n;
    res.volume = pi * hh * hh * (3 * r - hh) / 3;
    res.contactArea = pi * hh * (2 * r - hh);
    const double z = 3 * (2 * r - hh) * (2 * r - hh) / (4 * (3 * r - hh));
    res.centroid = x - z * n;
    res.areaVector = res.contactArea * n;
    return res;
}

//- Evaluates every contact once, in the list of its particle of smaller id,
//  and leaves the force and both torques in the pair's slot for ForceKernel
struct PairKernel
{
    ParticleView p;
    LawView law;
    const int* nbrOwned;
    const int* nbr;
    int maxNbr;
    const int* mirror;
    Vec3* pairXi;
    Vec3* pairMr;
    unsigned char* slotTouching;
    Vec3* slotForce;
    Vec3* slotTorque;

    //- Volumetric overlap of particles a and b, normal from a to b
    PD_HD OverlapResult pairOverlap(int a, int b) const
    {
        const int sa = law.typeShape[p.type[a]];
        const int sb = law.typeShape[p.type[b]];
        if (sa < 0 && sb < 0)
        {
            return sphereSphereOverlap(p.pos[a], p.radius[a], p.pos[b], p.radius[b]);
        }
        if (sa >= 0 && sb >= 0)
        {
            return polyhedronOverlap(law.shapes.shape(sa), p.pos[a], p.q[a],
                                     law.shapes.shape(sb), p.pos[b], p.q[b]);
        }
        if (sa >= 0)
        {
            return polyhedronSphereOverlap(law.shapes.shape(sa), p.pos[a], p.q[a], p.pos[b], p.radius[b]);
        }
        OverlapResult r = polyhedronSphereOverlap(law.shapes.shape(sb), p.pos[b], p.q[b], p.pos[a], p.radius[a]);
        r.normal = -r.normal;
        r.areaVector = -r.areaVector;
        return r;
    }

    //- A contact that ended: its springs go (written only once, not every step
    //  for every neighbour out of reach)
    PD_HD void release(size_t s) const
    {
        if (slotTouching[s])
        {
            slotTouching[s] = 0;
            slotTouching[mirror[s]] = 0;
            pairXi[s] = Vec3();
            pairMr[s] = Vec3();
        }
    }

    //- Each side's share goes into its own slot: the partner then sums its
    //  list front to back, with no scattered reads (and no write races: the
    //  mirror slot is written by this pair's owner only)
    PD_HD void store(size_t s, const ContactResult& res, const Vec3& armA, const Vec3& armB) const
    {
        const size_t m = size_t(mirror[s]);
        slotTouching[s] = 1;
        slotTouching[m] = 1;
        slotForce[s] = res.force;
        slotTorque[s] = cross(armA, res.force) + res.rollingTorque;
        slotForce[m] = -res.force;
        slotTorque[m] = cross(armB, -res.force) - res.rollingTorque;
    }

    PD_HD void operator()(int i) const
    {
        // Only the pairs this particle owns: they are first in its list
        const int cnt = nbrOwned[i];
        for (int k = 0; k < cnt; ++k)
        {
            evaluatePair(i, k);
        }
    }

    //- Contact of particle i with its k-th (owned) neighbour
    PD_HD void evaluatePair(int i, int k) const
    {
        {
            const size_t s = size_t(i) * maxNbr + k;
            const int a = i;
            const int b = nbr[s];
            if (law.law.law == ContactLaw::overlapVolume)
            {
                // Bounding spheres first: the exact overlap is the costly part
                const double reach = p.radius[a] + p.radius[b];
                const OverlapResult ov = normSqr(p.pos[b] - p.pos[a]) < reach * reach
                                       ? pairOverlap(a, b) : OverlapResult();
                if (!ov.touching)
                {
                    release(s);
                    return;
                }
                
                ContactKinematics kin;
                kin.normal = ov.normal;
                kin.overlap = ov.volume;
                kin.contactArea = ov.contactArea;
                const double ra = p.radius[a], rb = p.radius[b];
                kin.rStar = ra * rb / (ra + rb);
                const double ma = p.mass[a], mb = p.mass[b];
                kin.mStar = ma * mb / (ma + mb);
                const double Ia = rollingInertiaOf(p.inertia[a].x, ma, ra);
                const double Ib = rollingInertiaOf(p.inertia[b].x, mb, rb);
                kin.rollingInertia = Ia * Ib / (Ia + Ib);
                const Vec3 armA = ov.centroid - p.pos[a];
                const Vec3 armB = ov.centroid - p.pos[b];
                kin.relVelocity = (p.vel[a] + cross(p.omega[a], armA)) - (p.vel[b] + cross(p.omega[b], armB));
                kin.relOmega = p.omega[a] - p.omega[b];
                const ContactResult res = evaluateContact(law.law, law.pair(law.typeMaterial[p.type[a]],
                                                          law.typeMaterial[p.type[b]]), kin, pairXi[s], pairMr[s]);
                store(s, res, armA, armB);
                return;
            }
            const Vec3 d = p.pos[b] - p.pos[a];
            const double dist = norm(d);
            const double ra = p.radius[a], rb = p.radius[b];
            const double overlap = ra + rb - dist;
            if (overlap <= 0 || dist <= 0)
            {
                release(s);
                return;
            }
            
            ContactKinematics kin;
            kin.normal = d / dist;
            kin.overlap = overlap;
            kin.rStar = ra * rb / (ra + rb);
            const double ma = p.mass[a], mb = p.mass[b];
            kin.mStar = ma * mb / (ma + mb);
            const double Ia = rollingInertiaOf(p.inertia[a].x, ma, ra);
            const double Ib = rollingInertiaOf(p.inertia[b].x, mb, rb);
            kin.rollingInertia = Ia * Ib / (Ia + Ib);
            const Vec3 armA = (ra - 0.5 * overlap) * kin.normal;
            const Vec3 armB = -(rb - 0.5 * overlap) * kin.normal;
            kin.relVelocity = (p.vel[a] + cross(p.omega[a], armA)) - (p.vel[b] + cross(p.omega[b], armB));
            kin.relOmega = p.omega[a] - p.omega[b];
            const int ma_ = law.typeMaterial[p.type[a]];
            const int mb_ = law.typeMaterial[p.type[b]];
            const ContactResult res = evaluateContact(law.law, law.pair(ma_, mb_), kin, pairXi[s], pairMr[s]);
            store(s, res, armA, armB);
        }
    }
};

//- One thread per neighbour slot (GPU): a polyhedron pair is a long serial
//  computation (clipping), and one thread per particle running through its
//  list leaves a small system with too few threads and each thread with too
//  much work. Same pairs, same slots, same results as PairKernel.
struct PairSlotKernel
{
    PairKernel pk;

    PD_HD void operator()(int t) const
    {
        const int i = t / pk.maxNbr;
        const int k = t - i * pk.maxNbr;
        if (k < pk.nbrOwned[i])
        {
            pk.evaluatePair(i, k);
        }
    }
};

struct ForceKernel
{
    ParticleView p;
    LawView law;
    Vec3 gravity;
    double time;

    // particle-particle results of PairKernel, per slot of each list
    const int* nbrCount;
    int maxNbr;
    const unsigned char* slotTouching;
    const Vec3* slotForce;
    const Vec3* slotTorque;
    int* contactCount;

    // planes: per particle nPlanes slots
    const PlaneDevice* planes;
    int nPlanes;
    Vec3* planeXi;
    Vec3* planeMr;

    // triangle meshes: per particle maxMeshSlots slots
    const MeshDevice* meshes;
    int nMeshes;
    const Vec3* triA;
    const Vec3* triB;
    const Vec3* triC;
    const int* cellStart;
    const int* cellTriangles;
    MeshSlot* meshSlots;
    int* wallContactCount;

    PD_HD void wallContact
    (
        int i, int material, const Vec3& wallPoint, const Vec3& wallVel, const Vec3& wallOmega,
        Vec3& xi, Vec3& mr, Vec3& F, Vec3& T
    ) const
    {
        const Vec3 x = p.pos[i];
        const double r = p.radius[i];
        const Vec3 d = wallPoint - x;
        const double dist = norm(d);
        ContactKinematics k;
        k.normal = d / dist;
        k.overlap = r - dist;
        k.rStar = r;
        k.mStar = p.mass[i];
        k.rollingInertia = rollingInertiaOf(p.inertia[i].x, p.mass[i], r);
        const Vec3 arm = (r - 0.5 * k.overlap) * k.normal;
        k.relVelocity = p.vel[i] + cross(p.omega[i], arm) - wallVel;
        k.relOmega = p.omega[i] - wallOmega;
        const int mp = law.typeMaterial[p.type[i]];
        const ContactResult res = evaluateContact(law.law, law.pair(mp, material), k, xi, mr);
        F += res.force;
        T += cross(arm, res.force) + res.rollingTorque;
    }

    //- Reset a wall spring, writing only when there is something to reset
    //  (most particles are away from most walls most of the time)
    PD_HD static void clearSpring(Vec3& xi, Vec3& mr)
    {
        if (xi.x != 0 || xi.y != 0 || xi.z != 0) xi = Vec3();
        if (mr.x != 0 || mr.y != 0 || mr.z != 0) mr = Vec3();
    }

    //- Volumetric contact of particle i with a wall. ov.normal points from the
    //  wall into the particle; ov.centroid is the contact point.
    PD_HD void wallContactVolumetric
    (
        int i, int material, const OverlapResult& ov, const Vec3& wallVel, const Vec3& wallOmega,
        Vec3& xi, Vec3& mr, Vec3& F, Vec3& T
    ) const
    {
        const Vec3 x = p.pos[i];
        ContactKinematics k;
        k.normal = -ov.normal;
        k.overlap = ov.volume;
        k.contactArea = ov.contactArea;
        k.rStar = p.radius[i];
        k.mStar = p.mass[i];
        k.rollingInertia = rollingInertiaOf(p.inertia[i].x, p.mass[i], p.radius[i]);
        const Vec3 arm = ov.centroid - x;
        k.relVelocity = p.vel[i] + cross(p.omega[i], arm) - wallVel;
        k.relOmega = p.omega[i] - wallOmega;
        const int mp = law.typeMaterial[p.type[i]];
        const ContactResult res = evaluateContact(law.law, law.pair(mp, material), k, xi, mr);
        F += res.force;
        T += cross(arm, res.force) + res.rollingTorque;
    }

    PD_HD void operator()(int i) const
    {
        const double m = p.mass[i];
        Vec3 F = m * gravity;
        Vec3 T;
        if (p.extForce) F += p.extForce[i];
        if (p.extTorque) T += p.extTorque[i];

        const Vec3 xi_ = p.pos[i];
        const double ri = p.radius[i];

        // Particle-particle: sum this particle's share of every pair, in list
        // order (deterministic whatever the thread schedule)
        int touching = 0;
        const int cnt = nbrCount[i];
        for (int k = 0; k < cnt; ++k)
        {
            const size_t s = size_t(i) * maxNbr + k;
            if (!slotTouching[s]) continue;
            ++touching;
            F += slotForce[s];
            T += slotTorque[s];
        }
        contactCount[i] = touching;

        int walls = 0;

        // Planes
        for (int w = 0; w < nPlanes; ++w)
        {
            const PlaneDevice& pl = planes[w];
            const Quaternion R = pl.motion.rotationAt(time);
            const Vec3 n = pl.motion.directionToWorld(pl.normal, R);
            const Vec3 p0 = pl.motion.toWorld(pl.point, time, R);
            const double h = dot(xi_ - p0, n);
            const size_t s = size_t(i) * nPlanes + w;
            if (h >= ri)
            {
                clearSpring(planeXi[s], planeMr[s]);
                continue;
            }
            const Vec3 foot = xi_ - h * n;
            if (law.law.law == ContactLaw::overlapVolume)
            {
                const int sh = law.typeShape[p.type[i]];
                const OverlapResult ov = sh >= 0
                    ? polyhedronPlaneOverlap(law.shapes.shape(sh), xi_, p.q[i], p0, n)
                    : sphereHalfSpaceOverlap(xi_, ri, foot, n);
                if (!ov.touching)
                {
                    clearSpring(planeXi[s], planeMr[s]);
                    continue;
                }
                ++walls;
                wallContactVolumetric(i, pl.material, ov, pl.motion.velocityAt(ov.centroid),
                                      pl.motion.angularVelocity(), planeXi[s], planeMr[s], F, T);
                continue;
            }
            ++walls;
            wallContact(i, pl.material, foot, pl.motion.velocityAt(foot), pl.motion.angularVelocity(),
                        planeXi[s], planeMr[s], F, T);
        }

        // Triangle meshes
        if (nMeshes > 0)
        {
            MeshSlot* slots = meshSlots + size_t(i) * maxMeshSlots;
            MeshSlot next[maxMeshSlots];
            int nNext = 0;

            for (int w = 0; w < nMeshes; ++w)
            {
                const MeshDevice& mesh = meshes[w];
                const Quaternion R = mesh.motion.rotationAt(time);
                const Vec3 y = mesh.motion.toBody(xi_, time, R);
                const Vec3 g = (y - mesh.gridOrigin) / mesh.cellSize;
                const int cx = int(floor(g.x)), cy = int(floor(g.y)), cz = int(floor(g.z));
                if (cx < 0 || cy < 0 || cz < 0 || cx >= mesh.nx || cy >= mesh.ny || cz >= mesh.nz) continue;
                const int cell = mesh.firstCell + (cz * mesh.ny + cy) * mesh.nx + cx;

                const int shapeI = law.typeShape[p.type[i]];
                if (law.law.law == ContactLaw::overlapVolume && shapeI >= 0)
                {
                    // Polyhedron: every triangle's prism adds its own overlap
                    // (coplanar neighbours partition the wall, so nothing is counted twice)
                    const ConvexPolyhedron P = law.shapes.shape(shapeI);
                    const Quaternion qBody = conjugate(R) * p.q[i];
                    for (int t = cellStart[cell]; t < cellStart[cell + 1] && nNext < maxMeshSlots; ++t)
                    {
                        const int tri = cellTriangles[t];
                        const int g0 = mesh.firstTriangle + tri;
                        const OverlapResult ovBody = polyhedronTriangleOverlap(P, y, qBody, triA[g0], triB[g0], triC[g0]);
                        if (!ovBody.touching) continue;
                        OverlapResult ov = ovBody;
                        ov.normal = mesh.motion.directionToWorld(ovBody.normal, R);
                        ov.centroid = mesh.motion.toWorld(ovBody.centroid, time, R);
                        Vec3 sxi, smr;
                        for (int s2 = 0; s2 < maxMeshSlots; ++s2)
                        {
                            if (slots[s2].mesh == w && slots[s2].triangle == tri)
                            {
                                sxi = slots[s2].xi;
                                smr = slots[s2].mr;
                                break;
                            }
                        }
                        ++walls;
                        wallContactVolumetric(i, mesh.material, ov, mesh.motion.velocityAt(ov.centroid),
                                              mesh.motion.angularVelocity(), sxi, smr, F, T);
                        MeshSlot& ns = next[nNext++];
                        ns.mesh = w;
                        ns.triangle = tri;
                        ns.normal = -ov.normal;
                        ns.xi = sxi;
                        ns.mr = smr;
                    }
                    continue;
                }

                // Candidates: every triangle within reach
                Vec3 cPoint[maxMeshCandidates];
                double cDist[maxMeshCandidates];
                int cTri[maxMeshCandidates], cFeature[maxMeshCandidates];
                int nc = 0;
                for (int t = cellStart[cell]; t < cellStart[cell + 1]; ++t)
                {
                    const int tri = cellTriangles[t];
                    const int g0 = mesh.firstTriangle + tri;
                    int feature;
                    const Vec3 cp = detail::closestPointOnTriangle(y, triA[g0], triB[g0], triC[g0], feature);
                    const double dd = norm(cp - y);
                    if (dd >= ri || dd <= 0) continue;
                    // Keep the nearest ones, sorted by feature (faces first) then distance
                    int pos = nc < maxMeshCandidates ? nc : maxMeshCandidates - 1;
                    if (nc == maxMeshCandidates)
                    {
                        const bool better = feature < cFeature[pos] || (feature == cFeature[pos] && dd < cDist[pos]);
                        if (!better) continue;
                    }
                    else
                    {
                        ++nc;
                    }
                    while (pos > 0 && (feature < cFeature[pos - 1] || (feature == cFeature[pos - 1] && dd < cDist[pos - 1])))
                    {
                        cPoint[pos] = cPoint[pos - 1]; cDist[pos] = cDist[pos - 1];
                        cTri[pos] = cTri[pos - 1]; cFeature[pos] = cFeature[pos - 1];
                        --pos;
                    }
                    cPoint[pos] = cp; cDist[pos] = dd; cTri[pos] = tri; cFeature[pos] = feature;
                }

                // Accept face contacts; an edge or vertex contact is an artefact of the
                // tessellation when it lies on an accepted face's plane or on an
                // accepted contact point (the same touch seen by a neighbour triangle).
                int accepted[maxMeshCandidates];
                int na = 0;
                const double tol = 1e-9 * ri + 1e-6 * ri;
                for (int c = 0; c < nc; ++c)
                {
                    bool duplicate = false;
                    for (int a = 0; a < na && !duplicate; ++a)
                    {
                        const int q = accepted[a];
                        if (norm(cPoint[c] - cPoint[q]) < tol) duplicate = true;
                        else if (cFeature[c] != detail::featureFace && cFeature[q] == detail::featureFace)
                        {
                            const Vec3 nq = (y - cPoint[q]) / cDist[q];
                            if (fabs(dot(cPoint[c] - cPoint[q], nq)) < tol) duplicate = true;
                        }
                    }
                    if (!duplicate) accepted[na++] = c;
                }

                for (int a = 0; a < na && nNext < maxMeshSlots; ++a)
                {
                    const int c = accepted[a];
                    const Vec3 nBody = (cPoint[c] - y) / cDist[c];
                    const Vec3 nWorld = mesh.motion.directionToWorld(nBody, R);
                    // The spring of this touch: same triangle, else a neighbour
                    // triangle touched last step with nearly the same normal
                    Vec3 sxi, smr;
                    int found = -1;
                    for (int s = 0; s < maxMeshSlots; ++s)
                    {
                        if (slots[s].mesh == w && slots[s].triangle == cTri[c]) { found = s; break; }
                    }
                    if (found < 0)
                    {
                        for (int s = 0; s < maxMeshSlots; ++s)
                        {
                            if (slots[s].mesh == w && dot(slots[s].normal, nWorld) > 0.99) { found = s; break; }
                        }
                    }
                    if (found >= 0)
                    {
                        sxi = slots[found].xi;
                        smr = slots[found].mr;
                    }
                    const Vec3 wallPoint = mesh.motion.toWorld(cPoint[c], time, R);
                    ++walls;
                    if (law.law.law == ContactLaw::overlapVolume)
                    {
                        // A sphere under the volumetric law: the cap cut by the
                        // tangent plane at the closest point
                        const OverlapResult ov = sphereHalfSpaceOverlap(xi_, ri, wallPoint, -nWorld);
                        wallContactVolumetric(i, mesh.material, ov, mesh.motion.velocityAt(ov.centroid),
                                              mesh.motion.angularVelocity(), sxi, smr, F, T);
                    }
                    else
                    {
                        wallContact(i, mesh.material, wallPoint, mesh.motion.velocityAt(wallPoint),
                                    mesh.motion.angularVelocity(), sxi, smr, F, T);
                    }
                    MeshSlot& ns = next[nNext++];
                    ns.mesh = w;
                    ns.triangle = cTri[c];
                    ns.normal = nWorld;
                    ns.xi = sxi;
                    ns.mr = smr;
                }
            }
            for (int s = 0; s < maxMeshSlots; ++s)
            {
                if (s < nNext) slots[s] = next[s];
                else slots[s].mesh = -1;
            }
        }
        wallContactCount[i] = walls;

        p.force[i] = F;
        p.torque[i] = T;
    }
};

struct KineticEnergy
{
    ParticleView p;
    Vec3 gravity;

    PD_HD Energies operator()(int i) const
    {
        Energies e;
        e.translational = 0.5 * p.mass[i] * normSqr(p.vel[i]);
        e.rotational = 0.5 * dot(p.omega[i], worldInertiaTimes(p.q[i], p.inertia[i], p.omega[i]));
        e.gravitational = -p.mass[i] * dot(gravity, p.pos[i]);
        return e;
    }
};

//- Largest overlap of a particle's contacts relative to the smaller radius
//  (Hertz and linear laws): how hard the contacts are pressed, a check on the
//  stiffness chosen. Not defined for the volumetric law (its overlap is a volume).
struct MaxOverlapRatio
{
    ParticleView p;
    const int* nbrOwned;
    const int* nbr;
    int maxNbr;
    const unsigned char* slotTouching;

    PD_HD double operator()(int i) const
    {
        double worst = 0;
        for (int k = 0; k < nbrOwned[i]; ++k)
        {
            const size_t s = size_t(i) * maxNbr + k;
            if (!slotTouching[s]) continue;
            const int j = nbr[s];
            const double rMin = p.radius[i] < p.radius[j] ? p.radius[i] : p.radius[j];
            const double ratio = (p.radius[i] + p.radius[j] - norm(p.pos[j] - p.pos[i])) / rMin;
            worst = ratio > worst ? ratio : worst;
        }
        return worst;
    }
};

//- total += new - old, for the external part of a stored force or torque
struct ReplaceExternal
{
    Vec3* total;
    const Vec3* oldPart;   //!< null: none
    const Vec3* newPart;   //!< null: none

    PD_HD void operator()(int i) const
    {
        if (oldPart) total[i] -= oldPart[i];
        if (newPart) total[i] += newPart[i];
    }
};

struct AddEnergies
{
    PD_HD Energies operator()(const Energies& a, const Energies& b) const
    {
        Energies e;
        e.translational = a.translational + b.translational;
        e.rotational = a.rotational + b.rotational;
        e.gravitational = a.gravitational + b.gravitational;
        e.elastic = a.elastic + b.elastic;
        return e;
    }
};

// ---------------------------------------------------------------------------
// The engine
// ---------------------------------------------------------------------------

class ThrustEngine : public Engine
{
public:
    std::string name() const override { return PD_BACKEND_NAME; }

    void initialise(const SimulationConfig& config, const Snapshot& s) override
    {
        config_ = config;
        time_ = s.time;
        step_ = s.step;
        setupLaw();
        setupPlanes();
        uploadParticles(s.particles);
        if (s.referencePosition.size() == s.particles.size())
        {
            toDevice(ref_, s.referencePosition);
        }
        else
        {
            ref_ = pos_;
        }
        setupMeshes();
        const size_t np = s.particles.size();
        toDevice(extForce_, s.externalForce.size() == np ? s.externalForce : std::vector<Vec3>());
        toDevice(extTorque_, s.externalTorque.size() == np ? s.externalTorque : std::vector<Vec3>());
        rebuild(false);
        restoreHistory(s);
        if (!s.forcesValid)
        {
            computeForces();
        }
    }

    void advance(int64_t nSteps) override
    {
        const double dt = config_.timeStep;
        const auto first = thrust::counting_iterator<int>(0);
        for (int64_t k = 0; k < nSteps; ++k)
        {
            const int n = int(id_.size());
            const double maxSqr = n == 0 ? 0.0 : thrust::transform_reduce(
                thrust::device, first, first + n, KickDrift{view(), ptr(typeShape_), ptr(ref_), dt},
                0.0, thrust::maximum<double>());
            ++step_;
            time_ = double(step_) * dt + timeOffset();
            const double half = 0.5 * skin();
            if (maxSqr > half * half)
            {
                rebuild(true);
            }
            computeForces();
            const int n2 = int(id_.size());
            thrust::for_each(thrust::device, first, first + n2, FinalKick{view(), ptr(typeShape_), dt});
        }
    }

    Snapshot snapshot() const override
    {
        Snapshot s;
        s.time = time_;
        s.step = step_;
        s.particles = particles();
        s.referencePosition = toHost(ref_);
        s.forcesValid = true;
        s.externalForce = toHost(extForce_);
        s.externalTorque = toHost(extTorque_);

        const int n = int(id_.size());
        const auto cnt = toHost(nbrCount_);
        const auto nb = toHost(nbr_);
        const auto xi = toHost(pairXi_);
        const auto mr = toHost(pairMr_);
        const auto& ids = s.particles.id;
        for (int i = 0; i < n; ++i)
        {
            for (int k = 0; k < cnt[i]; ++k)
            {
                const size_t sl = size_t(i) * maxNbr_ + k;
                const int j = nb[sl];
                if (ids[i] < ids[j] && (normSqr(xi[sl]) > 0 || normSqr(mr[sl]) > 0))
                {
                    s.pairs.push_back({ids[i], ids[j], xi[sl], mr[sl]});
                }
            }
        }
        const int nPl = int(config_.planes.size());
        if (nPl > 0)
        {
            const auto pxi = toHost(planeXi_);
            const auto pmr = toHost(planeMr_);
            for (int i = 0; i < n; ++i)
                for (int w = 0; w < nPl; ++w)
                {
                    const size_t sl = size_t(i) * nPl + w;
                    if (normSqr(pxi[sl]) > 0 || normSqr(pmr[sl]) > 0)
                    {
                        s.walls.push_back({ids[i], w, -1, Vec3(), pxi[sl], pmr[sl]});
                    }
                }
        }
        if (!config_.meshes.empty())
        {
            const auto slots = toHost(meshSlots_);
            for (int i = 0; i < n; ++i)
                for (int k = 0; k < maxMeshSlots; ++k)
                {
                    const MeshSlot& ms = slots[size_t(i) * maxMeshSlots + k];
                    if (ms.mesh >= 0)
                    {
                        s.walls.push_back({ids[i], nPl + ms.mesh, ms.triangle, ms.normal, ms.xi, ms.mr});
                    }
                }
        }
        return s;
    }

    ParticleState particles() const override
    {
        ParticleState p;
        p.id = toHost(id_);
        p.type = toHost(type_);
        p.radius = toHost(radius_);
        p.mass = toHost(mass_);
        p.inertia = toHost(inertia_);
        p.position = toHost(pos_);
        p.orientation = toHost(q_);
        p.velocity = toHost(vel_);
        p.omega = toHost(omega_);
        p.force = toHost(force_);
        p.torque = toHost(torque_);
        return p;
    }

    void addParticles(const ParticleState& added) override
    {
        ParticleState all = particles();
        std::vector<Vec3> ref = toHost(ref_);
        for (std::size_t i = 0; i < added.size(); ++i)
        {
            all.id.push_back(added.id[i]);
            all.type.push_back(added.type[i]);
            all.radius.push_back(added.radius[i]);
            all.mass.push_back(added.mass[i]);
            all.inertia.push_back(added.inertia[i]);
            all.position.push_back(added.position[i]);
            all.orientation.push_back(added.orientation[i]);
            all.velocity.push_back(added.velocity[i]);
            all.omega.push_back(added.omega[i]);
            all.force.push_back(Vec3());
            all.torque.push_back(Vec3());
            ref.push_back(added.position[i]);
        }
        // History of the existing particles survives: rebuild() matches it by id
        uploadParticles(all, false);
        toDevice(ref_, ref);
        extForce_.clear();
        extTorque_.clear();
        setupMeshes();
        rebuild(true);
        computeForces();
    }

    void setExternalForces(const std::vector<Vec3>& force, const std::vector<Vec3>& torque) override
    {
        const size_t n = id_.size();
        if ((!force.empty() && force.size() != n) || (!torque.empty() && torque.size() != n))
        {
            throw Error("external forces given for " + std::to_string(force.size())
                        + " particles, the engine holds " + std::to_string(n));
        }
        // The stored force and torque feed the next half kick: swap the old
        // external part for the new one there too, so that a force set between
        // steps acts from the very next step (not half a step late)
        dvec<Vec3> newForce, newTorque;
        toDevice(newForce, force);
        toDevice(newTorque, torque);
        const auto first = thrust::counting_iterator<int>(0);
        thrust::for_each(thrust::device, first, first + int(n),
                         ReplaceExternal{ptr(force_), extForce_.empty() ? nullptr : ptr(extForce_),
                                         newForce.empty() ? nullptr : ptr(newForce)});
        thrust::for_each(thrust::device, first, first + int(n),
                         ReplaceExternal{ptr(torque_), extTorque_.empty() ? nullptr : ptr(extTorque_),
                                         newTorque.empty() ? nullptr : ptr(newTorque)});
        extForce_.swap(newForce);
        extTorque_.swap(newTorque);
    }

    Energies energies(bool includeElastic = true) const override
    {
        const int n = int(id_.size());
        const auto first = thrust::counting_iterator<int>(0);
        ThrustEngine& self = const_cast<ThrustEngine&>(*this);
        Energies e = thrust::transform_reduce(thrust::device, first, first + n,
                                              KineticEnergy{self.view(), config_.gravity}, Energies(), AddEnergies());
        e.elastic = includeElastic ? elasticEnergy() : 0.0;
        return e;
    }

    Statistics statistics() const override
    {
        Statistics s;
        s.particles = id_.size();
        const auto cc = toHost(contactCount_);
        const auto wc = toHost(wallContactCount_);
        size_t sum = 0, inContact = 0, walls = 0;
        for (size_t i = 0; i < cc.size(); ++i)
        {
            sum += cc[i];
            walls += wc[i];
            if (cc[i] + wc[i] > 0) ++inContact;
        }
        s.contacts = sum / 2;
        const int n = int(id_.size());
        if (n > 0 && law_.law != ContactLaw::overlapVolume)
        {
            ThrustEngine& self = const_cast<ThrustEngine&>(*this);
            const auto first = thrust::counting_iterator<int>(0);
            s.maxOverlapRatio = thrust::transform_reduce(
                thrust::device, first, first + n,
                MaxOverlapRatio{self.view(), ptr(nbrOwned_), ptr(nbr_), maxNbr_, ptr(slotTouching_)},
                0.0, thrust::maximum<double>());
        }
        s.wallContacts = walls;
        s.particlesInContact = inContact;
        s.neighbourListBuilds = builds_;
        return s;
    }

    double time() const override { return time_; }
    int64_t step() const override { return step_; }

private:
    // Time is step * dt relative to the step/time the run started from, so a
    // restart reproduces the same wall positions to the bit.
    double timeOffset() const { return time0_ - double(step0_) * config_.timeStep; }

    ParticleView view()
    {
        return ParticleView{int(id_.size()), ptr(id_), ptr(type_), ptr(radius_), ptr(mass_), ptr(inertia_),
                            ptr(pos_), ptr(q_), ptr(vel_), ptr(omega_), ptr(force_), ptr(torque_),
                            extForce_.empty() ? nullptr : ptr(extForce_),
                            extTorque_.empty() ? nullptr : ptr(extTorque_)};
    }

    LawView lawView() const
    {
        return LawView{law_, ptr(pairCoeffs_), int(config_.materials.size()), ptr(typeMaterial_),
                       ptr(typeShape_), shapeTable_};
    }

    void setupLaw()
    {
        time0_ = time_;
        step0_ = step_;
        law_.law = config_.contact.law;
        law_.rolling = config_.contact.rolling;
        law_.normalStiffness = config_.contact.normalStiffness;
        law_.tangentialStiffnessRatio = config_.contact.tangentialStiffnessRatio;
        law_.volumetricStiffness = config_.contact.volumetricStiffness;
        law_.dt = config_.timeStep;

        const int nm = int(config_.materials.size());
        std::vector<PairCoefficients> pc(nm * nm);
        std::map<double, double> dampingOf;
        for (int a = 0; a < nm; ++a)
        {
            for (int b = 0; b < nm; ++b)
            {
                const Material& A = config_.materials[a];
                const Material& B = config_.materials[b];
                const PairProperties& pp = config_.pair(a, b);
                PairCoefficients& c = pc[a * nm + b];
                c.effectiveYoungs = 1.0 / ((1 - A.poissonsRatio * A.poissonsRatio) / A.youngsModulus
                                           + (1 - B.poissonsRatio * B.poissonsRatio) / B.youngsModulus);
                c.effectiveShear = 1.0 / (2 * (2 - A.poissonsRatio) * (1 + A.poissonsRatio) / A.youngsModulus
                                          + 2 * (2 - B.poissonsRatio) * (1 + B.poissonsRatio) / B.youngsModulus);
                auto it = dampingOf.find(pp.restitution);
                if (it == dampingOf.end())
                {
                    it = dampingOf.emplace(pp.restitution, dampingForRestitution(config_.contact.law, pp.restitution)).first;
                }
                c.damping = it->second;
                c.friction = pp.friction;
                c.rollingFriction = pp.rollingFriction;
                c.rollingDamping = pp.rollingDamping;
            }
        }
        toDevice(pairCoeffs_, pc);
        std::vector<int> tm, ts;
        for (const auto& t : config_.types)
        {
            tm.push_back(t.material);
            ts.push_back(t.shape == ShapeKind::polyhedron ? t.shapeIndex : -1);
        }
        toDevice(typeMaterial_, tm);
        toDevice(typeShape_, ts);
        uploadShapes();
    }

    //- The convex shapes live on the device once; particles only index them
    void uploadShapes()
    {
        const PackedPolyhedra packed = packPolyhedra(config_.shapes);
        toDevice(shapeVertexBegin_, packed.vertexBegin);
        toDevice(shapeFaceBegin_, packed.faceBegin);
        toDevice(shapeFaceStartBegin_, packed.faceStartBegin);
        toDevice(shapeFaceVertexBegin_, packed.faceVertexBegin);
        toDevice(shapeEdgeBegin_, packed.edgeBegin);
        toDevice(shapeBoundingRadius_, packed.boundingRadius);
        toDevice(shapeVolume_, packed.volume);
        toDevice(shapeInertia_, packed.inertiaPerDensity);
        toDevice(shapeVertices_, packed.vertices);
        toDevice(shapeFaceNormals_, packed.faceNormals);
        toDevice(shapeFaceOffsets_, packed.faceOffsets);
        toDevice(shapeFaceStart_, packed.faceStart);
        toDevice(shapeFaceVertex_, packed.faceVertex);
        toDevice(shapeEdges_, packed.edges);
        PolyhedronTable& t = shapeTable_;
        t.nShapes = packed.nShapes();
        auto p0 = [](auto& v) { return v.empty() ? nullptr : ptr(v); };
        t.vertexBegin = p0(shapeVertexBegin_);
        t.faceBegin = p0(shapeFaceBegin_);
        t.faceStartBegin = p0(shapeFaceStartBegin_);
        t.faceVertexBegin = p0(shapeFaceVertexBegin_);
        t.edgeBegin = p0(shapeEdgeBegin_);
        t.boundingRadius = p0(shapeBoundingRadius_);
        t.volume = p0(shapeVolume_);
        t.inertiaPerDensity = p0(shapeInertia_);
        t.vertices = p0(shapeVertices_);
        t.faceNormals = p0(shapeFaceNormals_);
        t.faceOffsets = p0(shapeFaceOffsets_);
        t.faceStart = p0(shapeFaceStart_);
        t.faceVertex = p0(shapeFaceVertex_);
        t.edges = p0(shapeEdges_);
    }

    static RigidMotion motionOf(const WallMotion& m)
    {
        RigidMotion r;
        r.kind = int(m.kind);
        r.velocity = m.velocity;
        r.origin = m.origin;
        r.axis = m.axis;
        r.omega = m.omega;
        return r;
    }

    void setupPlanes()
    {
        std::vector<PlaneDevice> pl;
        for (const auto& w : config_.planes)
        {
            pl.push_back(PlaneDevice{w.point, w.normal, w.material, motionOf(w.motion)});
        }
        toDevice(planes_, pl);
    }

    //- Bin every mesh's triangles (body frame) into a uniform grid whose cells
    //  list all triangles within the largest particle radius of the cell
    void setupMeshes()
    {
        if (config_.meshes.empty()) return;
        const auto radius = toHost(radius_);
        double rMax = 0;
        for (double r : radius) rMax = std::max(rMax, r);
        if (rMax <= 0) rMax = 1e-3;
        if (rMax <= meshBinnedRadius_) return;
        meshBinnedRadius_ = rMax * 1.25;  // room for later, larger inserts
        const double reach = meshBinnedRadius_;

        std::vector<MeshDevice> md;
        std::vector<Vec3> A, B, C;
        std::vector<int> cellStart, cellTri;
        for (const auto& w : config_.meshes)
        {
            const TriangleMesh& mesh = w.mesh;
            Vec3 lo(1e300, 1e300, 1e300), hi(-1e300, -1e300, -1e300);
            for (const auto& p : mesh.points)
            {
                for (int d = 0; d < 3; ++d)
                {
                    lo[d] = std::min(lo[d], p[d]);
                    hi[d] = std::max(hi[d], p[d]);
                }
            }
            for (int d = 0; d < 3; ++d)
            {
                lo[d] -= 2 * reach;
                hi[d] += 2 * reach;
            }
            const Vec3 ext = hi - lo;
            // Cells about a particle diameter, at most ~4M cells
            double h = 2 * reach;
            const double vol = ext.x * ext.y * ext.z;
            h = std::max(h, std::cbrt(vol / 4.0e6));
            MeshDevice m;
            m.material = w.material;
            m.motion = motionOf(w.motion);
            m.firstTriangle = int(A.size());
            m.gridOrigin = lo;
            m.cellSize = h;
            m.nx = std::max(1, int(std::ceil(ext.x / h)));
            m.ny = std::max(1, int(std::ceil(ext.y / h)));
            m.nz = std::max(1, int(std::ceil(ext.z / h)));
            m.firstCell = int(cellStart.size());

            const size_t nCells = size_t(m.nx) * m.ny * m.nz;
            std::vector<std::vector<int>> bins(nCells);
            for (size_t t = 0; t < mesh.triangles.size(); ++t)
            {
                const Vec3 a = mesh.points[mesh.triangles[t][0]];
                const Vec3 b = mesh.points[mesh.triangles[t][1]];
                const Vec3 c = mesh.points[mesh.triangles[t][2]];
                A.push_back(a);
                B.push_back(b);
                C.push_back(c);
                int i0[3], i1[3];
                for (int d = 0; d < 3; ++d)
                {
                    const double mn = std::min({a[d], b[d], c[d]}) - reach;
                    const double mx = std::max({a[d], b[d], c[d]}) + reach;
                    const int nd = d == 0 ? m.nx : (d == 1 ? m.ny : m.nz);
                    i0[d] = std::max(0, int(std::floor((mn - lo[d]) / h)));
                    i1[d] = std::min(nd - 1, int(std::floor((mx - lo[d]) / h)));
                }
                for (int z = i0[2]; z <= i1[2]; ++z)
                    for (int y = i0[1]; y <= i1[1]; ++y)
                        for (int x = i0[0]; x <= i1[0]; ++x)
                        {
                            // Only cells the triangle's reach really touches:
                            // distance from the cell centre <= reach + half diagonal
                            const Vec3 cc = lo + Vec3((x + 0.5) * h, (y + 0.5) * h, (z + 0.5) * h);
                            int f;
                            const Vec3 cp = detail::closestPointOnTriangle(cc, a, b, c, f);
                            if (norm(cp - cc) <= reach + 0.8660254037844387 * h)
                            {
                                bins[(size_t(z) * m.ny + y) * m.nx + x].push_back(int(t));
                            }
                        }
            }
            for (size_t c = 0; c < nCells; ++c)
            {
                cellStart.push_back(int(cellTri.size()));
                cellTri.insert(cellTri.end(), bins[c].begin(), bins[c].end());
            }
            cellStart.push_back(int(cellTri.size()));
            md.push_back(m);
        }
        toDevice(meshes_, md);
        toDevice(triA_, A);
        toDevice(triB_, B);
        toDevice(triC_, C);
        toDevice(meshCellStart_, cellStart);
        toDevice(meshCellTri_, cellTri);
    }

    void uploadParticles(const ParticleState& p, bool resetWallHistory = true)
    {
        toDevice(id_, p.id);
        toDevice(type_, p.type);
        toDevice(radius_, p.radius);
        toDevice(mass_, p.mass);
        toDevice(inertia_, p.inertia);
        toDevice(pos_, p.position);
        toDevice(q_, p.orientation);
        toDevice(vel_, p.velocity);
        toDevice(omega_, p.omega);
        std::vector<Vec3> f = p.force, t = p.torque;
        f.resize(p.size());
        t.resize(p.size());
        toDevice(force_, f);
        toDevice(torque_, t);
        (void)resetWallHistory;
        double rMax = 0;
        for (double r : p.radius) rMax = std::max(rMax, r);
        rMax_ = std::max(rMax_, rMax);
    }

    double skin() const { return config_.skinFraction * 2 * rMax_; }

    template<class T>
    static void permute(dvec<T>& v, const dvec<int>& perm)
    {
        dvec<T> out(perm.size());
        thrust::gather(thrust::device, perm.begin(), perm.end(), v.begin(), out.begin());
        v.swap(out);
    }

    //- Remove particles that left the domain, sort by cell, rebuild the
    //  neighbour lists and carry the springs over. With moved = false the
    //  stored reference positions are used as they are (restart).
    void rebuild(bool moved)
    {
        ++builds_;
        const int oldN = int(id_.size());
        if (moved)
        {
            ref_ = pos_;
        }
        const auto first = thrust::counting_iterator<int>(0);

        // Keep the particles inside the domain
        dvec<int> perm(oldN);
        auto endIt = thrust::copy_if(thrust::device, first, first + oldN, perm.begin(),
                                     InsideDomain{ptr(ref_), config_.domainMin, config_.domainMax});
        const int n = int(endIt - perm.begin());
        perm.resize(n);

        // Sort by cell (stable: ties keep their order, so a restart that starts
        // from a sorted state keeps it)
        Grid grid;
        grid.cellSize = 2 * rMax_ + skin();
        unsigned table = 1024;
        while (table < 2u * unsigned(std::max(n, 1))) table <<= 1;
        grid.tableMask = table - 1;
        dvec<unsigned> keys(n);
        thrust::transform(thrust::device, perm.begin(), perm.end(), keys.begin(), CellKey{grid, ptr(ref_)});
        thrust::stable_sort_by_key(thrust::device, keys.begin(), keys.end(), perm.begin());

        // Old neighbour data, indexed by old particle index
        dvec<int> oldCount;
        oldCount.swap(nbrCount_);
        dvec<int64_t> oldPartner;
        oldPartner.swap(pairPartner_);
        dvec<Vec3> oldXi, oldMr;
        oldXi.swap(pairXi_);
        oldMr.swap(pairMr_);
        const int oldMax = maxNbr_;
        const int oldListN = int(oldCount.size());

        // Wall springs follow their particle
        const int nPl = int(config_.planes.size());
        std::vector<int> permHost;
        if (nPl > 0 || !config_.meshes.empty())
        {
            permHost = toHost(perm);
        }
        if (nPl > 0)
        {
            planeXi_.resize(size_t(oldN) * nPl);
            planeMr_.resize(size_t(oldN) * nPl);
            std::vector<int> slotPerm(size_t(n) * nPl);
            for (int i = 0; i < n; ++i)
                for (int w = 0; w < nPl; ++w) slotPerm[size_t(i) * nPl + w] = permHost[i] * nPl + w;
            dvec<int> sp;
            toDevice(sp, slotPerm);
            permute(planeXi_, sp);
            permute(planeMr_, sp);
        }
        if (!config_.meshes.empty())
        {
            MeshSlot empty{};
            empty.mesh = -1;
            meshSlots_.resize(size_t(oldN) * maxMeshSlots, empty);
            std::vector<int> slotPerm(size_t(n) * maxMeshSlots);
            for (int i = 0; i < n; ++i)
                for (int k = 0; k < maxMeshSlots; ++k)
                    slotPerm[size_t(i) * maxMeshSlots + k] = permHost[i] * maxMeshSlots + k;
            dvec<int> sp;
            toDevice(sp, slotPerm);
            permute(meshSlots_, sp);
        }

        permute(id_, perm);
        permute(type_, perm);
        permute(radius_, perm);
        permute(mass_, perm);
        permute(inertia_, perm);
        permute(pos_, perm);
        permute(q_, perm);
        permute(vel_, perm);
        permute(omega_, perm);
        permute(force_, perm);
        permute(torque_, perm);
        permute(ref_, perm);
        if (!extForce_.empty()) permute(extForce_, perm);
        if (!extTorque_.empty()) permute(extTorque_, perm);

        // Cell ranges
        dvec<int> cellStart(table, -1), cellEnd(table, -1);
        thrust::for_each(thrust::device, first, first + n,
                         MarkCellRanges{ptr(keys), n, ptr(cellStart), ptr(cellEnd)});

        // Count, size, fill
        nbrCount_.assign(n, 0);
        nbrOwned_.assign(n, 0);
        BuildNeighbours build{grid, ptr(ref_), ptr(radius_), ptr(id_), ptr(cellStart), ptr(cellEnd), skin(),
                              ptr(nbrCount_), ptr(nbrOwned_), nullptr, 0};
        thrust::for_each(thrust::device, first, first + n, build);
        const int maxCount = n > 0 ? thrust::reduce(thrust::device, nbrCount_.begin(), nbrCount_.end(), 0,
                                                    thrust::maximum<int>()) : 0;
        maxNbr_ = std::max(1, maxCount);
        nbr_.assign(size_t(n) * maxNbr_, -1);
        build.out = ptr(nbr_);
        build.maxNbr = maxNbr_;
        thrust::for_each(thrust::device, first, first + n, build);

        pairPartner_.assign(size_t(n) * maxNbr_, -1);
        slotTouching_.assign(size_t(n) * maxNbr_, 0);
        pairXi_.assign(size_t(n) * maxNbr_, Vec3());
        pairMr_.assign(size_t(n) * maxNbr_, Vec3());
        if (oldMax > 0 && !oldCount.empty())
        {
            TransferPairHistory transfer{ptr(perm), oldListN, ptr(nbrCount_), ptr(nbr_), maxNbr_, ptr(id_),
                                         ptr(oldCount), ptr(oldPartner), ptr(oldXi), ptr(oldMr), oldMax,
                                         ptr(pairPartner_), ptr(pairXi_), ptr(pairMr_), ptr(slotTouching_)};
            thrust::for_each(thrust::device, first, first + n, transfer);
        }
        else
        {
            TransferPairHistory transfer{ptr(perm), 0, ptr(nbrCount_), ptr(nbr_), maxNbr_, ptr(id_),
                                         nullptr, nullptr, nullptr, nullptr, 0,
                                         ptr(pairPartner_), ptr(pairXi_), ptr(pairMr_), ptr(slotTouching_)};
            thrust::for_each(thrust::device, first, first + n, transfer);
        }

        if (size_t(n) * maxNbr_ > size_t(2147483647))
        {
            throw Error("neighbour lists exceed 2^31 slots: too many particles or neighbours per particle");
        }
        mirrorSlot_.assign(size_t(n) * maxNbr_, 0);
        thrust::for_each(thrust::device, first, first + n,
                         LinkMirrorSlots{ptr(nbrOwned_), ptr(nbrCount_), ptr(nbr_), maxNbr_, ptr(mirrorSlot_)});
        slotForce_.resize(size_t(n) * maxNbr_);
        slotTorque_.resize(size_t(n) * maxNbr_);

        contactCount_.assign(n, 0);
        wallContactCount_.assign(n, 0);
        if (nPl > 0)
        {
            planeXi_.resize(size_t(n) * nPl);
            planeMr_.resize(size_t(n) * nPl);
        }
    }

    //- Put the springs of a snapshot into the freshly built lists
    void restoreHistory(const Snapshot& s)
    {
        const int n = int(id_.size());
        const auto ids = toHost(id_);
        std::map<int64_t, int> indexOf;
        for (int i = 0; i < n; ++i) indexOf[ids[i]] = i;

        if (!s.pairs.empty())
        {
            std::map<std::pair<int64_t, int64_t>, const PairHistory*> hist;
            for (const auto& h : s.pairs) hist[{h.idA, h.idB}] = &h;
            const auto cnt = toHost(nbrCount_);
            const auto nb = toHost(nbr_);
            auto xi = toHost(pairXi_);
            auto mr = toHost(pairMr_);
            auto touching = toHost(slotTouching_);
            for (int i = 0; i < n; ++i)
                for (int k = 0; k < cnt[i]; ++k)
                {
                    const size_t sl = size_t(i) * maxNbr_ + k;
                    const int64_t a = std::min(ids[i], ids[nb[sl]]), b = std::max(ids[i], ids[nb[sl]]);
                    auto it = hist.find({a, b});
                    if (it != hist.end() && ids[i] < ids[nb[sl]])
                    {
                        xi[sl] = it->second->tangential;
                        mr[sl] = it->second->rolling;
                        touching[sl] = 1;
                    }
                }
            toDevice(pairXi_, xi);
            toDevice(pairMr_, mr);
            toDevice(slotTouching_, touching);
        }

        const int nPl = int(config_.planes.size());
        std::vector<Vec3> pxi(size_t(n) * nPl), pmr(size_t(n) * nPl);
        MeshSlot empty{};
        empty.mesh = -1;
        std::vector<MeshSlot> slots(config_.meshes.empty() ? 0 : size_t(n) * maxMeshSlots, empty);
        std::vector<int> used(n, 0);
        for (const auto& w : s.walls)
        {
            auto it = indexOf.find(w.id);
            if (it == indexOf.end()) continue;
            const int i = it->second;
            if (w.wall < nPl)
            {
                pxi[size_t(i) * nPl + w.wall] = w.tangential;
                pmr[size_t(i) * nPl + w.wall] = w.rolling;
            }
            else if (!slots.empty() && used[i] < maxMeshSlots)
            {
                MeshSlot& ms = slots[size_t(i) * maxMeshSlots + used[i]++];
                ms.mesh = w.wall - nPl;
                ms.triangle = w.triangle;
                ms.normal = w.normal;
                ms.xi = w.tangential;
                ms.mr = w.rolling;
            }
        }
        toDevice(planeXi_, pxi);
        toDevice(planeMr_, pmr);
        toDevice(meshSlots_, slots);
    }

    void computeForces()
    {
        const int n = int(id_.size());
        if (n == 0) return;
        contactCount_.resize(n);
        wallContactCount_.resize(n);
        const int nPl = int(config_.planes.size());
        ForceKernel k;
        k.p = view();
        k.law = lawView();
        k.gravity = config_.gravity;
        k.time = time_;
        const auto first = thrust::counting_iterator<int>(0);
        PairKernel pk{k.p, k.law, ptr(nbrOwned_), ptr(nbr_), maxNbr_, ptr(mirrorSlot_), ptr(pairXi_), ptr(pairMr_),
                      ptr(slotTouching_), ptr(slotForce_), ptr(slotTorque_)};
#ifdef __CUDACC__
        if (int64_t(n) * maxNbr_ < int64_t(std::numeric_limits<int>::max()))
        {
            thrust::for_each(thrust::device, first, first + n * maxNbr_, PairSlotKernel{pk});
        }
        else
#endif
        {
            thrust::for_each(thrust::device, first, first + n, pk);
        }
        k.nbrCount = ptr(nbrCount_);
        k.maxNbr = maxNbr_;
        k.slotTouching = ptr(slotTouching_);
        k.slotForce = ptr(slotForce_);
        k.slotTorque = ptr(slotTorque_);
        k.contactCount = ptr(contactCount_);
        k.planes = nPl ? ptr(planes_) : nullptr;
        k.nPlanes = nPl;
        k.planeXi = nPl ? ptr(planeXi_) : nullptr;
        k.planeMr = nPl ? ptr(planeMr_) : nullptr;
        const int nMesh = int(config_.meshes.size());
        k.meshes = nMesh ? ptr(meshes_) : nullptr;
        k.nMeshes = nMesh;
        k.triA = nMesh ? ptr(triA_) : nullptr;
        k.triB = nMesh ? ptr(triB_) : nullptr;
        k.triC = nMesh ? ptr(triC_) : nullptr;
        k.cellStart = nMesh ? ptr(meshCellStart_) : nullptr;
        k.cellTriangles = nMesh && !meshCellTri_.empty() ? ptr(meshCellTri_) : nullptr;
        k.meshSlots = nMesh ? ptr(meshSlots_) : nullptr;
        k.wallContactCount = ptr(wallContactCount_);
        thrust::for_each(thrust::device, first, first + n, k);
    }

    //- Elastic energy of the normal springs (host side: a diagnostic, not hot)
    double elasticEnergy() const
    {
        const auto pos = toHost(pos_);
        const auto rad = toHost(radius_);
        const auto ids = toHost(id_);
        const auto cnt = toHost(nbrCount_);
        const auto nb = toHost(nbr_);
        const auto type = toHost(type_);
        const auto q = toHost(q_);
        const auto pc = toHost(pairCoeffs_);
        const int nm = int(config_.materials.size());
        auto coeff = [&](int ma, int mb) { return pc[ma * nm + mb]; };
        const bool volumetric = law_.law == ContactLaw::overlapVolume;
        const PackedPolyhedra packed = packPolyhedra(config_.shapes);
        const PolyhedronTable table = packed.table();
        auto shapeOf = [&](int i) {
            const ParticleType& t = config_.types[type[i]];
            return t.shape == ShapeKind::polyhedron ? t.shapeIndex : -1;
        };
        double e = 0;
        const int n = int(ids.size());
        for (int i = 0; i < n; ++i)
        {
            const int mi = config_.types[type[i]].material;
            for (int k = 0; k < cnt[i]; ++k)
            {
                const int j = nb[size_t(i) * maxNbr_ + k];
                if (ids[i] > ids[j]) continue;
                const int mj = config_.types[type[j]].material;
                if (volumetric)
                {
                    // Exact for flat (face-face) contacts, V = A d: W = Kn V^2 / (2 A)
                    const int si = shapeOf(i), sj = shapeOf(j);
                    OverlapResult ov;
                    if (si < 0 && sj < 0) ov = sphereSphereOverlap(pos[i], rad[i], pos[j], rad[j]);
                    else if (si >= 0 && sj >= 0)
                        ov = polyhedronOverlap(table.shape(si), pos[i], q[i], table.shape(sj), pos[j], q[j]);
                    else if (si >= 0) ov = polyhedronSphereOverlap(table.shape(si), pos[i], q[i], pos[j], rad[j]);
                    else ov = polyhedronSphereOverlap(table.shape(sj), pos[j], q[j], pos[i], rad[i]);
                    if (ov.touching && ov.contactArea > 0)
                    {
                        e += 0.5 * law_.volumetricStiffness * ov.volume * ov.volume / ov.contactArea;
                    }
                    continue;
                }
                const double d = rad[i] + rad[j] - norm(pos[j] - pos[i]);
                if (d <= 0) continue;
                e += normalElasticEnergy(law_, coeff(mi, mj), rad[i] * rad[j] / (rad[i] + rad[j]), d);
            }
            for (const auto& w : config_.planes)
            {
                detail::RigidMotion m = motionOf(w.motion);
                const Quaternion R = m.rotationAt(time_);
                const Vec3 nrm = m.directionToWorld(w.normal, R);
                const Vec3 p0 = m.toWorld(w.point, time_, R);
                const double h = dot(pos[i] - p0, nrm);
                if (h >= rad[i]) continue;
                if (volumetric)
                {
                    // Exact: Kn times the first moment of the overlap about the plane
                    const int si = shapeOf(i);
                    const OverlapResult ov = si >= 0
                        ? polyhedronPlaneOverlap(table.shape(si), pos[i], q[i], p0, nrm)
                        : sphereHalfSpaceOverlap(pos[i], rad[i], pos[i] - h * nrm, nrm);
                    if (ov.touching)
                    {
                        e += law_.volumetricStiffness * ov.volume * dot(p0 - ov.centroid, nrm);
                    }
                    continue;
                }
                e += normalElasticEnergy(law_, coeff(mi, w.material), rad[i], rad[i] - h);
            }
        }
        return e;
    }

    SimulationConfig config_;
    double time_ = 0, time0_ = 0;
    int64_t step_ = 0, step0_ = 0;
    LawParameters law_;
    double rMax_ = 0;
    double meshBinnedRadius_ = 0;
    size_t builds_ = 0;

    dvec<int64_t> id_;
    dvec<int> type_;
    dvec<double> radius_, mass_;
    dvec<Vec3> inertia_, pos_, vel_, omega_, force_, torque_, ref_, extForce_, extTorque_;
    dvec<Quaternion> q_;

    dvec<PairCoefficients> pairCoeffs_;
    dvec<int> typeMaterial_, typeShape_;

    dvec<int> shapeVertexBegin_, shapeFaceBegin_, shapeFaceStartBegin_, shapeFaceVertexBegin_, shapeEdgeBegin_;
    dvec<double> shapeBoundingRadius_, shapeVolume_, shapeFaceOffsets_;
    dvec<Vec3> shapeInertia_, shapeVertices_, shapeFaceNormals_;
    dvec<int> shapeFaceStart_, shapeFaceVertex_;
    dvec<PolyhedronEdge> shapeEdges_;
    PolyhedronTable shapeTable_;

    int maxNbr_ = 0;
    dvec<int> nbrCount_, nbrOwned_, nbr_, contactCount_, wallContactCount_;
    dvec<int64_t> pairPartner_;
    dvec<Vec3> pairXi_, pairMr_;
    dvec<int> mirrorSlot_;
    dvec<unsigned char> slotTouching_;
    dvec<Vec3> slotForce_, slotTorque_;

    dvec<PlaneDevice> planes_;
    dvec<Vec3> planeXi_, planeMr_;

    dvec<MeshDevice> meshes_;
    dvec<Vec3> triA_, triB_, triC_;
    dvec<int> meshCellStart_, meshCellTri_;
    dvec<MeshSlot> meshSlots_;
};

} // namespace PD_BACKEND_NS
} // namespace polydem

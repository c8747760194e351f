// polyDEM engine: broad phase (uniform grid, particles sorted by a locality-preserving
// cell key) and neighbour lists.
// Part of ThrustEngine.inl: compiled once per back end inside
// namespace polydem::PD_BACKEND_NS (defined by the including back end).
#pragma once

#include "DeviceViews.hpp"

namespace polydem
{
namespace PD_BACKEND_NS
{

//- Uniform grid of cubic cells (cell = largest diameter + skin). A cell's key
//  is its linear index in the bounding box of the particles' reference
//  positions, x fastest (dx + nx (dy + ny dz), the indices taken from the
//  cell of the box's lower corner), modulo the power-of-two table: cells near
//  in space get keys near in the sorted order, so after the sort a particle's
//  partners lie near it in memory (cells along x are consecutive; the 27-cell
//  walk reads 9 runs of up to 3 consecutive cells). When the box holds more
//  cells than the table, or for a cell outside the box (a neighbour of a
//  boundary cell), the index wraps: different cells then share a key (a
//  collision), which the neighbour search filters.
struct Grid
{
    double cellSize;
    unsigned tableMask;
    int64_t ox = 0, oy = 0, oz = 0;   //!< cell of the box's lower corner
    uint64_t nx = 1, ny = 1;          //!< cells of the box along x, y

    PD_HD void cellOf(const Vec3& x, int64_t& ix, int64_t& iy, int64_t& iz) const
    {
        ix = int64_t(floor(x.x / cellSize));
        iy = int64_t(floor(x.y / cellSize));
        iz = int64_t(floor(x.z / cellSize));
    }

    PD_HD unsigned key(int64_t ix, int64_t iy, int64_t iz) const
    {
        // Unsigned arithmetic: wraps (defined) outside the box and for
        // unbounded domains alike
        const uint64_t dx = uint64_t(ix) - uint64_t(ox);
        const uint64_t dy = uint64_t(iy) - uint64_t(oy);
        const uint64_t dz = uint64_t(iz) - uint64_t(oz);
        return unsigned(dx + nx * (dy + ny * dz)) & tableMask;
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
        return grid.key(ix, iy, iz);
    }
};

//- Bounding box of the reference positions of the particles listed (reduction)
struct Box
{
    Vec3 lo, hi;
};

struct BoxOf
{
    const Vec3* ref;
    PD_HD Box operator()(int i) const { return Box{ref[i], ref[i]}; }
};

struct MergeBoxes
{
    PD_HD static double lower(double a, double b) { return a < b ? a : b; }
    PD_HD static double upper(double a, double b) { return a < b ? b : a; }
    PD_HD Box operator()(const Box& a, const Box& b) const
    {
        return Box{Vec3(lower(a.lo.x, b.lo.x), lower(a.lo.y, b.lo.y), lower(a.lo.z, b.lo.z)),
                   Vec3(upper(a.hi.x, b.hi.x), upper(a.hi.y, b.hi.y), upper(a.hi.z, b.hi.z))};
    }
};

//- Particle i is kept: inside the domain box and in none of the outlet boxes
struct InsideDomain
{
    const Vec3* ref;
    Vec3 lo, hi;
    const Vec3* outletLo = nullptr;   //!< nOutlets boxes
    const Vec3* outletHi = nullptr;
    int nOutlets = 0;

    PD_HD static bool inBox(const Vec3& x, const Vec3& a, const Vec3& b)
    {
        return x.x >= a.x && x.x <= b.x && x.y >= a.y && x.y <= b.y && x.z >= a.z && x.z <= b.z;
    }

    PD_HD bool operator()(int i) const
    {
        const Vec3 x = ref[i];
        if (!inBox(x, lo, hi)) return false;
        for (int k = 0; k < nOutlets; ++k)
        {
            if (inBox(x, outletLo[k], outletHi[k])) return false;
        }
        return true;
    }
};

//- Particle i is removed (the complement of InsideDomain)
struct OutsideDomain
{
    InsideDomain inside;

    PD_HD bool operator()(int i) const { return !inside(i); }
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

//- Half neighbour list in CSR form: particle i lists the partners j > i (in
//  the cell-sorted order) within reach + skin, so each pair appears once and
//  i is its body 1. With `out` null it only counts.
//  A hash collision can bring a particle of another cell into the range: it is
//  skipped unless it really lies in the cell being scanned, so nobody is listed twice.
struct BuildNeighbours
{
    Grid grid;
    const Vec3* ref;
    const double* radius;
    const int* cellStart;
    const int* cellEnd;
    double skin;
    int* count;        //!< counting pass: pairs of i
    const int* start;  //!< filling pass: first pair of i
    int* out;          //!< null for the counting pass
    int* owner;        //!< filling pass: body 1 of each pair

    PD_HD void operator()(int i) const
    {
        int64_t cx, cy, cz;
        const Vec3 xi = ref[i];
        const double ri = radius[i];
        grid.cellOf(xi, cx, cy, cz);
        int c = out ? start[i] : 0;
        for (int dz = -1; dz <= 1; ++dz)
        for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
        {
            const int64_t ix = cx + dx, iy = cy + dy, iz = cz + dz;
            const unsigned h = grid.key(ix, iy, iz);
            const int first = cellStart[h];
            if (first < 0) continue;
            const int end = cellEnd[h];
            for (int j = first > i ? first : i + 1; j < end; ++j)
            {
                const Vec3 xj = ref[j];
                const double reach = ri + radius[j] + skin;
                if (normSqr(xj - xi) >= reach * reach) continue;
                int64_t jx, jy, jz;
                grid.cellOf(xj, jx, jy, jz);
                if (jx != ix || jy != iy || jz != iz) continue;
                if (out)
                {
                    out[c] = j;
                    owner[c] = i;
                }
                ++c;
            }
        }
        if (!out) count[i] = c;
    }
};

//- Key of a pair for carrying its history over a rebuild: (smaller id, larger id)
struct PairKey
{
    int64_t lo, hi;
};

//- Old pairs that hold a spring, keyed by id, with the springs as seen from
//  the particle of smaller id (body 1 may change when the order changes;
//  negating a spring is exact)
struct OldPairKeys
{
    const int* owner;
    const int* partner;
    const int64_t* id;
    const Vec3* xi;
    const Vec3* mr;   //!< null without rolling history
    const Vec3* axis; //!< contact normals of polyhedron pairs; null without
    int64_t* keyLo;
    int64_t* keyHi;
    Vec3* canonXi;
    Vec3* canonMr;
    Vec3* canonAxis;

    PD_HD void operator()(int k) const
    {
        const int64_t a = id[owner[k]], b = id[partner[k]];
        const double sign = a < b ? 1.0 : -1.0;
        keyLo[k] = a < b ? a : b;
        keyHi[k] = a < b ? b : a;
        canonXi[k] = sign * xi[k];
        canonMr[k] = mr ? sign * mr[k] : Vec3();
        canonAxis[k] = axis ? sign * axis[k] : Vec3();
    }
};

struct HasHistory
{
    const unsigned char* touching;
    PD_HD bool operator()(int k) const { return touching[k] != 0; }
};

//- Sort-merge of the history: each new pair looks its key up (binary search)
//  in the old pairs that held a spring, sorted by key
struct TransferPairHistory
{
    const int* owner;
    const int* partner;
    const int64_t* id;      //!< ids in the new order
    const int64_t* oldLo;
    const int64_t* oldHi;
    const Vec3* oldXi;
    const Vec3* oldMr;
    const Vec3* oldAxis;    //!< null without polyhedra
    int nOld;
    Vec3* xi;
    Vec3* mr;               //!< null without rolling history
    Vec3* axis;             //!< contact normals (PairLists::separatingAxis); null without polyhedra
    unsigned char* touching;

    PD_HD void operator()(int k) const
    {
        const int64_t a = id[owner[k]], b = id[partner[k]];
        const int64_t lo = a < b ? a : b, hi = a < b ? b : a;
        int first = 0, count = nOld;
        while (count > 0)
        {
            const int step = count / 2, m = first + step;
            if (oldLo[m] < lo || (oldLo[m] == lo && oldHi[m] < hi))
            {
                first = m + 1;
                count -= step + 1;
            }
            else
            {
                count = step;
            }
        }
        const bool found = first < nOld && oldLo[first] == lo && oldHi[first] == hi;
        const double sign = a < b ? 1.0 : -1.0;
        xi[k] = found ? sign * oldXi[first] : Vec3();
        if (mr) mr[k] = found ? sign * oldMr[first] : Vec3();
        if (axis) axis[k] = found ? sign * oldAxis[first] : Vec3();
        touching[k] = found ? 1 : 0;
    }
};

//- Plane-wall candidates of a particle: every moving plane, and every fixed
//  plane within its radius plus the skin (a particle moves less than half the
//  skin between rebuilds). With `out` null it only counts.
struct BuildPlaneCandidates
{
    const Vec3* ref;
    const double* radius;
    const PlaneDevice* planes;
    int nPlanes;
    double skin;
    int* count;
    const int* start;
    int* out;

    PD_HD void operator()(int i) const
    {
        int c = out ? start[i] : 0;
        for (int w = 0; w < nPlanes; ++w)
        {
            const PlaneDevice& pl = planes[w];
            const bool near = pl.motion.kind != int(MotionKind::fixed)
                           || dot(ref[i] - pl.point, pl.normal) < radius[i] + skin;
            if (!near) continue;
            if (out) out[c] = w;
            ++c;
        }
        if (!out) count[i] = c;
    }
};

//- Wall springs follow their particle: looked up in the particle's old candidates
struct TransferPlaneHistory
{
    const int* perm;          //!< new index -> old index
    int oldN;                 //!< particles the old candidate lists cover
    const int* oldStart;
    const int* oldPlane;
    const Vec3* oldXi;
    const Vec3* oldMr;        //!< null without rolling history
    const int* start;
    const int* plane;
    Vec3* xi;
    Vec3* mr;

    PD_HD void operator()(int i) const
    {
        const int o = perm[i];
        const int b0 = (oldStart && o < oldN) ? oldStart[o] : 0;
        const int b1 = (oldStart && o < oldN) ? oldStart[o + 1] : 0;
        for (int c = start[i]; c < start[i + 1]; ++c)
        {
            Vec3 x, m;
            for (int l = b0; l < b1; ++l)
            {
                if (oldPlane[l] == plane[c])
                {
                    x = oldXi[l];
                    if (oldMr) m = oldMr[l];
                    break;
                }
            }
            xi[c] = x;
            if (mr) mr[c] = m;
        }
    }
};

//- Index map for permuting per-particle blocks of `block` entries
struct BlockPermutation
{
    const int* perm;
    int block;

    PD_HD int operator()(int s) const
    {
        const int i = s / block;
        return perm[i] * block + (s - i * block);
    }
};

} // namespace PD_BACKEND_NS
} // namespace polydem

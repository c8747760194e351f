// polyDEM: overlaps of listed particles at insertion (see InsertionChecks.hpp).
#include "polyDEM/InsertionChecks.hpp"

#include "polyDEM/MeshQueries.hpp"
#include "polyDEM/PolyhedronOverlap.hpp"
#include "polyDEM/WallDepths.hpp"
#include "polyDEM/WallSidePlanes.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <unordered_map>

namespace polydem
{

namespace
{

const double pi = 3.14159265358979323846;

//- One particle as the checks see it (inserted or present)
struct Body
{
    Vec3 x;
    Quaternion q;
    double r = 0;        //!< sphere radius, or the polyhedron's bounding radius
    double volume = 0;
    const ConvexShape* shape = nullptr;   //!< null for a sphere
};

Body bodyOf(const SimulationConfig& config, const ParticleState& p, std::size_t i)
{
    Body b;
    b.x = p.position[i];
    b.q = p.orientation[i];
    b.r = p.radius[i];
    const ParticleType& t = config.types.at(p.type[i]);
    if (t.shape == ShapeKind::polyhedron)
    {
        b.shape = &config.shapes.at(t.shapeIndex);
        b.volume = b.shape->volume;
        b.r = b.shape->boundingRadius;
    }
    else
    {
        b.volume = 4.0 / 3.0 * pi * b.r * b.r * b.r;
    }
    return b;
}

//- The overlap of two bodies beyond the tolerances: measure > 0, else 0
double pairMeasure(const Body& a, const Body& b, bool& byVolume)
{
    const double dist = norm(b.x - a.x);
    byVolume = false;
    if (dist >= a.r + b.r)
    {
        return 0;
    }
    if (!a.shape && !b.shape)
    {
        const double m = (a.r + b.r - dist) / (2 * std::min(a.r, b.r));
        return m > kInsertionDepthTolerance ? m : 0;
    }
    byVolume = true;
    OverlapResult o;
    if (a.shape && b.shape)
    {
        o = polyhedronOverlap(a.shape->view(), a.x, a.q, b.shape->view(), b.x, b.q);
    }
    else if (a.shape)
    {
        o = polyhedronSphereOverlap(a.shape->view(), a.x, a.q, b.x, b.r);
    }
    else
    {
        o = polyhedronSphereOverlap(b.shape->view(), b.x, b.q, a.x, a.r);
    }
    if (!o.touching)
    {
        return 0;
    }
    const double m = o.volume / std::min(a.volume, b.volume);
    return m > kInsertionVolumeTolerance ? m : 0;
}

//- Buckets of a uniform grid of cell size h
struct Grid
{
    double h;
    std::unordered_map<std::int64_t, std::vector<std::size_t>> cells;

    std::int64_t key(long i, long j, long k) const
    {
        // 21 bits per axis, wrapped: collisions only add candidates
        const std::int64_t m = (1 << 21) - 1;
        return ((std::int64_t(i) & m) << 42) | ((std::int64_t(j) & m) << 21) | (std::int64_t(k) & m);
    }
    long index(double v) const { return long(std::floor(v / h)); }

    void add(const Vec3& x, std::size_t i)
    {
        cells[key(index(x.x), index(x.y), index(x.z))].push_back(i);
    }

    template<class Visit>
    void near(const Vec3& x, const Visit& visit) const
    {
        const long ci = index(x.x), cj = index(x.y), ck = index(x.z);
        for (long i = ci - 1; i <= ci + 1; ++i)
            for (long j = cj - 1; j <= cj + 1; ++j)
                for (long k = ck - 1; k <= ck + 1; ++k)
                {
                    const auto it = cells.find(key(i, j, k));
                    if (it != cells.end())
                    {
                        for (const std::size_t n : it->second) visit(n);
                    }
                }
    }
};

} // namespace


std::vector<InsertionOverlap> insertionOverlaps
(
    const SimulationConfig& config,
    const ParticleState& inserted,
    const ParticleState& present,
    bool atStart
)
{
    std::vector<InsertionOverlap> found;
    std::vector<Body> ins(inserted.size()), pre(present.size());
    double rMax = 0;
    for (std::size_t i = 0; i < ins.size(); ++i)
    {
        ins[i] = bodyOf(config, inserted, i);
        rMax = std::max(rMax, ins[i].r);
    }
    for (std::size_t i = 0; i < pre.size(); ++i)
    {
        pre[i] = bodyOf(config, present, i);
        rMax = std::max(rMax, pre[i].r);
    }
    if (ins.empty() || !(rMax > 0))
    {
        return found;
    }

    // Any two bodies that can touch are in neighbouring cells of size 2 rMax
    Grid insGrid{2 * rMax, {}}, preGrid{2 * rMax, {}};
    for (std::size_t i = 0; i < ins.size(); ++i) insGrid.add(ins[i].x, i);
    for (std::size_t i = 0; i < pre.size(); ++i) preGrid.add(pre[i].x, i);

    // Mesh walls: each triangle in the cells its bounding box covers, on
    // the finest of a hierarchy of grids (cell sizes 2 rMax 4^L) on which
    // it spans at most 4^3 cells; a triangle within r <= rMax of a centre
    // is then in one of the centre's 27 cells on its level
    const int nLevels = 16;
    std::vector<std::vector<Grid>> triGrids(config.meshes.size());
    std::vector<std::vector<std::size_t>> seen(config.meshes.size());
    // How deep each triangle's wall solid reaches (as the engine's: floors
    // no deeper than four reaches of 1.25 rMax), for the triangles visited only
    std::vector<std::unique_ptr<WallDepths>> depths(config.meshes.size());
    auto depthOf = [&](std::size_t mw, std::size_t t)
    {
        const MeshWall& w = config.meshes[mw];
        if (w.wallDepth.size() == w.mesh.size()) return w.wallDepth[t];
        if (!depths[mw]) depths[mw].reset(new WallDepths(w.mesh, 5 * rMax));
        return (*depths[mw])(t);
    };
    // Each triangle's side planes (as the engine's), for meshes a polyhedron meets
    std::vector<WallSidePlanes> sides(config.meshes.size());
    auto sidesOf = [&](std::size_t mw) -> const WallSidePlanes&
    {
        if (sides[mw].start.empty()) sides[mw] = wallSidePlanes(config.meshes[mw].mesh);
        return sides[mw];
    };
    std::size_t stamp = 0;
    for (std::size_t mw = 0; mw < config.meshes.size(); ++mw)
    {
        const TriangleMesh& m = config.meshes[mw].mesh;
        seen[mw].assign(m.triangles.size(), 0);
        double h = 2 * rMax;
        for (int L = 0; L < nLevels; ++L, h *= 4)
        {
            triGrids[mw].push_back(Grid{h, {}});
        }
        for (std::size_t t = 0; t < m.triangles.size(); ++t)
        {
            Vec3 lo = m.points[m.triangles[t][0]], hi = lo;
            for (int k = 1; k < 3; ++k)
            {
                const Vec3& q = m.points[m.triangles[t][k]];
                lo = Vec3(std::min(lo.x, q.x), std::min(lo.y, q.y), std::min(lo.z, q.z));
                hi = Vec3(std::max(hi.x, q.x), std::max(hi.y, q.y), std::max(hi.z, q.z));
            }
            for (int L = 0; L < nLevels; ++L)
            {
                Grid& g = triGrids[mw][L];
                const long i0 = g.index(lo.x), i1 = g.index(hi.x);
                const long j0 = g.index(lo.y), j1 = g.index(hi.y);
                const long k0 = g.index(lo.z), k1 = g.index(hi.z);
                if ((i1 - i0 + 1) * (j1 - j0 + 1) * (k1 - k0 + 1) > 64 && L < nLevels - 1)
                {
                    continue;
                }
                for (long i = i0; i <= i1; ++i)
                    for (long j = j0; j <= j1; ++j)
                        for (long k = k0; k <= k1; ++k)
                            g.cells[g.key(i, j, k)].push_back(t);
                break;
            }
        }
    }

    for (std::size_t i = 0; i < ins.size(); ++i)
    {
        const Body& a = ins[i];
        insGrid.near(a.x, [&](std::size_t j)
        {
            if (j <= i) return;
            bool byVolume;
            const double m = pairMeasure(a, ins[j], byVolume);
            if (m > 0)
            {
                InsertionOverlap o;
                o.particle = i;
                o.partner = InsertionOverlap::Partner::inserted;
                o.otherIndex = j;
                o.measure = m;
                o.byVolume = byVolume;
                found.push_back(o);
            }
        });
        preGrid.near(a.x, [&](std::size_t j)
        {
            bool byVolume;
            const double m = pairMeasure(a, pre[j], byVolume);
            if (m > 0)
            {
                InsertionOverlap o;
                o.particle = i;
                o.partner = InsertionOverlap::Partner::present;
                o.otherId = present.id[j];
                o.measure = m;
                o.byVolume = byVolume;
                found.push_back(o);
            }
        });

        for (const PlaneWall& w : config.planes)
        {
            if (!atStart && w.motion.kind != MotionKind::fixed) continue;
            const Vec3 n = w.normal / norm(w.normal);
            const double dist = dot(n, a.x - w.point);
            InsertionOverlap o;
            o.particle = i;
            o.partner = InsertionOverlap::Partner::wall;
            o.wall = w.name;
            if (dist <= 0)
            {
                o.behindWall = true;
                found.push_back(o);
                continue;
            }
            if (dist >= a.r) continue;
            if (a.shape)
            {
                const OverlapResult r = polyhedronPlaneOverlap(a.shape->view(), a.x, a.q, w.point, n);
                o.byVolume = true;
                o.measure = r.touching ? r.volume / a.volume : 0;
                if (o.measure > kInsertionVolumeTolerance) found.push_back(o);
            }
            else
            {
                o.measure = (a.r - dist) / (2 * a.r);
                if (o.measure > kInsertionDepthTolerance) found.push_back(o);
            }
        }

        for (std::size_t mw = 0; mw < config.meshes.size(); ++mw)
        {
            const MeshWall& w = config.meshes[mw];
            if (!atStart && w.motion.kind != MotionKind::fixed) continue;
            const TriangleMesh& m = w.mesh;
            InsertionOverlap o;
            o.particle = i;
            o.partner = InsertionOverlap::Partner::wall;
            o.wall = w.name;
            double v = 0, dMin = 1e300;
            ++stamp;
            auto visit = [&](std::size_t t)
            {
                if (seen[mw][t] == stamp) return;
                seen[mw][t] = stamp;
                const auto& tri = m.triangles[t];
                const Vec3& t0 = m.points[tri[0]];
                const Vec3& t1 = m.points[tri[1]];
                const Vec3& t2 = m.points[tri[2]];
                const double d = norm(closestPointOnTriangle(a.x, t0, t1, t2) - a.x);
                dMin = std::min(dMin, d);
                if (a.shape && d < a.r)
                {
                    const WallSidePlanes& sp = sidesOf(mw);
                    const int s0 = sp.start[t];
                    const OverlapResult r = polyhedronTriangleOverlap(a.shape->view(), a.x, a.q, t0, t1, t2,
                                                                        depthOf(mw, t), sp.normal.data() + s0,
                                                                        sp.offset.data() + s0, sp.start[t + 1] - s0);
                    if (r.touching) v += r.volume;
                }
            };
            for (const Grid& g : triGrids[mw])
            {
                if (!g.cells.empty()) g.near(a.x, visit);
            }
            if (a.shape)
            {
                o.byVolume = true;
                o.measure = v / a.volume;
                if (o.measure > kInsertionVolumeTolerance) found.push_back(o);
            }
            else if (dMin < a.r)
            {
                o.measure = (a.r - dMin) / (2 * a.r);
                if (o.measure > kInsertionDepthTolerance) found.push_back(o);
            }
        }
    }
    return found;
}

} // namespace polydem

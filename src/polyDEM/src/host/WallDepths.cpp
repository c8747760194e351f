// polyDEM: floor depths of wall triangles. See WallDepths.hpp.

#include "polyDEM/WallDepths.hpp"

#include "polyDEM/MeshQueries.hpp"

#include <algorithm>
#include <cmath>

namespace polydem
{

namespace
{

// Distance t along the ray p + t d to triangle (a, b, c), either side
// (Moeller & Trumbore 1997); edges and vertices count as hits; -1: a miss
double rayTriangle(const Vec3& p, const Vec3& d, const Vec3& a, const Vec3& b, const Vec3& c)
{
    const Vec3 e1 = b - a, e2 = c - a;
    const Vec3 s = cross(d, e2);
    const double det = dot(e1, s);
    if (!(std::fabs(det) > 1e-14 * norm(e1) * norm(e2))) return -1;   // along the plane
    const double inv = 1.0 / det;
    const Vec3 o = p - a;
    const double u = dot(o, s) * inv;
    const double eps = 1e-9;
    if (u < -eps || u > 1 + eps) return -1;
    const Vec3 qv = cross(o, e1);
    const double v = dot(d, qv) * inv;
    if (v < -eps || u + v > 1 + eps) return -1;
    return dot(e2, qv) * inv;
}

} // namespace


WallDepths::WallDepths(const TriangleMesh& mesh, double maxDepth)
:
    mesh_(mesh),
    maxDepth_(maxDepth),
    seen_(mesh.size(), 0),
    depth_(mesh.size(), -1.0)
{
    const std::size_t nt = mesh.size();
    if (nt == 0) return;

    // A uniform grid of about four cells per triangle over the bounding box
    Vec3 lo(1e300, 1e300, 1e300), hi(-1e300, -1e300, -1e300);
    for (const auto& p : mesh.points)
    {
        for (int k = 0; k < 3; ++k)
        {
            lo[k] = std::min(lo[k], p[k]);
            hi[k] = std::max(hi[k], p[k]);
        }
    }
    const double size = norm(hi - lo);
    if (!(size > 0))
    {
        std::fill(depth_.begin(), depth_.end(), kUnboundedWallDepth);
        return;
    }
    for (int k = 0; k < 3; ++k)
    {
        lo[k] -= 1e-6 * size;
        hi[k] += 1e-6 * size;
    }
    const Vec3 ext = hi - lo;
    const double h = std::max(std::cbrt(ext.x * ext.y * ext.z / (4.0 * double(nt))), size / 256);
    for (int k = 0; k < 3; ++k) n_[k] = std::min(256, std::max(1, int(std::ceil(ext[k] / h))));
    lo_ = lo;
    cell_ = Vec3(ext.x / n_[0], ext.y / n_[1], ext.z / n_[2]);
    tMin_ = 1e-6 * size;
    bins_.resize(std::size_t(n_[0]) * n_[1] * n_[2]);
    for (std::size_t t = 0; t < nt; ++t)
    {
        int i0[3], i1[3];
        for (int k = 0; k < 3; ++k)
        {
            double mn = 1e300, mx = -1e300;
            for (int v = 0; v < 3; ++v)
            {
                mn = std::min(mn, mesh.points[mesh.triangles[t][v]][k]);
                mx = std::max(mx, mesh.points[mesh.triangles[t][v]][k]);
            }
            // One cell of margin: the walk's cell of a point on a cell face
            i0[k] = std::max(0, int(std::floor((mn - lo_[k]) / cell_[k])) - 1);
            i1[k] = std::min(n_[k] - 1, int(std::floor((mx - lo_[k]) / cell_[k])) + 1);
        }
        for (int k = i0[2]; k <= i1[2]; ++k)
            for (int j = i0[1]; j <= i1[1]; ++j)
                for (int i = i0[0]; i <= i1[0]; ++i)
                    bins_[cellIndex(i, j, k)].push_back(int(t));
    }
}


double WallDepths::cast(const Vec3& p, const Vec3& d, std::size_t self)
{
    // Amanatides & Woo (1987) grid walk
    ++stamp_;
    int c[3], step[3];
    double tNext[3], tDelta[3];
    for (int k = 0; k < 3; ++k)
    {
        c[k] = std::min(n_[k] - 1, std::max(0, int(std::floor((p[k] - lo_[k]) / cell_[k]))));
        step[k] = d[k] > 0 ? 1 : (d[k] < 0 ? -1 : 0);
        const double face = lo_[k] + (c[k] + (step[k] > 0 ? 1 : 0)) * cell_[k];
        tNext[k] = step[k] != 0 ? (face - p[k]) / d[k] : 1e300;
        tDelta[k] = step[k] != 0 ? cell_[k] / std::fabs(d[k]) : 1e300;
    }
    double best = -1;
    while (true)
    {
        for (const int t : bins_[cellIndex(c[0], c[1], c[2])])
        {
            if (std::size_t(t) == self || seen_[t] == stamp_) continue;
            seen_[t] = stamp_;
            const auto& tri = mesh_.triangles[t];
            const double s = rayTriangle(p, d, mesh_.points[tri[0]], mesh_.points[tri[1]],
                                         mesh_.points[tri[2]]);
            if (s > tMin_ && (best < 0 || s < best)) best = s;
        }
        int k = 0;
        if (tNext[1] < tNext[k]) k = 1;
        if (tNext[2] < tNext[k]) k = 2;
        // A hit inside this cell is the nearest: later cells lie further on
        if (best >= 0 && best <= tNext[k]) return best;
        if (step[k] == 0) return best;
        c[k] += step[k];
        if (c[k] < 0 || c[k] >= n_[k]) return best;
        tNext[k] += tDelta[k];
    }
}


double WallDepths::shrinkBall(const Vec3& m, const Vec3& n, double rho)
{
    // While a surface point x lies inside the ball, shrink it to the ball
    // through m and x
    for (int iteration = 0; iteration < 100; ++iteration)
    {
        const Vec3 centre = m - rho * n;
        ++stamp_;
        double next = rho;
        int i0[3], i1[3];
        for (int k = 0; k < 3; ++k)
        {
            i0[k] = std::max(0, int(std::floor((centre[k] - rho - lo_[k]) / cell_[k])));
            i1[k] = std::min(n_[k] - 1, int(std::floor((centre[k] + rho - lo_[k]) / cell_[k])));
        }
        for (int k = i0[2]; k <= i1[2]; ++k)
            for (int j = i0[1]; j <= i1[1]; ++j)
                for (int i = i0[0]; i <= i1[0]; ++i)
                    for (const int t : bins_[cellIndex(i, j, k)])
                    {
                        if (seen_[t] == stamp_) continue;
                        seen_[t] = stamp_;
                        const auto& tri = mesh_.triangles[t];
                        const Vec3 x = closestPointOnTriangle(centre, mesh_.points[tri[0]],
                                                              mesh_.points[tri[1]],
                                                              mesh_.points[tri[2]]);
                        const double behind = dot(n, m - x);
                        if (!(behind > tMin_) || !(norm(centre - x) < rho * (1 - 1e-9))) continue;
                        next = std::min(next, normSqr(m - x) / (2 * behind));
                    }
        if (!(next < rho * (1 - 1e-9))) break;
        rho = next;
    }
    return rho;
}


double WallDepths::operator()(std::size_t t)
{
    if (depth_[t] >= 0) return depth_[t];
    const Vec3 a = mesh_.points[mesh_.triangles[t][0]];
    const Vec3 b = mesh_.points[mesh_.triangles[t][1]];
    const Vec3 c = mesh_.points[mesh_.triangles[t][2]];
    Vec3 normal = cross(b - a, c - a);
    const double twiceArea = norm(normal);
    if (!(twiceArea > 0))
    {
        return depth_[t] = kUnboundedWallDepth;
    }
    normal = normal / twiceArea;
    const Vec3 m = (a + b + c) / 3.0;
    const Vec3 samples[7] =
    {
        m, m + 0.95 * (a - m), m + 0.95 * (b - m), m + 0.95 * (c - m),
        m + 0.95 * (0.5 * (a + b) - m), m + 0.95 * (0.5 * (b + c) - m),
        m + 0.95 * (0.5 * (c + a) - m)
    };
    double thickness = -1;
    for (const Vec3& p : samples)
    {
        const double s = cast(p, -1.0 * normal, t);
        if (s > 0 && (thickness < 0 || s < thickness)) thickness = s;
    }
    if (thickness < 0)
    {
        return depth_[t] = kUnboundedWallDepth;
    }
    // The deepest of the samples' balls: a triangle whose centroid lies near
    // a convex edge still reaches into the body where its other parts lie far
    // from it (too shallow a prism would let a particle through; too deep a
    // one counts some overlap twice)
    const double start = std::min(0.5 * thickness, maxDepth_);
    double reach = 0;
    for (const Vec3& p : samples)
    {
        reach = std::max(reach, shrinkBall(p, normal, start));
        if (reach >= start) break;   // none can be larger
    }
    return depth_[t] = reach;
}


std::vector<double> WallDepths::all()
{
    for (std::size_t t = 0; t < depth_.size(); ++t) (*this)(t);
    return depth_;
}


std::vector<double> wallDepths(const TriangleMesh& mesh, double maxDepth)
{
    return WallDepths(mesh, maxDepth).all();
}

} // namespace polydem

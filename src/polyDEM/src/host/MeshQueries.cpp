// polyDEM: geometric queries on triangle surfaces. See MeshQueries.hpp.

#include "polyDEM/MeshQueries.hpp"

#include "polyDEM/Error.hpp"
#include "polyDEM/PolyhedronOverlap.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>
#include <vector>

namespace polydem
{

namespace
{

constexpr double pi = 3.14159265358979323846;

std::uint64_t edgeKey(int a, int b)
{
    return (std::uint64_t(std::uint32_t(a)) << 32) | std::uint32_t(b);
}

// Solid angle of triangle (a, b, c) seen from the origin (van Oosterom and
// Strackee 1983), signed by orientation
double solidAngle(const Vec3& a, const Vec3& b, const Vec3& c)
{
    const double la = norm(a), lb = norm(b), lc = norm(c);
    const double num = dot(a, cross(b, c));
    const double den = la * lb * lc + dot(a, b) * lc + dot(b, c) * la + dot(c, a) * lb;
    return 2.0 * std::atan2(num, den);
}

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


bool isClosed(const TriangleMesh& mesh)
{
    if (mesh.triangles.empty())
    {
        return false;
    }
    std::unordered_map<std::uint64_t, int> count;
    count.reserve(3 * mesh.triangles.size());
    for (const auto& t : mesh.triangles)
    {
        for (int k = 0; k < 3; ++k)
        {
            const int a = t[k], b = t[(k + 1) % 3];
            ++count[edgeKey(std::min(a, b), std::max(a, b))];
        }
    }
    for (const auto& e : count)
    {
        if (e.second != 2)
        {
            return false;
        }
    }
    return true;
}


bool isConsistentlyOriented(const TriangleMesh& mesh)
{
    if (!isClosed(mesh))
    {
        return false;
    }
    std::unordered_map<std::uint64_t, int> count;
    count.reserve(3 * mesh.triangles.size());
    for (const auto& t : mesh.triangles)
    {
        for (int k = 0; k < 3; ++k)
        {
            if (++count[edgeKey(t[k], t[(k + 1) % 3])] > 1)
            {
                return false;
            }
        }
    }
    return true;
}


double enclosedVolume(const TriangleMesh& mesh)
{
    if (mesh.triangles.empty())
    {
        return 0;
    }
    // Relative to a point on the mesh: less cancellation far from the origin
    const Vec3 o = mesh.points[mesh.triangles[0][0]];
    double v = 0;
    for (const auto& t : mesh.triangles)
    {
        v += dot(mesh.points[t[0]] - o, cross(mesh.points[t[1]] - o, mesh.points[t[2]] - o));
    }
    return v / 6.0;
}


double surfaceArea(const TriangleMesh& mesh)
{
    double a = 0;
    for (const auto& t : mesh.triangles)
    {
        const Vec3& p = mesh.points[t[0]];
        a += norm(cross(mesh.points[t[1]] - p, mesh.points[t[2]] - p));
    }
    return 0.5 * a;
}


double windingNumber(const TriangleMesh& mesh, const Vec3& p)
{
    double w = 0;
    for (const auto& t : mesh.triangles)
    {
        w += solidAngle(mesh.points[t[0]] - p, mesh.points[t[1]] - p, mesh.points[t[2]] - p);
    }
    return w / (4.0 * pi);
}


bool insideClosedMesh(const TriangleMesh& mesh, const Vec3& p)
{
    return std::abs(windingNumber(mesh, p)) > 0.5;
}


Vec3 closestPointOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c)
{
    // Voronoi regions of vertices, edges and face (Ericson 2005, 5.1.5)
    const Vec3 ab = b - a, ac = c - a, ap = p - a;
    const double d1 = dot(ab, ap), d2 = dot(ac, ap);
    if (d1 <= 0 && d2 <= 0)
    {
        return a;
    }
    const Vec3 bp = p - b;
    const double d3 = dot(ab, bp), d4 = dot(ac, bp);
    if (d3 >= 0 && d4 <= d3)
    {
        return b;
    }
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0)
    {
        return a + (d1 / (d1 - d3)) * ab;
    }
    const Vec3 cp = p - c;
    const double d5 = dot(ab, cp), d6 = dot(ac, cp);
    if (d6 >= 0 && d5 <= d6)
    {
        return c;
    }
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0)
    {
        return a + (d2 / (d2 - d6)) * ac;
    }
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
    {
        return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
    }
    const double denom = 1.0 / (va + vb + vc);
    return a + (vb * denom) * ab + (vc * denom) * ac;
}


double distanceToSurface(const TriangleMesh& mesh, const Vec3& p)
{
    double d2 = std::numeric_limits<double>::infinity();
    for (const auto& t : mesh.triangles)
    {
        const Vec3 q = closestPointOnTriangle(p, mesh.points[t[0]], mesh.points[t[1]],
                                              mesh.points[t[2]]);
        d2 = std::min(d2, normSqr(q - p));
    }
    return std::sqrt(d2);
}


void windingAndDistance(const TriangleMesh& mesh, const Vec3& p, double& winding,
                        double& distance)
{
    double w = 0;
    double d2 = std::numeric_limits<double>::infinity();
    for (const auto& t : mesh.triangles)
    {
        const Vec3 &a = mesh.points[t[0]], &b = mesh.points[t[1]], &c = mesh.points[t[2]];
        w += solidAngle(a - p, b - p, c - p);
        d2 = std::min(d2, normSqr(closestPointOnTriangle(p, a, b, c) - p));
    }
    winding = w / (4.0 * pi);
    distance = std::sqrt(d2);
}


std::pair<Vec3, Vec3> boundingBox(const TriangleMesh& mesh)
{
    if (mesh.points.empty())
    {
        throw Error("bounding box of an empty surface", mesh.source);
    }
    Vec3 lo = mesh.points[0], hi = mesh.points[0];
    for (const Vec3& p : mesh.points)
    {
        for (int d = 0; d < 3; ++d)
        {
            lo[d] = std::min(lo[d], p[d]);
            hi[d] = std::max(hi[d], p[d]);
        }
    }
    return {lo, hi};
}


void transform(TriangleMesh& mesh, double scale, const Quaternion& rotation,
               const Vec3& translation)
{
    if (!(scale > 0) || !std::isfinite(scale))
    {
        throw Error("scale must be a finite positive number", mesh.source, "scale");
    }
    const double qn = std::sqrt(rotation.w * rotation.w + rotation.x * rotation.x
                                + rotation.y * rotation.y + rotation.z * rotation.z);
    if (!(qn > 0) || !std::isfinite(qn))
    {
        throw Error("rotation quaternion must be non-zero and finite", mesh.source, "rotation");
    }
    const Quaternion q = normalised(rotation);
    for (Vec3& p : mesh.points)
    {
        p = rotate(q, scale * p) + translation;
    }
}

std::vector<double> wallDepths(const TriangleMesh& mesh)
{
    const std::size_t nt = mesh.triangles.size();
    std::vector<double> depth(nt, kUnboundedWallDepth);
    if (nt == 0) return depth;

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
    if (!(size > 0)) return depth;
    for (int k = 0; k < 3; ++k)
    {
        lo[k] -= 1e-6 * size;
        hi[k] += 1e-6 * size;
    }
    const Vec3 ext = hi - lo;
    const double h = std::max(std::cbrt(ext.x * ext.y * ext.z / (4.0 * double(nt))), size / 256);
    int n[3];
    for (int k = 0; k < 3; ++k) n[k] = std::min(256, std::max(1, int(std::ceil(ext[k] / h))));
    const Vec3 cell(ext.x / n[0], ext.y / n[1], ext.z / n[2]);
    auto index = [&](int i, int j, int k) { return (std::size_t(k) * n[1] + j) * n[0] + i; };
    std::vector<std::vector<int>> bins(std::size_t(n[0]) * n[1] * n[2]);
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
            i0[k] = std::max(0, int(std::floor((mn - lo[k]) / cell[k])) - 1);
            i1[k] = std::min(n[k] - 1, int(std::floor((mx - lo[k]) / cell[k])) + 1);
        }
        for (int k = i0[2]; k <= i1[2]; ++k)
            for (int j = i0[1]; j <= i1[1]; ++j)
                for (int i = i0[0]; i <= i1[0]; ++i)
                    bins[index(i, j, k)].push_back(int(t));
    }

    std::vector<std::size_t> seen(nt, 0);
    std::size_t stamp = 0;
    const double tMin = 1e-6 * size;
    // Nearest hit of the ray p + t d, t > tMin, other than triangle self
    // (Amanatides & Woo 1987 grid walk); -1: none
    auto cast = [&](const Vec3& p, const Vec3& d, std::size_t self)
    {
        ++stamp;
        int c[3], step[3];
        double tNext[3], tDelta[3];
        for (int k = 0; k < 3; ++k)
        {
            c[k] = std::min(n[k] - 1, std::max(0, int(std::floor((p[k] - lo[k]) / cell[k]))));
            step[k] = d[k] > 0 ? 1 : (d[k] < 0 ? -1 : 0);
            const double face = lo[k] + (c[k] + (step[k] > 0 ? 1 : 0)) * cell[k];
            tNext[k] = step[k] != 0 ? (face - p[k]) / d[k] : 1e300;
            tDelta[k] = step[k] != 0 ? cell[k] / std::fabs(d[k]) : 1e300;
        }
        double best = -1;
        while (true)
        {
            for (const int t : bins[index(c[0], c[1], c[2])])
            {
                if (std::size_t(t) == self || seen[t] == stamp) continue;
                seen[t] = stamp;
                const auto& tri = mesh.triangles[t];
                const double s = rayTriangle(p, d, mesh.points[tri[0]], mesh.points[tri[1]],
                                             mesh.points[tri[2]]);
                if (s > tMin && (best < 0 || s < best)) best = s;
            }
            int k = 0;
            if (tNext[1] < tNext[k]) k = 1;
            if (tNext[2] < tNext[k]) k = 2;
            // A hit inside this cell is the nearest: later cells lie further on
            if (best >= 0 && best <= tNext[k]) return best;
            if (step[k] == 0) return best;
            c[k] += step[k];
            if (c[k] < 0 || c[k] >= n[k]) return best;
            tNext[k] += tDelta[k];
        }
    };

    // Radius of the largest ball inside the body that touches the surface at
    // m (inward normal -normal), no larger than rho (Ma, Bae, Choi &
    // Rusinkiewicz 2012, the shrinking ball): while a surface point x lies
    // inside the ball, shrink it to the ball through m and x
    auto shrinkBall = [&](const Vec3& m, const Vec3& normal, double rho)
    {
        for (int iteration = 0; iteration < 100; ++iteration)
        {
            const Vec3 centre = m - rho * normal;
            ++stamp;
            double next = rho;
            int i0[3], i1[3];
            for (int k = 0; k < 3; ++k)
            {
                i0[k] = std::max(0, int(std::floor((centre[k] - rho - lo[k]) / cell[k])));
                i1[k] = std::min(n[k] - 1, int(std::floor((centre[k] + rho - lo[k]) / cell[k])));
            }
            for (int k = i0[2]; k <= i1[2]; ++k)
                for (int j = i0[1]; j <= i1[1]; ++j)
                    for (int i = i0[0]; i <= i1[0]; ++i)
                        for (const int t : bins[index(i, j, k)])
                        {
                            if (seen[t] == stamp) continue;
                            seen[t] = stamp;
                            const auto& tri = mesh.triangles[t];
                            const Vec3 x = closestPointOnTriangle(centre, mesh.points[tri[0]],
                                                                  mesh.points[tri[1]],
                                                                  mesh.points[tri[2]]);
                            const double behind = dot(normal, m - x);
                            if (!(behind > tMin) || !(norm(centre - x) < rho * (1 - 1e-9))) continue;
                            next = std::min(next, normSqr(m - x) / (2 * behind));
                        }
            if (!(next < rho * (1 - 1e-9))) break;
            rho = next;
        }
        return rho;
    };

    for (std::size_t t = 0; t < nt; ++t)
    {
        const Vec3 a = mesh.points[mesh.triangles[t][0]];
        const Vec3 b = mesh.points[mesh.triangles[t][1]];
        const Vec3 c = mesh.points[mesh.triangles[t][2]];
        Vec3 normal = cross(b - a, c - a);
        const double twiceArea = norm(normal);
        if (!(twiceArea > 0)) continue;
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
        if (thickness > 0)
        {
            // The deepest of the samples' balls: a triangle whose centroid
            // lies near a convex edge still reaches into the body where its
            // other parts lie far from it (too shallow a prism would let a
            // particle through; too deep a one counts some overlap twice)
            double reach = 0;
            for (const Vec3& p : samples)
            {
                reach = std::max(reach, shrinkBall(p, normal, 0.5 * thickness));
            }
            depth[t] = reach;
        }
    }
    return depth;
}


} // namespace polydem

// polyDEM: geometric queries on triangle surfaces. See MeshQueries.hpp.

#include "polyDEM/MeshQueries.hpp"

#include "polyDEM/Error.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>

namespace polydem
{

namespace
{

constexpr double pi = 3.14159265358979323846;

// Solid angle of triangle (a, b, c) seen from the origin (van Oosterom and
// Strackee 1983), signed by orientation
double solidAngle(const Vec3& a, const Vec3& b, const Vec3& c)
{
    const double la = norm(a), lb = norm(b), lc = norm(c);
    const double num = dot(a, cross(b, c));
    const double den = la * lb * lc + dot(a, b) * lc + dot(b, c) * la + dot(c, a) * lb;
    return 2.0 * std::atan2(num, den);
}

} // namespace


std::uint64_t edgeKey(int a, int b)
{
    return (std::uint64_t(std::uint32_t(a)) << 32) | std::uint32_t(b);
}


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

} // namespace polydem

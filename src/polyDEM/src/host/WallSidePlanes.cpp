// polyDEM: side planes of wall triangles. See WallSidePlanes.hpp.

#include "polyDEM/WallSidePlanes.hpp"

#include "polyDEM/MeshQueries.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

namespace polydem
{

namespace
{

Vec3 unitNormal(const TriangleMesh& mesh, std::size_t t)
{
    const auto& tri = mesh.triangles[t];
    const Vec3 n = cross(mesh.points[tri[1]] - mesh.points[tri[0]], mesh.points[tri[2]] - mesh.points[tri[0]]);
    const double a = norm(n);
    return a > 0 ? n / a : Vec3();
}

struct EdgeUse
{
    int triangle[2] = {-1, -1};
    int local[2] = {-1, -1};
    int count = 0;
};

//- The undirected edge's key
std::uint64_t undirectedKey(int a, int b)
{
    return edgeKey(std::min(a, b), std::max(a, b));
}

} // namespace


WallSidePlanes wallSidePlanes(const TriangleMesh& mesh)
{
    const std::size_t nt = mesh.size();
    WallSidePlanes sides;
    sides.start.reserve(nt + 1);
    sides.start.push_back(0);

    // Every edge's uses, keyed by its vertex indices; every vertex's triangles
    std::unordered_map<std::uint64_t, EdgeUse> edges;
    edges.reserve(3 * nt);
    std::vector<std::vector<int>> atVertex(mesh.points.size());
    for (std::size_t t = 0; t < nt; ++t)
    {
        for (int k = 0; k < 3; ++k)
        {
            EdgeUse& e = edges[undirectedKey(mesh.triangles[t][k], mesh.triangles[t][(k + 1) % 3])];
            if (e.count < 2)
            {
                e.triangle[e.count] = int(t);
                e.local[e.count] = k;
            }
            ++e.count;
            atVertex[mesh.triangles[t][k]].push_back(int(t));
        }
    }

    std::vector<Vec3> normal(nt);
    for (std::size_t t = 0; t < nt; ++t) normal[t] = unitNormal(mesh, t);

    for (std::size_t t = 0; t < nt; ++t)
    {
        const auto& tri = mesh.triangles[t];
        const Vec3 p[3] = {mesh.points[tri[0]], mesh.points[tri[1]], mesh.points[tri[2]]};
        const Vec3 centroid = (p[0] + p[1] + p[2]) / 3.0;
        const Vec3 nT = normal[t];
        const double size = std::max({norm(p[1] - p[0]), norm(p[2] - p[1]), norm(p[0] - p[2])});
        const double tol = 1e-9 * size;
        Vec3 planeNormal[kMaxWallSidePlanes], planePoint[kMaxWallSidePlanes];
        int nPlanes = 0;
        int edgeNeighbour[3] = {-1, -1, -1};

        // Edges: the bisector with the neighbour, else the normal prism's side
        for (int k = 0; k < 3; ++k)
        {
            const int a = tri[k], b = tri[(k + 1) % 3];
            Vec3 edge = p[(k + 1) % 3] - p[k];
            const double length = norm(edge);
            Vec3 side;
            if (length > 0 && norm(nT) > 0)
            {
                edge = edge / length;
                side = cross(edge, nT);   // in the triangle's plane, outward
                const EdgeUse& e = edges.at(undirectedKey(a, b));
                const int other = e.count == 2 ? (e.triangle[0] == int(t) ? 1 : 0) : -1;
                if (other >= 0 && e.triangle[other] != int(t))
                {
                    const int u = e.triangle[other];
                    const auto& triU = mesh.triangles[u];
                    const int kU = e.local[other];
                    // Consistent orientation: the neighbour runs the edge b -> a
                    const bool consistent = triU[kU] == b && triU[(kU + 1) % 3] == a;
                    const Vec3 mean = nT + normal[u];
                    if (consistent && norm(normal[u]) > 0 && norm(mean) > 1e-6)
                    {
                        edgeNeighbour[k] = u;
                        // The bisector contains the edge and the mean normal
                        Vec3 m = cross(edge, mean);
                        m = m / norm(m);
                        side = dot(m, centroid - p[k]) > 0 ? -1.0 * m : m;
                    }
                }
            }
            planeNormal[nPlanes] = side;
            planePoint[nPlanes++] = p[k];
        }

        // Vertices: the bisector with each face meeting the triangle there
        // only, where it leaves the triangle inside
        for (int k = 0; k < 3 && norm(nT) > 0; ++k)
        {
            for (const int u : atVertex[tri[k]])
            {
                if (u == int(t) || u == edgeNeighbour[0] || u == edgeNeighbour[1] || u == edgeNeighbour[2])
                {
                    continue;
                }
                const Vec3 nU = normal[u];
                Vec3 line = cross(nT, nU);
                const double s = norm(line);
                const Vec3 mean = nT + nU;
                if (!(s > 1e-6) || !(norm(mean) > 1e-6)) continue;   // parallel planes
                line = line / s;
                Vec3 m = cross(line, mean);
                m = m / norm(m);
                if (dot(m, centroid - p[k]) > 0) m = -1.0 * m;
                bool cuts = false;
                for (int j = 0; j < 3; ++j) cuts = cuts || dot(m, p[j] - p[k]) > tol;
                if (cuts) continue;   // a saddle: it would cut the triangle
                bool known = false;
                for (int j = 0; j < nPlanes && !known; ++j)
                {
                    known = norm(m - planeNormal[j]) < 1e-9 && std::fabs(dot(m, p[k] - planePoint[j])) < tol;
                }
                if (known || nPlanes == kMaxWallSidePlanes) continue;
                planeNormal[nPlanes] = m;
                planePoint[nPlanes++] = p[k];
            }
        }
        for (int j = 0; j < nPlanes; ++j)
        {
            sides.normal.push_back(planeNormal[j]);
            sides.offset.push_back(dot(planeNormal[j], planePoint[j] - p[0]));
        }
        sides.start.push_back(int(sides.normal.size()));
    }
    return sides;
}

} // namespace polydem

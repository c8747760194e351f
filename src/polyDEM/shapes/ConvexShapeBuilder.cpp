// polyDEM shapes: a ConvexShape from any point set (see ConvexShapeBuilder.hpp).

#include "ConvexShapeBuilder.hpp"
#include "ShapeMetrics.hpp"

#include "polyDEM/Error.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <set>

namespace polydem
{

namespace
{

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point3 = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point3>;

// Faces closer than this in angle are one face (round-off of symmetric solids
// given in irrational coordinates is ~1e-16)
constexpr double kCoplanarAngle = 1e-9;

Vec3 toVec3(const Point3& p)
{
    return {p.x(), p.y(), p.z()};
}

int findRoot(std::vector<int>& parent, int i)
{
    while (parent[i] != i)
    {
        parent[i] = parent[parent[i]];
        i = parent[i];
    }
    return i;
}

//- Newell's normal of a polygon (unit)
Vec3 polygonNormal(const std::vector<Vec3>& pts, const int* idx, int n)
{
    Vec3 s;
    for (int i = 0; i < n; ++i)
    {
        const Vec3& a = pts[idx[i]];
        const Vec3& b = pts[idx[(i + 1) % n]];
        s += cross(a, b);
    }
    return s / norm(s);
}

//- Hull polygons (vertex indices into the returned points), CCW from outside
void hullPolygons(const std::vector<Vec3>& input, std::vector<Vec3>& points,
                  std::vector<std::vector<int>>& polygons)
{
    std::vector<Point3> cgalPoints;
    cgalPoints.reserve(input.size());
    for (const Vec3& p : input)
    {
        cgalPoints.emplace_back(p.x, p.y, p.z);
    }
    if (cgalPoints.size() < 4)
    {
        throw Error("a convex shape needs at least 4 points, got "
                    + std::to_string(cgalPoints.size()));
    }
    Mesh mesh;
    CGAL::convex_hull_3(cgalPoints.begin(), cgalPoints.end(), mesh);
    if (mesh.number_of_faces() < 4 || !CGAL::is_triangle_mesh(mesh))
    {
        throw Error("the points are coplanar or collinear: their convex hull has no volume");
    }

    points.clear();
    std::map<Mesh::Vertex_index, int> vid;
    for (Mesh::Vertex_index v : mesh.vertices())
    {
        vid[v] = int(points.size());
        points.push_back(toVec3(mesh.point(v)));
    }

    // Triangle normals, then union of nearly coplanar neighbours
    std::map<Mesh::Face_index, int> fid;
    std::vector<Mesh::Face_index> faces;
    std::vector<Vec3> normals;
    for (Mesh::Face_index f : mesh.faces())
    {
        fid[f] = int(faces.size());
        faces.push_back(f);
        int idx[3], k = 0;
        for (Mesh::Vertex_index v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
        {
            idx[k++] = vid[v];
        }
        normals.push_back(polygonNormal(points, idx, 3));
    }
    std::vector<int> parent(faces.size());
    std::iota(parent.begin(), parent.end(), 0);
    for (Mesh::Edge_index e : mesh.edges())
    {
        const int f = fid[mesh.face(mesh.halfedge(e, 0))];
        const int g = fid[mesh.face(mesh.halfedge(e, 1))];
        if (dot(normals[f], normals[g]) > 0 && norm(cross(normals[f], normals[g])) < kCoplanarAngle)
        {
            parent[findRoot(parent, f)] = findRoot(parent, g);
        }
    }

    // Boundary loop of each merged region, in the triangles' (CCW) direction
    std::map<int, std::map<int, int>> nextOf; // region -> (source -> target)
    for (Mesh::Halfedge_index h : mesh.halfedges())
    {
        const int f = fid[mesh.face(h)];
        const int g = fid[mesh.face(mesh.opposite(h))];
        const int rf = findRoot(parent, f);
        if (rf != findRoot(parent, g))
        {
            nextOf[rf][vid[mesh.source(h)]] = vid[mesh.target(h)];
        }
    }
    polygons.clear();
    for (auto& region : nextOf)
    {
        std::map<int, int>& next = region.second;
        std::vector<int> loop;
        const int start = next.begin()->first;
        int v = start;
        do
        {
            loop.push_back(v);
            v = next.at(v);
        } while (v != start && loop.size() <= next.size());
        if (loop.size() != next.size())
        {
            throw Error("merging coplanar hull facets gave a face with a hole (internal error)");
        }
        polygons.push_back(loop);
    }
}

//- Drop vertices lying inside a straight polygon edge
void dropStraightVertices(const std::vector<Vec3>& pts, std::vector<std::vector<int>>& polygons)
{
    for (std::vector<int>& poly : polygons)
    {
        bool changed = true;
        while (changed && poly.size() > 3)
        {
            changed = false;
            const int n = int(poly.size());
            for (int i = 0; i < n; ++i)
            {
                const Vec3& a = pts[poly[(i + n - 1) % n]];
                const Vec3& b = pts[poly[i]];
                const Vec3& c = pts[poly[(i + 1) % n]];
                if (norm(cross(b - a, c - b)) < kCoplanarAngle * norm(b - a) * norm(c - b))
                {
                    poly.erase(poly.begin() + i);
                    changed = true;
                    break;
                }
            }
        }
    }
}

} // namespace


ConvexShape buildConvexShape(const std::vector<Vec3>& input, const std::string& name,
                             BodyPlacement* placement)
{
    std::vector<Vec3> hullPoints;
    std::vector<std::vector<int>> polygons;
    hullPolygons(input, hullPoints, polygons);
    dropStraightVertices(hullPoints, polygons);

    // Keep the vertices that faces use, numbered in order of first use
    std::vector<int> newIndex(hullPoints.size(), -1);
    std::vector<Vec3> used;
    std::vector<int> faceStart{0}, faceVertex;
    for (const std::vector<int>& poly : polygons)
    {
        for (int v : poly)
        {
            if (newIndex[v] < 0)
            {
                newIndex[v] = int(used.size());
                used.push_back(hullPoints[v]);
            }
            faceVertex.push_back(newIndex[v]);
        }
        faceStart.push_back(int(faceVertex.size()));
    }

    // Principal frame
    const MassProperties mp = polyhedronMassProperties(used, faceStart, faceVertex);
    if (!(mp.volume > 0))
    {
        throw Error("convex hull of zero volume for shape '" + name + "'");
    }
    Vec3 moments;
    Matrix3 R;
    principalAxes(mp.inertia, moments, R);

    ConvexShape s;
    s.name = name;
    s.faceStart = faceStart;
    s.faceVertex = faceVertex;
    for (const Vec3& p : used)
    {
        s.vertices.push_back(R.transposeTimes(p - mp.centroid));
    }
    std::set<std::pair<int, int>> edgeSet;
    for (int f = 0; f + 1 < int(faceStart.size()); ++f)
    {
        const int n = faceStart[f + 1] - faceStart[f];
        const int* idx = faceVertex.data() + faceStart[f];
        const Vec3 nf = polygonNormal(s.vertices, idx, n);
        double offset = 0;
        for (int i = 0; i < n; ++i)
        {
            offset += dot(nf, s.vertices[idx[i]]);
            const int a = idx[i], b = idx[(i + 1) % n];
            edgeSet.insert({std::min(a, b), std::max(a, b)});
        }
        s.faceNormals.push_back(nf);
        s.faceOffsets.push_back(offset / n);
    }
    for (const auto& e : edgeSet)
    {
        s.edges.push_back({e.first, e.second});
    }

    s.volume = mp.volume;
    s.inertiaPerDensity = moments;
    s.surfaceArea = surfaceArea(s.vertices, s.faceStart, s.faceVertex);
    s.equivalentDiameter = equivalentDiameter(s.volume);
    s.sphericity = sphericity(s.volume, s.surfaceArea);
    for (int j = 0; j < 3; ++j)
    {
        Vec3 e;
        e[j] = 1;
        s.crosswiseSphericity[j] = crosswiseSphericity(s, e);
    }
    s.boundingRadius = 0;
    for (const Vec3& p : s.vertices)
    {
        s.boundingRadius = std::max(s.boundingRadius, norm(p));
    }

    if (placement)
    {
        placement->centroid = mp.centroid;
        placement->rotation = R;
        placement->orientation = quaternionOfRotation(R);
    }
    return s;
}


void scaleShape(ConvexShape& s, double f)
{
    for (Vec3& p : s.vertices)
    {
        p *= f;
    }
    for (double& d : s.faceOffsets)
    {
        d *= f;
    }
    s.volume *= f * f * f;
    s.surfaceArea *= f * f;
    s.equivalentDiameter *= f;
    s.boundingRadius *= f;
    s.inertiaPerDensity *= f * f * f * f * f;
}


void scaleToEquivalentDiameter(ConvexShape& s, double d)
{
    if (!(d > 0))
    {
        throw Error("equivalent diameter must be positive, got " + std::to_string(d));
    }
    scaleShape(s, d / s.equivalentDiameter);
    s.equivalentDiameter = d; // exact, not rounded through the volume
}


Vec3 bodyExtents(const ConvexShape& s)
{
    Vec3 lo(1e300, 1e300, 1e300), hi(-1e300, -1e300, -1e300);
    for (const Vec3& p : s.vertices)
    {
        for (int j = 0; j < 3; ++j)
        {
            lo[j] = std::min(lo[j], p[j]);
            hi[j] = std::max(hi[j], p[j]);
        }
    }
    return hi - lo;
}

} // namespace polydem

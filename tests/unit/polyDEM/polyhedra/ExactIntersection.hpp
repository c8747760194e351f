// Test reference: exact intersection of two convex polyhedra with CGAL.
//
// Vertex enumeration with exact constructions (Epeck): the vertices of A n B
// are the vertices of A inside B, of B inside A, and the crossings of A's
// edges with B's facets (and B's with A's) that lie in both; their exact
// convex hull is A n B. Volume and centroid are then summed in double from
// the exact hull (its combinatorics are exact; the sums are accurate to
// round-off), independent of the clipping algorithm under test.
#pragma once

#include "polyDEM/Vec3.hpp"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>

#include <vector>

namespace polydem
{
namespace test
{

using EK = CGAL::Exact_predicates_exact_constructions_kernel;

struct ExactConvex
{
    std::vector<EK::Point_3> points;
    std::vector<EK::Plane_3> planes; // positive side = outside
    std::vector<std::pair<int, int>> edges;
};

inline ExactConvex exactConvex(const std::vector<Vec3>& worldVertices)
{
    using Mesh = CGAL::Surface_mesh<EK::Point_3>;
    std::vector<EK::Point_3> pts;
    for (const Vec3& v : worldVertices)
    {
        pts.emplace_back(v.x, v.y, v.z);
    }
    Mesh mesh;
    CGAL::convex_hull_3(pts.begin(), pts.end(), mesh);
    ExactConvex c;
    for (Mesh::Vertex_index v : mesh.vertices())
    {
        c.points.push_back(mesh.point(v));
    }
    for (Mesh::Face_index f : mesh.faces())
    {
        std::vector<EK::Point_3> p;
        for (Mesh::Vertex_index v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
        {
            p.push_back(mesh.point(v));
        }
        c.planes.emplace_back(p[0], p[1], p[2]);
    }
    for (Mesh::Edge_index e : mesh.edges())
    {
        c.edges.emplace_back(int(mesh.source(mesh.halfedge(e))), int(mesh.target(mesh.halfedge(e))));
    }
    return c;
}

inline bool inside(const ExactConvex& c, const EK::Point_3& p)
{
    for (const EK::Plane_3& h : c.planes)
    {
        if (h.oriented_side(p) == CGAL::ON_POSITIVE_SIDE)
        {
            return false;
        }
    }
    return true;
}

inline void edgeCrossings(const ExactConvex& x, const ExactConvex& y,
                          std::vector<EK::Point_3>& out)
{
    for (const auto& e : x.edges)
    {
        const EK::Point_3& p = x.points[e.first];
        const EK::Point_3& q = x.points[e.second];
        for (const EK::Plane_3& h : y.planes)
        {
            const CGAL::Oriented_side sp = h.oriented_side(p), sq = h.oriented_side(q);
            if (sp == CGAL::ON_ORIENTED_BOUNDARY || sq == CGAL::ON_ORIENTED_BOUNDARY || sp == sq)
            {
                continue; // endpoints on the plane are vertex candidates already
            }
            const auto a = h.a() * p.x() + h.b() * p.y() + h.c() * p.z() + h.d();
            const auto b = h.a() * q.x() + h.b() * q.y() + h.c() * q.z() + h.d();
            const auto t = a / (a - b);
            const EK::Point_3 xp = p + t * (q - p);
            if (inside(y, xp))
            {
                out.push_back(xp);
            }
        }
    }
}

struct ExactOverlap
{
    double volume = 0;
    Vec3 centroid;
};

inline ExactOverlap exactOverlap(const std::vector<Vec3>& a, const std::vector<Vec3>& b)
{
    const ExactConvex A = exactConvex(a), B = exactConvex(b);
    std::vector<EK::Point_3> cand;
    for (const EK::Point_3& p : A.points)
        if (inside(B, p)) cand.push_back(p);
    for (const EK::Point_3& p : B.points)
        if (inside(A, p)) cand.push_back(p);
    edgeCrossings(A, B, cand);
    edgeCrossings(B, A, cand);
    ExactOverlap r;
    if (cand.size() < 4)
    {
        return r;
    }
    // Degenerate (flat) intersections have no volume
    bool flat = true;
    for (std::size_t i = 3; i < cand.size() && flat; ++i)
    {
        flat = CGAL::coplanar(cand[0], cand[1], cand[2], cand[i]);
    }
    if (flat)
    {
        return r;
    }
    using Mesh = CGAL::Surface_mesh<EK::Point_3>;
    Mesh hull;
    CGAL::convex_hull_3(cand.begin(), cand.end(), hull);
    const auto toVec = [](const EK::Point_3& p)
    {
        return Vec3(CGAL::to_double(CGAL::exact(p.x())), CGAL::to_double(CGAL::exact(p.y())),
                    CGAL::to_double(CGAL::exact(p.z())));
    };
    const Vec3 o = toVec(hull.point(*hull.vertices().begin()));
    double sixV = 0;
    Vec3 m;
    for (Mesh::Face_index f : hull.faces())
    {
        std::vector<Vec3> p;
        for (Mesh::Vertex_index v : CGAL::vertices_around_face(hull.halfedge(f), hull))
        {
            p.push_back(toVec(hull.point(v)) - o);
        }
        const double d = dot(p[0], cross(p[1], p[2]));
        sixV += d;
        m += d * (p[0] + p[1] + p[2]);
    }
    r.volume = sixV / 6.0;
    r.centroid = o + m / (4.0 * sixV);
    return r;
}

} // namespace test
} // namespace polydem

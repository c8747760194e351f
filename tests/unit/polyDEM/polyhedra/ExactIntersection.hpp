// Test reference: exact intersection of two convex polyhedra with CGAL.
//
// Vertex enumeration with exact constructions (Epeck): the vertices of A n B
// are the vertices of A inside B, of B inside A, and the crossings of A's
// edges with B's facets (and B's with A's) that lie in both; their convex
// hull is A n B. Volume and centroid are then summed in double over
// the hull of those vertices (decided exactly, rounded to double; the sums
// are accurate to round-off), independent of the clipping algorithm under test.
#pragma once

#include "polyDEM/Vec3.hpp"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
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

//- Hull of double points: exact predicates suffice for its combinatorics (the
//  points are exact inputs), the planes are then built exactly
inline ExactConvex exactConvex(const std::vector<Vec3>& worldVertices)
{
    using IK = CGAL::Exact_predicates_inexact_constructions_kernel;
    using Mesh = CGAL::Surface_mesh<IK::Point_3>;
    std::vector<IK::Point_3> pts;
    for (const Vec3& v : worldVertices)
    {
        pts.emplace_back(v.x, v.y, v.z);
    }
    Mesh mesh;
    CGAL::convex_hull_3(pts.begin(), pts.end(), mesh);
    const auto exactPoint = [](const IK::Point_3& p) { return EK::Point_3(p.x(), p.y(), p.z()); };
    ExactConvex c;
    for (Mesh::Vertex_index v : mesh.vertices())
    {
        c.points.push_back(exactPoint(mesh.point(v)));
    }
    for (Mesh::Face_index f : mesh.faces())
    {
        std::vector<EK::Point_3> p;
        for (Mesh::Vertex_index v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
        {
            p.push_back(exactPoint(mesh.point(v)));
        }
        c.planes.emplace_back(p[0], p[1], p[2]);
    }
    for (Mesh::Edge_index e : mesh.edges())
    {
        c.edges.emplace_back(int(mesh.source(mesh.halfedge(e))), int(mesh.target(mesh.halfedge(e))));
    }
    return c;
}

//- Is p inside (or on) c? skipPlane: a plane p is known to lie on
inline bool inside(const ExactConvex& c, const EK::Point_3& p, int skipPlane = -1)
{
    for (int i = 0; i < int(c.planes.size()); ++i)
    {
        if (i != skipPlane && c.planes[i].oriented_side(p) == CGAL::ON_POSITIVE_SIDE)
        {
            return false;
        }
    }
    return true;
}

inline Vec3 toVec3(const EK::Point_3& p)
{
    return {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
}

//- Crossings of x's edges with y's facet planes that lie in y (exact decisions)
inline void edgeCrossings(const ExactConvex& x, const ExactConvex& y, std::vector<Vec3>& out)
{
    for (const auto& e : x.edges)
    {
        const EK::Point_3& p = x.points[e.first];
        const EK::Point_3& q = x.points[e.second];
        for (int j = 0; j < int(y.planes.size()); ++j)
        {
            const EK::Plane_3& h = y.planes[j];
            const CGAL::Oriented_side sp = h.oriented_side(p), sq = h.oriented_side(q);
            if (sp == CGAL::ON_ORIENTED_BOUNDARY || sq == CGAL::ON_ORIENTED_BOUNDARY || sp == sq)
            {
                continue; // endpoints on the plane are vertex candidates already
            }
            const auto a = h.a() * p.x() + h.b() * p.y() + h.c() * p.z() + h.d();
            const auto b = h.a() * q.x() + h.b() * q.y() + h.c() * q.z() + h.d();
            const auto t = a / (a - b);
            const EK::Point_3 xp = p + t * (q - p);
            if (inside(y, xp, j))
            {
                out.push_back(toVec3(xp));
            }
        }
    }
}

struct ExactOverlap
{
    double volume = 0;
    Vec3 centroid;
};

//- Volume and centroid of A n B. The vertex set of A n B is decided exactly
//  (exact predicates and constructions); its points are then rounded to
//  double (relative error ~1e-16) and wrapped with exact predicates, so the
//  reference is accurate to round-off (~1e-14), far below the 1e-9 tested.
inline ExactOverlap exactOverlap(const std::vector<Vec3>& a, const std::vector<Vec3>& b)
{
    // to_double of a lazy exact number refines the interval (or goes exact)
    // until it is at least this tight
    EK::FT::set_relative_precision_of_to_double(1e-13);
    const ExactConvex A = exactConvex(a), B = exactConvex(b);
    std::vector<Vec3> cand;
    for (const EK::Point_3& p : A.points)
        if (inside(B, p)) cand.push_back(toVec3(p));
    for (const EK::Point_3& p : B.points)
        if (inside(A, p)) cand.push_back(toVec3(p));
    edgeCrossings(A, B, cand);
    edgeCrossings(B, A, cand);
    ExactOverlap r;
    if (cand.size() < 4)
    {
        return r;
    }
    using IK = CGAL::Exact_predicates_inexact_constructions_kernel;
    std::vector<IK::Point_3> pts;
    for (const Vec3& v : cand)
    {
        pts.emplace_back(v.x, v.y, v.z);
    }
    using Mesh = CGAL::Surface_mesh<IK::Point_3>;
    Mesh hull;
    CGAL::convex_hull_3(pts.begin(), pts.end(), hull);
    if (hull.number_of_faces() < 4) // flat or lower-dimensional: no volume
    {
        return r;
    }
    const auto toVec = [](const IK::Point_3& p) { return Vec3(p.x(), p.y(), p.z()); };
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

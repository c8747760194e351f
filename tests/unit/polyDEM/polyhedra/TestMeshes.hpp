// Small triangle meshes for the wall tests (polyhedraOverlap, polyhedra_thinWall).
#pragma once

#include "polyDEM/TriangleMesh.hpp"
#include "polyDEM/Vec3.hpp"

namespace polydem::test
{

//- A closed box [lo, hi] in 12 triangles, counter-clockwise seen from outside
inline TriangleMesh closedBox(const Vec3& lo, const Vec3& hi)
{
    TriangleMesh m;
    for (int k = 0; k < 8; ++k)
    {
        m.points.push_back(Vec3(k & 1 ? hi.x : lo.x, k & 2 ? hi.y : lo.y, k & 4 ? hi.z : lo.z));
    }
    // Quads (corner indices) counter-clockwise seen from outside
    const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                             {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (const auto& q : quads)
    {
        m.triangles.push_back({q[0], q[1], q[2]});
        m.triangles.push_back({q[0], q[2], q[3]});
    }
    m.source = "closedBox";
    return m;
}

} // namespace polydem::test

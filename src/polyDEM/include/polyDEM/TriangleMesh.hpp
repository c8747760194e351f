// polyDEM: a triangle surface (wall geometry, filling region), host side.
#pragma once

#include "polyDEM/Vec3.hpp"

#include <array>
#include <string>
#include <vector>

namespace polydem
{

//- A wall triangle whose solid has no floor (an open surface, the outside of
//  a container): WallDepths, polyhedronTriangleOverlap
constexpr double kUnboundedWallDepth = 1e300;

//- Most side planes of one wall triangle's solid: three edges, then the
//  faces meeting it at a vertex only (WallSidePlanes.hpp)
constexpr int kMaxWallSidePlanes = 9;

struct TriangleMesh
{
    //- Shared vertices (duplicates from STL merged)
    std::vector<Vec3> points;
    //- Triangles as vertex indices, counter-clockwise seen from outside
    std::vector<std::array<int, 3>> triangles;
    //- Where it came from, for messages
    std::string source;

    std::size_t size() const { return triangles.size(); }
};

} // namespace polydem

// polyDEM: the side planes of each wall triangle's solid, for the overlap of
// polyhedra with triangle meshes (PolyhedronOverlap.hpp).
//
// A triangle's wall solid is the part of the body below it, down to its floor
// (WallDepths.hpp), bounded by side planes. Where an edge is shared with one
// other triangle (consistently oriented), the side plane there is the bisector
// of the two triangles' planes: the points of the body equally deep below
// both. The solids of neighbouring triangles then meet on one plane and
// partition the body near the edge, at a convex edge (the bilge of a hull,
// the edge of a box: each point goes to the face it is least deep below) as
// at a concave one (the inside corner of a container: to the face it is
// deepest below): nothing is counted twice and nothing is left out. The
// plane normal to the triangle through the edge (its normal prism) would
// overlap its neighbour's at a convex edge and leave a wedge to neither at a
// concave one; it is the bisector's limit for coplanar neighbours, and what
// is kept at an edge with no neighbour (the rim of an open surface), more
// than one (a non-manifold edge), a neighbour of the opposite orientation,
// or a fold back onto itself (normals opposite).
//
// At a vertex, the faces that meet there without sharing an edge with the
// triangle (at the corner of a box split into triangles, the third face;
// around a vertex of a curved surface, the far side of the fan) bound its
// solid too: the bisector with each, through the line where the two planes
// meet, wherever that plane leaves the triangle itself wholly inside (a
// convex or a concave vertex). At a saddle vertex, where it would cut the
// triangle, it is left out, and the solids there overlap or leave a gap in
// a region of the size of the particle's reach past the vertex times the
// angle between the faces. Coincident planes are kept once, and at most
// kMaxWallSidePlanes per triangle (edges first). Only faces touching the
// triangle bound its solid: a long triangle across a flat face (a ladder
// triangulation of a hull's keel) also holds body below it that is nearer
// a side face it does not touch, which that face's solid holds too
// (docs/dem.md: up to 12 % of a block on the brash-ice hull at 2-3 cm
// penetration; fan-meshed and box faces are exact).
//
// The planes are in the mesh's own frame (the frame its triangles are stored
// in), so they move with the wall.
#pragma once

#include "polyDEM/TriangleMesh.hpp"
#include "polyDEM/Vec3.hpp"

#include <vector>

namespace polydem
{

//- Every triangle's side planes, m.(x - t0) <= offset (m unit, outward; t0
//  the triangle's first vertex), triangle t's in [start[t], start[t + 1])
struct WallSidePlanes
{
    std::vector<int> start;
    std::vector<Vec3> normal;
    std::vector<double> offset;
};

WallSidePlanes wallSidePlanes(const TriangleMesh& mesh);

} // namespace polydem

// polyDEM: geometric queries on triangle surfaces: closedness, enclosed
// volume, point inside a closed surface (generalised winding number,
// Jacobson et al. 2013), point-triangle distance (Ericson 2005, Real-Time
// Collision Detection, sec. 5.1.5), bounding box and rigid transformation.
// All queries are O(number of triangles) per point: fine for filling and
// set-up, not meant for per-time-step contact detection.
#pragma once

#include "polyDEM/Quaternion.hpp"
#include "polyDEM/TriangleMesh.hpp"
#include "polyDEM/Vec3.hpp"

#include <cstdint>
#include <utility>

namespace polydem
{

//- Every (undirected) edge is shared by exactly two triangles
//- Key of the directed edge a -> b (edgeKey(min, max) for an undirected one)
std::uint64_t edgeKey(int a, int b);

bool isClosed(const TriangleMesh& mesh);

//- Closed and each directed edge used once (neighbours agree on orientation)
bool isConsistentlyOriented(const TriangleMesh& mesh);

//- Signed enclosed volume by the divergence theorem: V = 1/6 sum a.(b x c).
//  Positive when triangles are counter-clockwise seen from outside.
double enclosedVolume(const TriangleMesh& mesh);

//- Total surface area
double surfaceArea(const TriangleMesh& mesh);

//- Generalised winding number of the surface about p: ~1 inside a closed
//  surface (-1 if inward oriented), ~0 outside; fractional near holes
double windingNumber(const TriangleMesh& mesh, const Vec3& p);

//- Point strictly inside a closed surface (either orientation). Robust to
//  rays through edges/vertices since no ray is cast; points on the surface
//  may go either way.
bool insideClosedMesh(const TriangleMesh& mesh, const Vec3& p);

//- Closest point to p on triangle (a, b, c)
Vec3 closestPointOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

//- Unsigned distance from p to the surface
double distanceToSurface(const TriangleMesh& mesh, const Vec3& p);

//- Winding number and surface distance in one pass over the triangles
void windingAndDistance(const TriangleMesh& mesh, const Vec3& p, double& winding,
                        double& distance);

//- Axis-aligned bounding box (min, max) of the points; throws on an empty mesh
std::pair<Vec3, Vec3> boundingBox(const TriangleMesh& mesh);

//- x -> rotate(rotation, scale x) + translation, in place. scale > 0 (a
//  negative scale would turn the surface inside out); rotation is normalised.
void transform(TriangleMesh& mesh, double scale, const Quaternion& rotation,
               const Vec3& translation);

} // namespace polydem

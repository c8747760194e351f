// polyDEM shapes: a ConvexShape from any point set.
//
// Convex hull of the points (CGAL::convex_hull_3, exact predicates), adjacent
// hull triangles whose normals agree to 1e-9 rad merged into one polygon face
// (so a cube has 6 square faces, a dodecahedron 12 pentagons), vertices lying
// inside a straight face edge dropped; then the exact mass properties, the
// shape moved to its centroid and turned to its principal axes (body x = the
// axis of least moment, the long axis of an elongated particle), and the
// derived properties (area, sphericity, crosswise sphericity, radius) filled.
#pragma once

#include "MassProperties.hpp"

#include "polyDEM/ConvexPolyhedron.hpp"

#include <string>
#include <vector>

namespace polydem
{

//- Where the body frame lies in the frame of the input points:
//  x_input = centroid + rotation * x_body  (= centroid + rotate(orientation, x_body))
struct BodyPlacement
{
    Vec3 centroid;
    Matrix3 rotation;
    Quaternion orientation;
};

//- Convex hull of points as a ConvexShape in its principal body frame.
//  Throws polydem::Error if the points span no volume.
ConvexShape buildConvexShape(const std::vector<Vec3>& points, const std::string& name,
                             BodyPlacement* placement = nullptr);

//- Scale a shape about its centroid by s (volume s^3, inertia s^5)
void scaleShape(ConvexShape& shape, double s);

//- Scale a shape so that its volume-equivalent diameter is d
void scaleToEquivalentDiameter(ConvexShape& shape, double d);

//- Extent of the shape along its body axes (max - min of the vertex coordinates)
Vec3 bodyExtents(const ConvexShape& shape);

} // namespace polydem

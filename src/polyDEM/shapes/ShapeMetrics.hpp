// polyDEM shapes: surface and shape descriptors of a convex polyhedron.
//
// Sphericity psi = pi^(1/3) (6V)^(2/3) / A (Wadell, H. 1933, J. Geol. 41:310);
// crosswise sphericity psi_perp(e) = (pi d_v^2 / 4) / A_proj(e), the
// cross-section of the volume-equivalent sphere over the area projected on
// the plane normal to e (Hoelzle, A. & Sommerfeld, M. 2008, Powder Technol.
// 184:361). The projected area of a convex body is exactly the area of the
// 2-D convex hull of its projected vertices (Andrew's monotone chain).
#pragma once

#include "polyDEM/Vec3.hpp"

#include <vector>

namespace polydem
{

struct ConvexShape;

//- Sum of the face polygon areas
double surfaceArea(const std::vector<Vec3>& points, const std::vector<int>& faceStart,
                   const std::vector<int>& faceVertex);

//- Diameter of the sphere of volume V
double equivalentDiameter(double volume);

//- pi^(1/3) (6V)^(2/3) / A
double sphericity(double volume, double area);

//- Area of the shadow of the convex hull of points on the plane normal to direction
double projectedArea(const std::vector<Vec3>& points, const Vec3& direction);

//- (pi d_v^2 / 4) / projectedArea(direction)
double crosswiseSphericity(const ConvexShape& shape, const Vec3& direction);

} // namespace polydem

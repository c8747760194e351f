// polyDEM shapes: generators of convex particle shapes.
//
// All shapes come out of buildConvexShape (principal body frame). Sizes are
// given either directly (box) or as the diameter d of the sphere of equal
// volume. Random rocks use a seeded 64-bit Mersenne twister and their own
// normal deviates (Box-Muller), so a seed gives the same rock on every
// platform.
//
// Settling family (J. Mar. Sci. Eng. 2023, reference/polyhedraSettling.md):
// a particle with C triangular facets and aspect ratio AR is the convex hull
// of V = C/2 + 2 points on a prolate spheroid (long axis x, semi-axes
// AR : 1 : 1), placed by a Fibonacci spiral (golden-angle steps in longitude,
// equal steps in x) so that they are in convex and general position; every
// point is then a hull vertex and every face a triangle, and Euler's formula
// for a closed triangulated convex surface (F = 2V - 4) gives exactly C
// facets. C must therefore be even, 4 <= C <= 64 (the shape caps). The
// polyhedron is then stretched along its long principal axis until its
// measured aspect ratio
//     AR = L / ((W1 + W2) / 2),
// L = extent along the long (body x) axis and W1, W2 the extents along the
// other two principal axes, equals the request exactly (a stretch along a
// principal axis keeps the principal axes and the facets), and finally scaled
// to the equivalent diameter d.
#pragma once

#include "polyDEM/ConvexPolyhedron.hpp"

#include <cstdint>

namespace polydem
{

//- Box of edges a, b, c (along x, y, z before the principal sort)
ConvexShape makeBox(double a, double b, double c);

//- Cube of edge a
ConvexShape makeCube(double a);

//- Regular solids of equivalent diameter d
ConvexShape makeTetrahedron(double d);
ConvexShape makeOctahedron(double d);
ConvexShape makeDodecahedron(double d);
ConvexShape makeIcosahedron(double d);

//- Random convex rock: hull of nPoints random points on an ellipsoid of
//  semi-axes 1 : elongation : elongation * flatness (elongation = b/a,
//  flatness = c/b, both in (0, 1]), scaled to equivalent diameter d
ConvexShape makeRock(double d, double elongation, double flatness, int nPoints,
                     std::uint64_t seed);

//- Settling-study particle: exactly C triangular facets, aspect ratio AR
//  (as defined above), equivalent diameter d
ConvexShape makeSettlingParticle(double d, double aspectRatio, int facets);

//- The aspect ratio measured as in makeSettlingParticle
double measuredAspectRatio(const ConvexShape& shape);

} // namespace polydem

// Tests of the host-side shape builder: mass properties against analytic
// values, coplanar-facet merging, principal frame and placement, the
// settling-study family, and STL round trips.

#include "ConvexShapeBuilder.hpp"
#include "MassProperties.hpp"
#include "ShapeFiles.hpp"
#include "ShapeGenerators.hpp"
#include "ShapeMetrics.hpp"

#include "polyDEM/Error.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <string>

using namespace polydem;

namespace
{
constexpr double pi = 3.14159265358979323846;

double rel(double a, double b)
{
    return std::fabs(a - b) / std::fabs(b);
}

double psi(double V, double A)
{
    return std::cbrt(pi) * std::pow(6 * V, 2.0 / 3.0) / A;
}
} // namespace


TEST(polyhedraShapes, boxMassProperties)
{
    const double a = 3, b = 2, c = 1;
    const ConvexShape s = makeBox(a, b, c);
    EXPECT_EQ(s.nFaces(), 6);
    EXPECT_EQ(s.nVertices(), 8);
    EXPECT_EQ(s.nEdges(), 12);
    const double V = a * b * c, A = 2 * (a * b + b * c + c * a);
    EXPECT_LT(rel(s.volume, V), 1e-12);
    EXPECT_LT(rel(s.surfaceArea, A), 1e-12);
    EXPECT_LT(rel(s.sphericity, psi(V, A)), 1e-12);
    // Ascending principal moments: about a (long), b, c
    EXPECT_LT(rel(s.inertiaPerDensity.x, V * (b * b + c * c) / 12), 1e-12);
    EXPECT_LT(rel(s.inertiaPerDensity.y, V * (a * a + c * c) / 12), 1e-12);
    EXPECT_LT(rel(s.inertiaPerDensity.z, V * (a * a + b * b) / 12), 1e-12);
    EXPECT_LT(rel(s.boundingRadius, 0.5 * std::sqrt(a * a + b * b + c * c)), 1e-12);
    // Crosswise sphericity along the long axis: projected area b c
    const double d = std::cbrt(6 * V / pi);
    EXPECT_LT(rel(s.crosswiseSphericity.x, 0.25 * pi * d * d / (b * c)), 1e-12);
    EXPECT_LT(rel(s.crosswiseSphericity.z, 0.25 * pi * d * d / (a * b)), 1e-12);
    EXPECT_NO_THROW(s.check());
}


TEST(polyhedraShapes, regularSolidsMassProperties)
{
    const double d = 0.01;
    const double V = pi * d * d * d / 6;
    {
        const ConvexShape s = makeTetrahedron(d);
        const double a = std::cbrt(6 * std::sqrt(2.0) * V); // edge
        EXPECT_EQ(s.nFaces(), 4);
        EXPECT_LT(rel(s.volume, V), 1e-12);
        EXPECT_LT(rel(s.volume, a * a * a / (6 * std::sqrt(2.0))), 1e-12);
        EXPECT_LT(rel(s.surfaceArea, std::sqrt(3.0) * a * a), 1e-12);
        EXPECT_LT(rel(s.sphericity, psi(V, std::sqrt(3.0) * a * a)), 1e-12);
        for (int j = 0; j < 3; ++j)
        {
            EXPECT_LT(rel(s.inertiaPerDensity[j], V * a * a / 20), 1e-12);
        }
        EXPECT_LT(rel(s.boundingRadius, a * std::sqrt(6.0) / 4), 1e-12);
    }
    {
        const ConvexShape s = makeOctahedron(d);
        const double a = std::cbrt(3 * V / std::sqrt(2.0));
        EXPECT_EQ(s.nFaces(), 8);
        EXPECT_EQ(s.nEdges(), 12);
        EXPECT_LT(rel(s.volume, std::sqrt(2.0) / 3 * a * a * a), 1e-12);
        EXPECT_LT(rel(s.surfaceArea, 2 * std::sqrt(3.0) * a * a), 1e-12);
        EXPECT_LT(rel(s.sphericity, psi(V, 2 * std::sqrt(3.0) * a * a)), 1e-12);
        for (int j = 0; j < 3; ++j)
        {
            EXPECT_LT(rel(s.inertiaPerDensity[j], V * a * a / 10), 1e-12);
        }
    }
    {
        const ConvexShape s = makeDodecahedron(d);
        EXPECT_EQ(s.nFaces(), 12); // pentagons merged from hull triangles
        EXPECT_EQ(s.nVertices(), 20);
        EXPECT_EQ(s.nEdges(), 30);
        EXPECT_LT(rel(s.volume, V), 1e-12);
        const double a = std::cbrt(4 * V / (15 + 7 * std::sqrt(5.0)));
        EXPECT_LT(rel(s.surfaceArea, 3 * std::sqrt(25 + 10 * std::sqrt(5.0)) * a * a), 1e-12);
    }
    {
        const ConvexShape s = makeIcosahedron(d);
        EXPECT_EQ(s.nFaces(), 20);
        EXPECT_EQ(s.nVertices(), 12);
        const double a = std::cbrt(12 * V / (5 * (3 + std::sqrt(5.0))));
        EXPECT_LT(rel(s.surfaceArea, 5 * std::sqrt(3.0) * a * a), 1e-12);
        EXPECT_LT(rel(s.equivalentDiameter, d), 1e-12);
    }
    {
        const ConvexShape s = makeCube(0.02);
        EXPECT_EQ(s.nFaces(), 6);
        EXPECT_LT(rel(s.sphericity, std::cbrt(pi / 6)), 1e-12); // psi of a cube
        // Axis-aligned despite the isotropic tensor
        EXPECT_LT(rel(s.crosswiseSphericity.x, 0.25 * pi * std::pow(6 / pi, 2.0 / 3.0)), 1e-12);
    }
}


// A rock given in an arbitrary frame: the placement puts the body back
TEST(polyhedraShapes, principalFrameAndPlacement)
{
    std::mt19937_64 rng(3);
    std::normal_distribution<double> g;
    std::vector<Vec3> pts;
    for (int i = 0; i < 30; ++i)
    {
        pts.emplace_back(3 + 2.0 * g(rng), -1 + 1.0 * g(rng), 0.5 * g(rng));
    }
    BodyPlacement place;
    const ConvexShape s = buildConvexShape(pts, "cloud", &place);
    // Every body vertex maps onto an input point
    for (const Vec3& v : s.vertices)
    {
        const Vec3 x = place.centroid + rotate(place.orientation, v);
        double best = 1e300;
        for (const Vec3& p : pts) best = std::min(best, norm(x - p));
        EXPECT_LT(best, 1e-12);
    }
    // Inertia of the body-frame shape is diagonal and ascending
    const MassProperties mp = polyhedronMassProperties(s.vertices, s.faceStart, s.faceVertex);
    EXPECT_LT(norm(mp.centroid), 1e-13);
    const double scale = mp.inertia.m[0][0];
    EXPECT_LT(std::fabs(mp.inertia.m[0][1]) / scale, 1e-12);
    EXPECT_LT(std::fabs(mp.inertia.m[0][2]) / scale, 1e-12);
    EXPECT_LT(std::fabs(mp.inertia.m[1][2]) / scale, 1e-12);
    EXPECT_LE(s.inertiaPerDensity.x, s.inertiaPerDensity.y);
    EXPECT_LE(s.inertiaPerDensity.y, s.inertiaPerDensity.z);
    // Faces: unit outward normals, all vertices on or behind every plane
    for (int f = 0; f < s.nFaces(); ++f)
    {
        EXPECT_NEAR(norm(s.faceNormals[f]), 1.0, 1e-14);
        for (const Vec3& v : s.vertices)
        {
            EXPECT_LE(dot(s.faceNormals[f], v) - s.faceOffsets[f], 1e-12);
        }
    }
}


TEST(polyhedraShapes, settlingFamily)
{
    const double d = 0.01;
    for (int C : {20, 50})
    {
        for (double AR : {1.25, 1.5, 1.75, 2.0})
        {
            const ConvexShape s = makeSettlingParticle(d, AR, C);
            EXPECT_EQ(s.nFaces(), C);
            EXPECT_EQ(s.nVertices(), C / 2 + 2);
            for (int f = 0; f < s.nFaces(); ++f)
            {
                EXPECT_EQ(s.faceStart[f + 1] - s.faceStart[f], 3); // all triangles
            }
            EXPECT_LT(rel(measuredAspectRatio(s), AR), 1e-12);
            EXPECT_LT(rel(s.equivalentDiameter, d), 1e-12);
            EXPECT_LT(rel(std::cbrt(6 * s.volume / pi), d), 1e-12);
            // The long axis is body x
            const Vec3 L = bodyExtents(s);
            EXPECT_GT(L.x, L.y);
            EXPECT_GT(L.x, L.z);
            EXPECT_NO_THROW(s.check());
            std::printf("[ polyhedra ] C %d AR %.2f: sphericity %.4f, crosswise (x y z) %.4f "
                        "%.4f %.4f\n",
                        C, AR, s.sphericity, s.crosswiseSphericity.x, s.crosswiseSphericity.y,
                        s.crosswiseSphericity.z);
        }
    }
    EXPECT_THROW(makeSettlingParticle(d, 1.5, 21), Error);  // odd: impossible
    EXPECT_THROW(makeSettlingParticle(d, 1.5, 100), Error); // above the face cap
    EXPECT_THROW(makeSettlingParticle(d, 0.5, 20), Error);
}


TEST(polyhedraShapes, rocksAreReproducibleAndWithinCaps)
{
    const ConvexShape a = makeRock(0.01, 0.6, 0.5, 34, 42);
    const ConvexShape b = makeRock(0.01, 0.6, 0.5, 34, 42);
    EXPECT_EQ(a.vertices.size(), b.vertices.size());
    EXPECT_EQ(a.volume, b.volume);
    EXPECT_LE(a.nFaces(), kMaxPolyhedronFaces);
    EXPECT_NO_THROW(a.check());
    EXPECT_LT(rel(a.equivalentDiameter, 0.01), 1e-12);
    EXPECT_THROW(makeRock(0.01, 0.6, 0.5, 35, 42), Error);
    EXPECT_THROW(makeRock(0.01, 1.5, 0.5, 20, 42), Error);
}


TEST(polyhedraShapes, stlRoundTrip)
{
    const ConvexShape s = makeRock(0.01, 0.7, 0.8, 25, 9);
    for (bool binary : {false, true})
    {
        const std::string file = std::string("polyhedraShapeTest_") + (binary ? "bin" : "ascii")
                                 + ".stl";
        writeStl(s, file, binary);
        const ConvexShape r = buildConvexShape(readPointSet(file), "read");
        EXPECT_EQ(r.nFaces(), s.nFaces());
        EXPECT_LT(rel(r.volume, s.volume), binary ? 1e-6 : 1e-14);
        std::remove(file.c_str());
    }
    EXPECT_THROW(readPointSet("does_not_exist.stl"), Error);
    writeProperties(s, "polyhedraShapeTest.properties");
    std::remove("polyhedraShapeTest.properties");
}


TEST(polyhedraShapes, rejectsDegenerateInput)
{
    EXPECT_THROW(buildConvexShape({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}}, "flat"), Error);
    EXPECT_THROW(buildConvexShape({{0, 0, 0}, {1, 0, 0}}, "two"), Error);
}

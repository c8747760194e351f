// Tests of STL reading/writing and of the triangle-surface queries.

#include "TestMeshes.hpp"

#include "polyDEM/Error.hpp"
#include "polyDEM/MeshQueries.hpp"
#include "polyDEM/StlReader.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

using namespace polydem;
using namespace polydem::test;

namespace
{

// Expect readStl(path) to throw an Error whose what() holds path and all of parts
void expectReadError(const std::string& path, std::initializer_list<const char*> parts)
{
    try
    {
        readStl(path);
        FAIL() << "no error for " << path;
    }
    catch (const Error& e)
    {
        const std::string what = e.what();
        EXPECT_NE(what.find(path), std::string::npos) << what;
        EXPECT_EQ(e.file(), path);
        for (const char* p : parts)
        {
            EXPECT_NE(what.find(p), std::string::npos) << "'" << p << "' not in: " << what;
        }
    }
}

void checkCube(const TriangleMesh& m)
{
    EXPECT_EQ(m.triangles.size(), 12u);
    EXPECT_EQ(m.points.size(), 8u);
    EXPECT_TRUE(isClosed(m));
    EXPECT_TRUE(isConsistentlyOriented(m));
    EXPECT_NEAR(enclosedVolume(m), 1.0, 1e-12);
    EXPECT_NEAR(surfaceArea(m), 6.0, 1e-12);
}

} // namespace


TEST(StlReader, asciiRoundTrip)
{
    const std::string path = tempPath("cube_ascii.stl");
    writeStl(path, unitCube(), false);
    StlReadInfo info;
    const TriangleMesh m = readStl(path, 1.0, &info);
    checkCube(m);
    EXPECT_FALSE(info.binary);
    EXPECT_EQ(info.trianglesInFile, 12u);
    EXPECT_EQ(info.verticesInFile, 36u);
    EXPECT_EQ(info.verticesMerged, 8u);
    EXPECT_EQ(info.degenerateDropped, 0u);
    EXPECT_EQ(m.source, path);
    std::remove(path.c_str());
}

TEST(StlReader, binaryRoundTrip)
{
    const std::string path = tempPath("cube_binary.stl");
    writeStl(path, unitCube(), true);
    EXPECT_EQ(slurp(path).size(), 84u + 50u * 12u);
    StlReadInfo info;
    checkCube(readStl(path, 1.0, &info));
    EXPECT_TRUE(info.binary);
    std::remove(path.c_str());
}

TEST(StlReader, binaryWithSolidHeaderIsBinary)
{
    const std::string path = tempPath("cube_solid_header.stl");
    writeStl(path, unitCube(), true);
    std::string data = slurp(path);
    const std::string header = "solid cube exported by a CAD tool";
    data.replace(0, header.size(), header);
    spit(path, data);
    StlReadInfo info;
    checkCube(readStl(path, 1.0, &info));
    EXPECT_TRUE(info.binary);
    std::remove(path.c_str());
}

TEST(StlReader, scaleAndDegenerate)
{
    const std::string path = tempPath("cube_degenerate.stl");
    TriangleMesh cube = unitCube();
    // A collinear (zero-area) facet and one collapsed to a point
    cube.points.push_back({0.5, 0, 0});
    cube.triangles.push_back({0, 8, 1});
    cube.triangles.push_back({3, 3, 3});
    writeStl(path, cube, false);
    StlReadInfo info;
    const TriangleMesh m = readStl(path, 2.0, &info);
    EXPECT_EQ(info.degenerateDropped, 2u);
    EXPECT_EQ(m.triangles.size(), 12u);
    EXPECT_EQ(m.points.size(), 8u); // the point of the dropped facet is gone
    EXPECT_NEAR(enclosedVolume(m), 8.0, 1e-12);
    std::remove(path.c_str());
}

TEST(StlReader, mergesWithinTolerance)
{
    TriangleMesh soup = unitCube();
    // Triangle soup with every corner perturbed far below the tolerance
    TriangleMesh separate;
    std::mt19937_64 rng(3);
    for (const auto& t : soup.triangles)
    {
        std::array<int, 3> nt;
        for (int k = 0; k < 3; ++k)
        {
            const double e = 1e-13 * (double(rng() % 1000) / 500.0 - 1.0);
            nt[k] = int(separate.points.size());
            separate.points.push_back(soup.points[t[k]] + Vec3{e, -e, e});
        }
        separate.triangles.push_back(nt);
    }
    EXPECT_EQ(mergePoints(separate, 1e-9), 36u - 8u);
    EXPECT_TRUE(isClosed(separate));
}

TEST(StlReader, errorsNameTheFile)
{
    const std::string missing = tempPath("does_not_exist.stl");
    expectReadError(missing, {"cannot open"});

    const std::string empty = tempPath("empty.stl");
    spit(empty, "");
    expectReadError(empty, {"empty"});

    // Truncated binary, also when the header starts with "solid"
    const std::string truncated = tempPath("truncated.stl");
    writeStl(truncated, unitCube(), true);
    std::string data = slurp(truncated);
    spit(truncated, data.substr(0, data.size() - 30));
    expectReadError(truncated, {"truncated binary", "12 triangles"});
    data.replace(0, 5, "solid");
    spit(truncated, data.substr(0, data.size() - 30));
    expectReadError(truncated, {"truncated binary"});

    const std::string garbage = tempPath("garbage.stl");
    spit(garbage, "solid broken\n"
                  "  facet normal 0 0 1\n"
                  "    outer loop\n"
                  "      vertex 0 0 0\n"
                  "      vertex 1 0 zero\n"
                  "      vertex 0 1 0\n"
                  "    endloop\n"
                  "  endfacet\n"
                  "endsolid broken\n");
    expectReadError(garbage, {"line 5", "expected 'vertex x y z'", "zero"});

    spit(garbage, "solid broken\n  facet normal 0 0 1\n    outer lop\n");
    expectReadError(garbage, {"line 3", "expected 'outer loop'"});

    spit(garbage, "solid cut\n  facet normal 0 0 1\n    outer loop\n      vertex 0 0 0\n");
    expectReadError(garbage, {"end of file"});

    spit(garbage, "this is not an stl file at all, just some text that is long enough to "
                  "pass eighty-four bytes without a doubt.\n");
    expectReadError(garbage, {"binary STL"});

    spit(garbage, "solid nothing\nendsolid nothing\n");
    expectReadError(garbage, {"no triangles"});

    spit(garbage, "solid nan\n facet normal 0 0 1\n outer loop\n vertex 0 0 0\n"
                  " vertex nan 0 0\n vertex 0 1 0\n endloop\n endfacet\nendsolid nan\n");
    expectReadError(garbage, {"line 5", "non-finite"});

    spit(garbage, "solid flat\n facet normal 0 0 1\n outer loop\n vertex 0 0 0\n"
                  " vertex 1 0 0\n vertex 2 0 0\n endloop\n endfacet\nendsolid flat\n");
    expectReadError(garbage, {"degenerate"});

    for (const auto& p : {empty, truncated, garbage})
    {
        std::remove(p.c_str());
    }
}

TEST(StlReader, multipleSolidsAndNameTokens)
{
    const std::string path = tempPath("two_solids.stl");
    const TriangleMesh cube = unitCube();
    writeStl(path, cube, false, "first part");
    std::string text = slurp(path);
    // A second (empty-named, upper case) solid appended, then read as one surface
    text += "SOLID\nENDSOLID\n";
    spit(path, text);
    checkCube(readStl(path));
    std::remove(path.c_str());
}

TEST(MeshQueries, openSurfaceNotClosed)
{
    TriangleMesh m = unitCube();
    m.triangles.pop_back();
    EXPECT_FALSE(isClosed(m));
    EXPECT_FALSE(isConsistentlyOriented(m));
    TriangleMesh flipped = unitCube();
    std::swap(flipped.triangles[0][1], flipped.triangles[0][2]);
    EXPECT_TRUE(isClosed(flipped));
    EXPECT_FALSE(isConsistentlyOriented(flipped));
}

TEST(MeshQueries, insideSphereVsAnalytic)
{
    const TriangleMesh s = uvSphere(1.0, 24, 48);
    ASSERT_TRUE(isClosed(s));
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(-1.5, 1.5);
    int checked = 0;
    for (int i = 0; i < 2000; ++i)
    {
        const Vec3 p{u(rng), u(rng), u(rng)};
        const double r = norm(p);
        // Skip the thin shell where the polygonal surface and the sphere differ
        if (std::abs(r - 1.0) < 0.02)
        {
            continue;
        }
        ++checked;
        EXPECT_EQ(insideClosedMesh(s, p), r < 1.0) << p.x << " " << p.y << " " << p.z;
    }
    EXPECT_GT(checked, 1800);
    // Points on the axes: rays through vertices/edges would trouble ray casting
    EXPECT_TRUE(insideClosedMesh(s, {0, 0, 0}));
    EXPECT_TRUE(insideClosedMesh(s, {0, 0, 0.9}));
    EXPECT_FALSE(insideClosedMesh(s, {0, 0, 1.1}));
    // Orientation does not matter
    TriangleMesh inward = s;
    for (auto& t : inward.triangles)
    {
        std::swap(t[1], t[2]);
    }
    EXPECT_TRUE(insideClosedMesh(inward, {0.1, 0.2, 0.3}));
    EXPECT_LT(enclosedVolume(inward), 0);
}

TEST(MeshQueries, distance)
{
    const Vec3 a{0, 0, 0}, b{1, 0, 0}, c{0, 1, 0};
    auto near = [](const Vec3& p, const Vec3& q) { return norm(p - q) < 1e-14; };
    EXPECT_TRUE(near(closestPointOnTriangle({0.2, 0.2, 3}, a, b, c), {0.2, 0.2, 0}));
    EXPECT_TRUE(near(closestPointOnTriangle({-1, -1, 0}, a, b, c), a));
    EXPECT_TRUE(near(closestPointOnTriangle({2, -1, 1}, a, b, c), b));
    EXPECT_TRUE(near(closestPointOnTriangle({-1, 3, 0}, a, b, c), c));
    EXPECT_TRUE(near(closestPointOnTriangle({0.5, -2, 0}, a, b, c), {0.5, 0, 0}));
    EXPECT_TRUE(near(closestPointOnTriangle({1, 1, 0}, a, b, c), {0.5, 0.5, 0}));
    EXPECT_TRUE(near(closestPointOnTriangle({-3, 0.25, 1}, a, b, c), {0, 0.25, 0}));

    const TriangleMesh cube = unitCube();
    EXPECT_NEAR(distanceToSurface(cube, {0.5, 0.5, 0.5}), 0.5, 1e-15);
    EXPECT_NEAR(distanceToSurface(cube, {0.3, 0.6, 0.45}), 0.3, 1e-15);
    EXPECT_NEAR(distanceToSurface(cube, {2, 2, 0.5}), std::sqrt(2.0), 1e-15);
}

TEST(MeshQueries, transformAndBoundingBox)
{
    TriangleMesh m = unitCube();
    transform(m, 2.0, fromAxisAngle({0, 0, 1}, 0.5 * 3.14159265358979323846), {10, 0, 0});
    const auto [lo, hi] = boundingBox(m);
    EXPECT_NEAR(lo.x, 8, 1e-12);
    EXPECT_NEAR(hi.x, 10, 1e-12);
    EXPECT_NEAR(lo.y, 0, 1e-12);
    EXPECT_NEAR(hi.y, 2, 1e-12);
    EXPECT_NEAR(lo.z, 0, 1e-12);
    EXPECT_NEAR(hi.z, 2, 1e-12);
    EXPECT_NEAR(enclosedVolume(m), 8, 1e-12);
    EXPECT_THROW(transform(m, -1.0, {}, {}), Error);
    EXPECT_THROW(boundingBox(TriangleMesh{}), Error);
}

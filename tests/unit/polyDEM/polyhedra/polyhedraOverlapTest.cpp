// Tests of PolyhedronOverlap.hpp: overlap volume/centroid against CGAL's exact
// intersection, Feng's normal against the finite-difference gradient of V,
// degenerate configurations (coplanar faces, coincident edges and vertices,
// exact touching), walls (plane, triangles) and spheres.

#include "ExactIntersection.hpp"
#include "TestMeshes.hpp"

#include "ConvexShapeBuilder.hpp"
#include "ShapeGenerators.hpp"

#include "polyDEM/MeshQueries.hpp"
#include "polyDEM/WallDepths.hpp"
#include "polyDEM/WallSidePlanes.hpp"
#include "polyDEM/PolyhedronOverlap.hpp"

#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

using namespace polydem;

namespace
{

constexpr double pi = 3.14159265358979323846;

Quaternion randomRotation(std::mt19937_64& rng)
{
    std::normal_distribution<double> g;
    return normalised(Quaternion{g(rng), g(rng), g(rng), g(rng)});
}

Vec3 randomDirection(std::mt19937_64& rng)
{
    std::normal_distribution<double> g;
    const Vec3 v(g(rng), g(rng), g(rng));
    return v / norm(v);
}

std::vector<Vec3> worldVertices(const ConvexShape& s, const Vec3& pos, const Quaternion& q)
{
    std::vector<Vec3> w;
    for (const Vec3& v : s.vertices)
    {
        w.push_back(pos + rotate(q, v));
    }
    return w;
}

bool finite(const OverlapResult& r)
{
    return std::isfinite(r.volume) && std::isfinite(r.centroid.x) && std::isfinite(r.centroid.y)
           && std::isfinite(r.centroid.z) && std::isfinite(r.normal.x)
           && std::isfinite(r.normal.y) && std::isfinite(r.normal.z)
           && std::isfinite(r.contactArea);
}

struct Pose
{
    Vec3 pos;
    Quaternion q;
};

//- n random rocks (size, elongation, flatness, 8-34 hull points; seeds
//  firstSeed, firstSeed + 1, ...), drawn from rng
std::vector<ConvexShape> randomRocks(int n, int firstSeed, std::mt19937_64& rng)
{
    std::uniform_real_distribution<double> u(0, 1);
    std::vector<ConvexShape> rocks;
    for (int k = 0; k < n; ++k)
    {
        rocks.push_back(makeRock(0.5 + u(rng), 0.4 + 0.6 * u(rng), 0.4 + 0.6 * u(rng),
                                 8 + int(u(rng) * 27), firstSeed + k));
    }
    return rocks;
}

} // namespace


// 1000 random pairs of random rocks in random overlapping poses vs CGAL
TEST(polyhedraOverlap, randomRocksAgainstExactIntersection)
{
    std::mt19937_64 rng(2024);
    std::uniform_real_distribution<double> u(0, 1);
    const std::vector<ConvexShape> rocks = randomRocks(40, 1000, rng);

    double maxVolumeError = 0, maxCentroidError = 0, maxNormalError = 0, maxAreaError = 0;
    double timeOurs = 0, timeExact = 0;
    int pairs = 0, gradientChecks = 0;
    while (pairs < 1000)
    {
        const ConvexShape& A = rocks[rng() % rocks.size()];
        const ConvexShape& B = rocks[rng() % rocks.size()];
        const Pose pa{Vec3(u(rng), u(rng), u(rng)), randomRotation(rng)};
        const double reach = A.boundingRadius + B.boundingRadius;
        const Pose pb{pa.pos + (0.8 * reach * u(rng)) * randomDirection(rng), randomRotation(rng)};

        auto t0 = std::chrono::steady_clock::now();
        const OverlapResult r =
            polyhedronOverlap(A.view(), pa.pos, pa.q, B.view(), pb.pos, pb.q);
        auto t1 = std::chrono::steady_clock::now();
        const test::ExactOverlap ref =
            test::exactOverlap(worldVertices(A, pa.pos, pa.q), worldVertices(B, pb.pos, pb.q));
        auto t2 = std::chrono::steady_clock::now();
        timeOurs += std::chrono::duration<double>(t1 - t0).count();
        timeExact += std::chrono::duration<double>(t2 - t1).count();

        ASSERT_TRUE(finite(r));
        const double minVolume = std::min(A.volume, B.volume);
        if (ref.volume <= 1e-9 * minVolume)
        {
            // Separate or grazing: we must agree that the contact is negligible
            EXPECT_LE(r.volume, 1e-9 * minVolume);
            continue;
        }
        ++pairs;
        ASSERT_TRUE(r.touching);
        const double volumeError = std::fabs(r.volume - ref.volume) / ref.volume;
        const double centroidError = norm(r.centroid - ref.centroid) / std::cbrt(ref.volume);
        maxVolumeError = std::max(maxVolumeError, volumeError);
        maxCentroidError = std::max(maxCentroidError, centroidError);
        EXPECT_LT(volumeError, 1e-9) << "pair " << pairs;
        EXPECT_LT(centroidError, 1e-9) << "pair " << pairs;

        // Swapping A and B: same volume, opposite normal (unless one shape is
        // inside the other, where S = 0 and the normal is the centre line)
        const OverlapResult rs =
            polyhedronOverlap(B.view(), pb.pos, pb.q, A.view(), pa.pos, pa.q);
        EXPECT_NEAR(rs.volume, r.volume, 1e-12 * r.volume);
        if (r.contactArea > 1e-6 * std::min(A.surfaceArea, B.surfaceArea))
        {
            EXPECT_LT(norm(rs.normal + r.normal), 1e-9);
        }

        // Feng's normal: S = -dV/dx_B by central differences (every 5th pair)
        if (pairs % 5 == 0)
        {
            const double h = 1e-6 * std::cbrt(minVolume);
            Vec3 grad;
            for (int j = 0; j < 3; ++j)
            {
                Vec3 e;
                e[j] = h;
                const double vp =
                    polyhedronOverlap(A.view(), pa.pos, pa.q, B.view(), pb.pos + e, pb.q).volume;
                const double vm =
                    polyhedronOverlap(A.view(), pa.pos, pa.q, B.view(), pb.pos - e, pb.q).volume;
                grad[j] = (vp - vm) / (2 * h);
            }
            const double gNorm = norm(grad);
            if (gNorm > 1e-6 * r.contactArea + 1e-300)
            {
                ++gradientChecks;
                const double normalError = norm(r.normal + grad / gNorm);
                const double areaError = std::fabs(r.contactArea - gNorm) / gNorm;
                maxNormalError = std::max(maxNormalError, normalError);
                maxAreaError = std::max(maxAreaError, areaError);
                EXPECT_LT(normalError, 1e-5) << "pair " << pairs;
                EXPECT_LT(areaError, 1e-5) << "pair " << pairs;
            }
        }
    }
    std::printf("[ polyhedra ] %d pairs: max rel. volume error %.3g, max centroid error / V^(1/3) "
                "%.3g\n[ polyhedra ] %d gradient checks: max |n - (-grad V)/|grad V|| %.3g, "
                "max rel. |S| error %.3g\n[ polyhedra ] time per overlap: ours %.3g us, CGAL "
                "exact %.3g us (incl. misses)\n",
                pairs, maxVolumeError, maxCentroidError, gradientChecks, maxNormalError,
                maxAreaError, 1e6 * timeOurs / pairs, 1e6 * timeExact / pairs);
}


// Shallow contacts, as in a settled pile (overlap 1e-2 to 1e-6 of the smaller
// volume, 100 each, found by bisection along a random direction): the
// clipping is restricted to a thin slab and to the planes that reach into it,
// so this is where a plane left out or a vertex made by the slab would show,
// against CGAL's exact intersection. hint: the engine's cached axis for a pair
// that touched at its last evaluation, along which the slab is then taken:
// none (line of centres), the normal turned by up to ~10 degrees (last step's),
// or a random direction (any axis bounds the intersection)
namespace
{

enum class SlabHint { none, turnedNormal, randomAxis };

void checkShallowContacts(SlabHint hint, const char* label)
{
    std::mt19937_64 rng(77);
    std::uniform_real_distribution<double> u(0, 1);
    const std::vector<ConvexShape> rocks = randomRocks(10, 2000, rng);
    double maxVolumeError = 0, maxCentroidError = 0;
    int pairs = 0;
    for (const double fraction : {1e-2, 1e-4, 1e-6})
    {
        for (int k = 0; k < 100; ++k)
        {
            const ConvexShape& A = rocks[rng() % rocks.size()];
            const ConvexShape& B = rocks[rng() % rocks.size()];
            const Pose pa{Vec3(0, 0, 0), randomRotation(rng)};
            const Quaternion qb = randomRotation(rng);
            const Vec3 dir = randomDirection(rng);
            const double target = fraction * std::min(A.volume, B.volume);
            double lo = 0, hi = A.boundingRadius + B.boundingRadius;
            for (int it = 0; it < 80; ++it)
            {
                const double mid = 0.5 * (lo + hi);
                const double v = polyhedronOverlap(A.view(), pa.pos, pa.q, B.view(), mid * dir, qb).volume;
                (v > target ? lo : hi) = mid;
            }
            const Pose pb{lo * dir, qb};
            OverlapResult r = polyhedronOverlap(A.view(), pa.pos, pa.q, B.view(), pb.pos, pb.q);
            if (hint != SlabHint::none)
            {
                Vec3 axis = hint == SlabHint::randomAxis ? randomDirection(rng)
                                                          : r.normal + 0.18 * randomDirection(rng);
                r = polyhedronOverlap(A.view(), pa.pos, pa.q, B.view(), pb.pos, pb.q, &axis, false, true);
            }
            const test::ExactOverlap ref =
                test::exactOverlap(worldVertices(A, pa.pos, pa.q), worldVertices(B, pb.pos, pb.q));
            ASSERT_TRUE(r.touching);
            ASSERT_GT(ref.volume, 0.5 * target);
            ++pairs;
            const double volumeError = std::fabs(r.volume - ref.volume) / ref.volume;
            const double centroidError = norm(r.centroid - ref.centroid) / std::cbrt(ref.volume);
            maxVolumeError = std::max(maxVolumeError, volumeError);
            maxCentroidError = std::max(maxCentroidError, centroidError);
            EXPECT_LT(volumeError, 1e-10) << label << " fraction " << fraction << " pair " << k;
            EXPECT_LT(centroidError, 1e-10) << label << " fraction " << fraction << " pair " << k;
        }
    }
    std::printf("[ polyhedra ] %d shallow contacts, %s: max rel. volume error %.3g, max centroid "
                "error / V^(1/3) %.3g\n", pairs, label, maxVolumeError, maxCentroidError);
}

} // namespace


TEST(polyhedraOverlap, shallowContactsAgainstExactIntersection)
{
    checkShallowContacts(SlabHint::none, "slab along the line of centres");
}


// A pair that touched before is clipped in a slab along its cached normal
TEST(polyhedraOverlap, shallowContactsAlongCachedNormal)
{
    checkShallowContacts(SlabHint::turnedNormal, "slab along last step's normal");
    checkShallowContacts(SlabHint::randomAxis, "slab along a random axis");
}


// Separated pairs: SAT with and without a cached axis, edge axes on and off
TEST(polyhedraOverlap, separatingAxisWarmStart)
{
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(0, 1);
    const ConvexShape A = makeRock(1.0, 0.7, 0.6, 24, 3);
    const ConvexShape B = makeRock(0.8, 0.5, 0.9, 18, 4);
    int separatedByCache = 0;
    for (int k = 0; k < 300; ++k)
    {
        const Pose pa{Vec3(0, 0, 0), randomRotation(rng)};
        const Pose pb{(1.2 * u(rng) * (A.boundingRadius + B.boundingRadius)) * randomDirection(rng),
                      randomRotation(rng)};
        Vec3 axis;
        const OverlapResult r0 = polyhedronOverlap(A.view(), pa.pos, pa.q, B.view(), pb.pos, pb.q,
                                                   &axis, false);
        const OverlapResult r1 = polyhedronOverlap(A.view(), pa.pos, pa.q, B.view(), pb.pos, pb.q,
                                                   nullptr, true);
        EXPECT_EQ(r0.touching, r1.touching);
        EXPECT_EQ(r0.volume, r1.volume);
        // Second call with the cached axis: same answer
        Vec3 axis2 = axis;
        const OverlapResult r2 = polyhedronOverlap(A.view(), pa.pos, pa.q, B.view(), pb.pos, pb.q,
                                                   &axis2, false);
        EXPECT_EQ(r0.touching, r2.touching);
        EXPECT_EQ(r0.volume, r2.volume);
        if (!r0.touching && normSqr(axis) > 0)
        {
            ++separatedByCache;
        }
    }
    EXPECT_GT(separatedByCache, 0);
}


// A pair that touched at its last evaluation skips the separating-axis tests
// and is clipped in a slab along its cached normal (the engine passes
// touchedBefore with it). Touching and separated pairs, shallow and deep: the
// same classification, a pair that has come apart found apart by the clipping
// alone, and the same overlap to round-off. (Until the slab followed the
// normal this held bit for bit: only the early outs differed.)
TEST(polyhedraOverlap, touchedBeforeAgreesToRoundOff)
{
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(0, 1);
    const ConvexShape A = makeRock(1.0, 0.7, 0.6, 24, 5);
    const ConvexShape B = makeRock(0.8, 0.5, 0.9, 18, 6);
    int touching = 0, apart = 0;
    double maxVolume = 0, maxCentroid = 0, maxArea = 0;
    for (int k = 0; k < 2000; ++k)
    {
        const Pose pa{Vec3(0, 0, 0), randomRotation(rng)};
        const Pose pb{(u(rng) * (A.boundingRadius + B.boundingRadius)) * randomDirection(rng),
                      randomRotation(rng)};
        Vec3 axis;
        const OverlapResult r0 = polyhedronOverlap(A.view(), pa.pos, pa.q, B.view(), pb.pos, pb.q,
                                                   &axis, false);
        // As the engine does it: last step's normal, or (for a pair that has
        // just come apart) a stale normal from a nearby pose
        Vec3 hint = r0.touching ? r0.normal : randomDirection(rng);
        const OverlapResult r1 = polyhedronOverlap(A.view(), pa.pos, pa.q, B.view(), pb.pos, pb.q,
                                                   &hint, false, true);
        ASSERT_EQ(r0.touching, r1.touching) << "pose " << k;
        if (!r0.touching)
        {
            EXPECT_EQ(r1.volume, 0.0);
            ++apart;
            continue;
        }
        ++touching;
        // Relative to the overlap's own size (round-off of the face sums)
        const double L = std::cbrt(r0.volume);
        maxVolume = std::max(maxVolume, std::fabs(r1.volume - r0.volume) / r0.volume);
        maxCentroid = std::max(maxCentroid, norm(r1.centroid - r0.centroid) / L);
        maxArea = std::max(maxArea, norm(r1.areaVector - r0.areaVector) / (L * L));
        EXPECT_NEAR(r1.volume, r0.volume, 1e-11 * r0.volume) << "pose " << k;
        EXPECT_LT(norm(r1.centroid - r0.centroid), 1e-11 * L) << "pose " << k;
        EXPECT_LT(norm(r1.areaVector - r0.areaVector), 1e-10 * L * L) << "pose " << k;
    }
    std::printf("[ polyhedra ] touchedBefore: %d touching, %d apart; max relative differences: "
                "volume %.3g, centroid %.3g, area vector %.3g\n", touching, apart, maxVolume,
                maxCentroid, maxArea);
    EXPECT_GT(touching, 100);
    EXPECT_GT(apart, 100);
}


// Identical aligned cubes: coplanar faces of the same orientation everywhere
TEST(polyhedraOverlap, alignedCubesFaceToFace)
{
    const ConvexShape cube = makeCube(1.0);
    const Quaternion q;
    for (double dx : {0.0, 1e-14, 1e-9, 0.25, 0.5, 1 - 1e-9})
    {
        for (double dy : {0.0, 1e-12, 0.3})
        {
            const OverlapResult r =
                polyhedronOverlap(cube.view(), Vec3(0, 0, 0), q, cube.view(), Vec3(dx, dy, 0), q);
            ASSERT_TRUE(finite(r));
            const double expected = (1 - dx) * (1 - dy);
            EXPECT_NEAR(r.volume, expected, 1e-12) << dx << ' ' << dy;
            EXPECT_NEAR(r.centroid.x, 0.5 * dx, 1e-12);
            EXPECT_NEAR(r.centroid.y, 0.5 * dy, 1e-12);
            EXPECT_NEAR(r.centroid.z, 0.0, 1e-12);
            EXPECT_NEAR(norm(r.normal), 1.0, 1e-12);
            // (a shift below the plane tolerance 1e-12 counts as none: S = 0)
            if (dx > 1e-10 && dy == 0)
            {
                EXPECT_NEAR(r.normal.x, 1.0, 1e-12);
                EXPECT_NEAR(r.contactArea, 1.0, 1e-12); // the 1 x 1 face of B inside A
            }
        }
    }
    // Exactly face to face, and apart
    for (double dx : {1.0, 1.0 + 1e-15, 2.0})
    {
        const OverlapResult r =
            polyhedronOverlap(cube.view(), Vec3(0, 0, 0), q, cube.view(), Vec3(dx, 0.3, 0.1), q);
        ASSERT_TRUE(finite(r));
        EXPECT_FALSE(r.touching);
        EXPECT_EQ(r.volume, 0.0);
    }
}


// Coincident edges and vertices: a cube turned by 45 degrees pushing its edge
// into another cube's face (top and bottom faces coplanar), vertex on vertex
TEST(polyhedraOverlap, coincidentEdgesAndVertices)
{
    const ConvexShape cube = makeCube(1.0);
    const Quaternion q45 = fromAxisAngle(Vec3(0, 0, 1), 0.25 * pi);
    const double halfDiagonal = std::sqrt(0.5);
    double previous = -1;
    for (int k = -3; k <= 40; ++k)
    {
        const double depth = 1e-3 * k; // of the edge past A's face x = 0.5
        const Vec3 pos(0.5 + halfDiagonal - depth, 0, 0);
        const OverlapResult r = polyhedronOverlap(cube.view(), Vec3(), Quaternion(), cube.view(),
                                                  pos, q45);
        ASSERT_TRUE(finite(r));
        const double expected = depth > 0 ? depth * depth : 0.0; // wedge: base 2d, height d, length 1
        EXPECT_NEAR(r.volume, expected, 1e-12 + 1e-10 * expected) << depth;
        EXPECT_EQ(r.touching, depth > 0);
        if (depth > 0)
        {
            EXPECT_NEAR(r.normal.x, 1.0, 1e-10);
            EXPECT_NEAR(r.contactArea, 2 * depth, 1e-10);
            EXPECT_NEAR(r.centroid.x, 0.5 - depth / 3, 1e-10);
            EXPECT_GE(r.volume, previous); // continuous and monotone
        }
        previous = r.volume;
    }
    // Vertex exactly on vertex (both cubes axis aligned, diagonal neighbours)
    const OverlapResult rv = polyhedronOverlap(cube.view(), Vec3(), Quaternion(), cube.view(),
                                               Vec3(1, 1, 1), Quaternion());
    ASSERT_TRUE(finite(rv));
    EXPECT_FALSE(rv.touching);
    // Edge exactly on edge
    const OverlapResult re = polyhedronOverlap(cube.view(), Vec3(), Quaternion(), cube.view(),
                                               Vec3(1, 1, 0.3), Quaternion());
    ASSERT_TRUE(finite(re));
    EXPECT_FALSE(re.touching);
    // Vertex of a turned cube exactly on a face, then slightly in
    const Quaternion qv = normalised(fromAxisAngle(Vec3(1, -1, 0), std::atan(std::sqrt(2.0))));
    const double tip = 0.5 * std::sqrt(3.0);
    for (double depth : {0.0, 1e-6, 1e-3})
    {
        const OverlapResult r = polyhedronOverlap(cube.view(), Vec3(), Quaternion(), cube.view(),
                                                  Vec3(0, 0, 0.5 + tip - depth), qv);
        ASSERT_TRUE(finite(r));
        // A corner of a cube cut at depth d along its diagonal: V = sqrt(3)/2 d^3
        const double expected = 0.5 * std::sqrt(3.0) * depth * depth * depth;
        EXPECT_NEAR(r.volume, expected, 1e-12 * (1 + expected));
        if (depth >= 1e-3)
        {
            EXPECT_NEAR(r.normal.z, 1.0, 1e-9);
        }
    }
}


// Feng's normal is continuous when the contact switches between edge-edge
// and vertex-face: sweep a rock past another and watch n and V
TEST(polyhedraOverlap, continuityAlongSweep)
{
    const ConvexShape A = makeRock(1.0, 0.8, 0.7, 20, 11);
    const ConvexShape B = makeRock(1.0, 0.6, 0.8, 16, 12);
    std::mt19937_64 rng(5);
    for (int trial = 0; trial < 5; ++trial)
    {
        const Quaternion qa = randomRotation(rng), qb = randomRotation(rng);
        const Vec3 dir = randomDirection(rng);
        const Vec3 side = cross(dir, randomDirection(rng));
        const double reach = A.boundingRadius + B.boundingRadius;
        const int n = 2000;
        OverlapResult prev;
        Vec3 prevPos;
        for (int k = 0; k <= n; ++k)
        {
            const double s = reach * (1.0 - 0.5 * k / n);
            const Vec3 pos = s * dir + (0.1 * std::sin(0.01 * k)) * side;
            const OverlapResult r = polyhedronOverlap(A.view(), Vec3(), qa, B.view(), pos, qb);
            ASSERT_TRUE(finite(r));
            if (prev.touching && r.touching)
            {
                const double step = norm(pos - prevPos);
                EXPECT_LT(std::fabs(r.volume - prev.volume), 2.0 * r.contactArea * step + 1e-15);
                EXPECT_GT(dot(r.normal, prev.normal), 0.9);
            }
            prev = r;
            prevPos = pos;
        }
    }
}


TEST(polyhedraOverlap, cubeOnPlane)
{
    const ConvexShape cube = makeCube(1.0);
    const Vec3 up(0, 0, 1);
    // Exactly touching: nothing
    OverlapResult r = polyhedronPlaneOverlap(cube.view(), Vec3(0.2, 0.3, 0.5), Quaternion(),
                                             Vec3(0, 0, 0), up);
    ASSERT_TRUE(finite(r));
    EXPECT_FALSE(r.touching);
    for (double depth : {1e-9, 1e-3, 0.2, 0.7})
    {
        r = polyhedronPlaneOverlap(cube.view(), Vec3(0.2, 0.3, 0.5 - depth), Quaternion(),
                                   Vec3(5, -3, 0), up);
        ASSERT_TRUE(finite(r));
        EXPECT_TRUE(r.touching);
        EXPECT_NEAR(r.volume, depth, 1e-12);
        EXPECT_NEAR(r.centroid.x, 0.2, 1e-12);
        EXPECT_NEAR(r.centroid.y, 0.3, 1e-12);
        EXPECT_NEAR(r.centroid.z, -0.5 * depth, 1e-12);
        EXPECT_NEAR(r.normal.z, 1.0, 1e-12);
        EXPECT_NEAR(r.contactArea, 1.0, 1e-12);
    }
    // Tilted plane, turned cube: compare with the exact reference via a big box
    std::mt19937_64 rng(9);
    const ConvexShape rock = makeRock(1.0, 0.7, 0.5, 22, 8);
    for (int k = 0; k < 50; ++k)
    {
        const Vec3 n = randomDirection(rng);
        const Quaternion q = randomRotation(rng);
        const Vec3 pos = (0.2 * rock.boundingRadius) * n + Vec3(0.1, 0.2, 0.3);
        const Vec3 p0(0.1, 0.2, 0.3);
        r = polyhedronPlaneOverlap(rock.view(), pos, q, p0, n);
        // Reference: the half-space as a large cube sharing the plane
        const ConvexShape big = makeCube(20.0);
        Vec3 e1, e2;
        const Vec3 a = std::fabs(n.x) < 0.6 ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
        e1 = cross(a, n) / norm(cross(a, n));
        e2 = cross(n, e1);
        Matrix3 R;
        for (int i = 0; i < 3; ++i)
        {
            R.m[i][0] = e1[i];
            R.m[i][1] = e2[i];
            R.m[i][2] = n[i];
        }
        const test::ExactOverlap ref = test::exactOverlap(
            worldVertices(big, p0 - 10.0 * n, quaternionOfRotation(R)), worldVertices(rock, pos, q));
        ASSERT_TRUE(r.touching);
        EXPECT_NEAR(r.volume, ref.volume, 1e-9 * ref.volume);
        EXPECT_LT(norm(r.centroid - ref.centroid), 1e-9);
        EXPECT_NEAR(dot(r.normal, n), 1.0, 1e-9);
    }
}


// A flat wall split into triangles gives what the plane gives
TEST(polyhedraOverlap, trianglesTileThePlane)
{
    const ConvexShape rock = makeRock(1.0, 0.8, 0.6, 20, 21);
    std::mt19937_64 rng(13);
    // A 4 x 4 square (z = 0) in 2 x 2 x 2 triangles, counter-clockwise seen from +z
    std::vector<std::array<Vec3, 3>> tris;
    for (int i = 0; i < 2; ++i)
    {
        for (int j = 0; j < 2; ++j)
        {
            const Vec3 a(-2 + 2 * i, -2 + 2 * j, 0), b = a + Vec3(2, 0, 0), c = a + Vec3(2, 2, 0),
                       d = a + Vec3(0, 2, 0);
            tris.push_back({a, b, c});
            tris.push_back({a, c, d});
        }
    }
    for (int k = 0; k < 50; ++k)
    {
        const Quaternion q = randomRotation(rng);
        const Vec3 pos(0.5 * (2 * (rng() % 1000) / 1000.0 - 1), 0.3, 0.3 * rock.boundingRadius);
        const OverlapResult plane =
            polyhedronPlaneOverlap(rock.view(), pos, q, Vec3(0, 0, 0), Vec3(0, 0, 1));
        double volume = 0;
        Vec3 moment, area;
        for (const auto& t : tris)
        {
            const OverlapResult r = polyhedronTriangleOverlap(rock.view(), pos, q, t[0], t[1], t[2]);
            ASSERT_TRUE(finite(r));
            if (r.touching)
            {
                volume += r.volume;
                moment += r.volume * r.centroid;
                area += r.areaVector;
            }
        }
        ASSERT_TRUE(plane.touching);
        EXPECT_NEAR(volume, plane.volume, 1e-12);
        EXPECT_LT(norm(moment / volume - plane.centroid), 1e-12);
        EXPECT_LT(norm(area - plane.areaVector), 1e-12);
    }
}


TEST(polyhedraOverlap, sphereAgainstPolyhedron)
{
    const ConvexShape cube = makeCube(1.0);
    const double R = 0.3;
    // Face contact: exact cap
    for (double depth : {0.0, 1e-6, 0.05, 0.2})
    {
        const OverlapResult r = polyhedronSphereOverlap(cube.view(), Vec3(), Quaternion(),
                                                        Vec3(0.1, 0.2, 0.5 + R - depth), R);
        ASSERT_TRUE(finite(r));
        const double expected = pi * depth * depth * (3 * R - depth) / 3;
        EXPECT_NEAR(r.volume, expected, 1e-14);
        EXPECT_EQ(r.touching, depth > 0);
        if (depth > 0)
        {
            EXPECT_NEAR(r.normal.z, 1.0, 1e-14);
            EXPECT_LT(r.centroid.z, 0.5);
            EXPECT_GT(r.centroid.z, 0.5 - depth);
        }
    }
    // Edge and vertex contacts: normal along the closest-point direction
    const Vec3 edgeDir = Vec3(1, 1, 0) / std::sqrt(2.0);
    const OverlapResult re = polyhedronSphereOverlap(
        cube.view(), Vec3(), Quaternion(), Vec3(0.5, 0.5, 0.1) + (R - 0.01) * edgeDir, R);
    ASSERT_TRUE(re.touching);
    EXPECT_LT(norm(re.normal - edgeDir), 1e-12);
    // Centre inside the cube: leaves through the nearest face
    const OverlapResult ri =
        polyhedronSphereOverlap(cube.view(), Vec3(), Quaternion(), Vec3(0.45, 0, 0), R);
    ASSERT_TRUE(ri.touching);
    EXPECT_NEAR(ri.normal.x, 1.0, 1e-14);
    // Far away
    EXPECT_FALSE(
        polyhedronSphereOverlap(cube.view(), Vec3(), Quaternion(), Vec3(2, 0, 0), R).touching);
}


TEST(polyhedraOverlap, packedTableMatchesShapes)
{
    std::vector<ConvexShape> shapes = {makeCube(1.0), makeRock(1.0, 0.7, 0.7, 30, 5),
                                       makeDodecahedron(2.0)};
    const PackedPolyhedra packed = packPolyhedra(shapes);
    const PolyhedronTable table = packed.table();
    ASSERT_EQ(table.nShapes, 3);
    for (int k = 0; k < 3; ++k)
    {
        const ConvexPolyhedron v = table.shape(k), w = shapes[k].view();
        ASSERT_EQ(v.nVertices, w.nVertices);
        ASSERT_EQ(v.nFaces, w.nFaces);
        ASSERT_EQ(v.nEdges, w.nEdges);
        for (int f = 0; f < v.nFaces; ++f)
        {
            ASSERT_EQ(v.faceSize(f), w.faceSize(f));
            for (int i = 0; i < v.faceSize(f); ++i)
            {
                EXPECT_EQ(v.faceVertexPoint(f, i).x, w.faceVertexPoint(f, i).x);
            }
        }
        EXPECT_EQ(v.volume, w.volume);
        EXPECT_EQ(v.boundingRadius, w.boundingRadius);
    }
    // Overlap through the table equals overlap through the shapes
    const OverlapResult a = polyhedronOverlap(table.shape(1), Vec3(), Quaternion(), table.shape(2),
                                              Vec3(0.9, 0.1, 0), Quaternion());
    const OverlapResult b = polyhedronOverlap(shapes[1].view(), Vec3(), Quaternion(),
                                              shapes[2].view(), Vec3(0.9, 0.1, 0), Quaternion());
    EXPECT_EQ(a.volume, b.volume);
}



// A closed body's prisms stop at its middle: wallDepths of a slab is half
// its smallest thickness on every face (the radius of the largest ball
// inside it), and an open surface (the inside of a container) has no floor
TEST(polyhedraOverlap, wallDepthsOfClosedAndOpenSurfaces)
{
    const TriangleMesh slab = test::closedBox(Vec3(-1, -0.05, -0.25), Vec3(1, 0.05, 0.25));
    ASSERT_TRUE(isClosed(slab));
    ASSERT_GT(enclosedVolume(slab), 0);
    const std::vector<double> depth = wallDepths(slab);
    ASSERT_EQ(depth.size(), slab.size());
    for (std::size_t t = 0; t < depth.size(); ++t)
    {
        // Never deeper than half the thickness; up to 2 % less on the end
        // faces, whose best sample point (5 % in from an edge midpoint) lies
        // 0.8 mm off the slab's middle plane
        EXPECT_LE(depth[t], 0.05 * (1 + 1e-12)) << "triangle " << t;
        EXPECT_GE(depth[t], 0.05 * 0.98) << "triangle " << t;
    }
    // Capped: no floor deeper than maxDepth
    for (double d : wallDepths(slab, 0.02))
    {
        EXPECT_EQ(d, 0.02);
    }
    // The same box seen from inside (a container): the solid is outside, and
    // no ray into it meets the surface again
    TriangleMesh container = slab;
    for (auto& t : container.triangles) std::swap(t[1], t[2]);
    for (double d : wallDepths(container))
    {
        EXPECT_EQ(d, kUnboundedWallDepth);
    }
}


// A particle beside a thin closed body, or pressed into it less than half
// its thickness, overlaps the triangles by exactly its overlap with the
// body (CGAL); without the floors, the far face's prism reaches through the
// body onto it (the brash-ice hull's phantom contacts, which this guards)
TEST(polyhedraOverlap, thinClosedBodyHasNoFarSideOverlap)
{
    const Vec3 lo(-1, -0.05, -0.25), hi(1, 0.05, 0.25);
    const TriangleMesh slab = test::closedBox(lo, hi);
    const std::vector<double> depth = wallDepths(slab);
    std::vector<Vec3> slabVertices = slab.points;
    const ConvexShape rock = makeRock(0.08, 0.8, 0.6, 20, 5);
    std::mt19937_64 rng(29);
    std::uniform_real_distribution<double> u(0, 1);
    int beside = 0, pressed = 0, farSide = 0;
    double maxError = 0;
    for (int k = 0; k < 300; ++k)
    {
        const Quaternion q = randomRotation(rng);
        // Centre in front of the y = lo.y face, from 2 cm into it to 6 cm
        // out, away from the face's edges
        const Vec3 pos(-0.5 + u(rng), lo.y - 0.06 + 0.08 * u(rng), -0.1 + 0.2 * u(rng));
        double deepest = -1e300;   // how far the rock reaches past the face
        for (const Vec3& v : worldVertices(rock, pos, q)) deepest = std::max(deepest, v.y - lo.y);
        if (deepest >= 0.05) continue;   // past the middle: the other face's
        double volume = 0, unbounded = 0;
        for (std::size_t t = 0; t < slab.size(); ++t)
        {
            const auto& tri = slab.triangles[t];
            const Vec3 &a = slab.points[tri[0]], &b = slab.points[tri[1]], &c = slab.points[tri[2]];
            const OverlapResult r = polyhedronTriangleOverlap(rock.view(), pos, q, a, b, c, depth[t]);
            ASSERT_TRUE(finite(r));
            if (r.touching) volume += r.volume;
            const OverlapResult r0 = polyhedronTriangleOverlap(rock.view(), pos, q, a, b, c);
            if (r0.touching) unbounded += r0.volume;
        }
        const test::ExactOverlap ref = test::exactOverlap(worldVertices(rock, pos, q), slabVertices);
        const double error = std::fabs(volume - ref.volume) / rock.volume;
        maxError = std::max(maxError, error);
        EXPECT_LT(error, 1e-12) << "pose " << k << ": " << volume << " against " << ref.volume;
        ref.volume > 0 ? ++pressed : ++beside;
        if (unbounded > ref.volume + 0.01 * rock.volume) ++farSide;
    }
    std::printf("thin body: %d poses beside, %d pressed in; volume error %.2e of the rock's;"
                " without floors %d poses gain > 1 %% phantom overlap\n",
                beside, pressed, maxError, farSide);
    EXPECT_GT(beside, 30);
    EXPECT_GT(pressed, 50);
    // The test can fail: the unbounded prisms do count the far face
    EXPECT_GT(farSide, 50);
}


namespace
{

//- A rock posed near a random corner of the box [lo, hi]: along each axis
//  from `out` outside the corner's face to `in` inside it
Vec3 nearCorner(const Vec3& lo, const Vec3& hi, double out, double in, std::mt19937_64& rng)
{
    std::uniform_real_distribution<double> u(0, 1);
    const int corner = int(rng() % 8);
    Vec3 pos;
    for (int d = 0; d < 3; ++d)
    {
        const bool high = corner & (1 << d);
        const double c = high ? hi[d] : lo[d];
        const double inward = high ? -1.0 : 1.0;
        pos[d] = c + inward * (-out + (out + in) * u(rng));
    }
    return pos;
}

struct TriangleSum
{
    double volume = 0;
    Vec3 moment;
};

//- The overlaps of P with every triangle of mesh, added (sides null: each
//  triangle's normal prism)
TriangleSum overTriangles(const ConvexShape& P, const Vec3& pos, const Quaternion& q,
                          const TriangleMesh& mesh, const std::vector<double>& depth,
                          const WallSidePlanes* sides)
{
    TriangleSum sum;
    for (std::size_t t = 0; t < mesh.size(); ++t)
    {
        const auto& tri = mesh.triangles[t];
        const int s0 = sides ? sides->start[t] : 0;
        const OverlapResult r = polyhedronTriangleOverlap(
            P.view(), pos, q, mesh.points[tri[0]], mesh.points[tri[1]], mesh.points[tri[2]], depth[t],
            sides ? sides->normal.data() + s0 : nullptr, sides ? sides->offset.data() + s0 : nullptr,
            sides ? sides->start[t + 1] - s0 : 0);
        EXPECT_TRUE(finite(r));
        if (r.touching)
        {
            sum.volume += r.volume;
            sum.moment += r.volume * r.centroid;
        }
    }
    return sum;
}

} // namespace


// At the edges and corners of a closed box (convex edges: a hull's bilge,
// a lifter's edge) the triangles' solids, bounded by the bisectors of their
// edges (WallSidePlanes.hpp), partition the body: a rock there overlaps them
// by exactly its overlap with the box (CGAL), volume and centroid. The
// triangles' normal prisms overlap each other there and count that part
// twice, which the test also shows
TEST(polyhedraOverlap, convexEdgesAndCornersOfClosedBody)
{
    const Vec3 lo(-0.3, -0.2, -0.15), hi(0.3, 0.2, 0.15);
    const TriangleMesh box = test::closedBox(lo, hi);
    const std::vector<double> depth = wallDepths(box);
    const WallSidePlanes sides = wallSidePlanes(box);
    const ConvexShape rock = makeRock(0.08, 0.8, 0.6, 20, 7);
    std::mt19937_64 rng(31);
    int touching = 0, prismsOver = 0;
    double maxVolumeError = 0, maxCentroidError = 0, worstPrism = 0;
    for (int k = 0; k < 400; ++k)
    {
        const Quaternion q = randomRotation(rng);
        const Vec3 pos = nearCorner(lo, hi, 0.05, 0.06, rng);
        const test::ExactOverlap ref = test::exactOverlap(worldVertices(rock, pos, q), box.points);
        const TriangleSum sum = overTriangles(rock, pos, q, box, depth, &sides);
        const double error = std::fabs(sum.volume - ref.volume) / rock.volume;
        maxVolumeError = std::max(maxVolumeError, error);
        EXPECT_LT(error, 1e-12) << "pose " << k << ": " << sum.volume << " against " << ref.volume;
        if (ref.volume > 1e-3 * rock.volume)
        {
            ++touching;
            const double centroidError = norm(sum.moment / sum.volume - ref.centroid) / 0.08;
            maxCentroidError = std::max(maxCentroidError, centroidError);
            EXPECT_LT(centroidError, 1e-9) << "pose " << k;
        }
        const TriangleSum prisms = overTriangles(rock, pos, q, box, depth, nullptr);
        const double over = (prisms.volume - ref.volume) / rock.volume;
        worstPrism = std::max(worstPrism, over);
        if (over > 0.01) ++prismsOver;
    }
    std::printf("closed box, near its corners: %d poses overlapping; volume error %.2e of the rock's,"
                " centroid %.2e of its size; normal prisms: %d poses over by > 1 %% of the rock"
                " (at most %.3f)\n",
                touching, maxVolumeError, maxCentroidError, prismsOver, worstPrism);
    EXPECT_GT(touching, 150);
    // The test can fail: the normal prisms count the edges twice
    EXPECT_GT(prismsOver, 50);
}


// In the inside corners of a container (concave edges, the solid outside
// the box) the bisectors give the wedge below two faces to one of them: a
// rock poking into a corner overlaps the triangles by exactly its volume
// outside the box. The normal prisms leave that wedge to neither
TEST(polyhedraOverlap, concaveEdgesAndCornersOfContainer)
{
    const Vec3 lo(-0.3, -0.2, -0.15), hi(0.3, 0.2, 0.15);
    TriangleMesh container = test::closedBox(lo, hi);
    for (auto& t : container.triangles) std::swap(t[1], t[2]);
    const std::vector<double> depth = wallDepths(container);
    const WallSidePlanes sides = wallSidePlanes(container);
    const ConvexShape rock = makeRock(0.08, 0.8, 0.6, 20, 7);
    std::mt19937_64 rng(37);
    int touching = 0, prismsUnder = 0;
    double maxVolumeError = 0, maxCentroidError = 0;
    for (int k = 0; k < 400; ++k)
    {
        const Quaternion q = randomRotation(rng);
        // Centre from 2 cm outside the corner's faces to 8 cm inside
        const Vec3 pos = nearCorner(lo, hi, 0.02, 0.08, rng);
        const test::ExactOverlap inside = test::exactOverlap(worldVertices(rock, pos, q), container.points);
        const double volume = rock.volume - inside.volume;
        const TriangleSum sum = overTriangles(rock, pos, q, container, depth, &sides);
        const double error = std::fabs(sum.volume - volume) / rock.volume;
        maxVolumeError = std::max(maxVolumeError, error);
        EXPECT_LT(error, 1e-12) << "pose " << k << ": " << sum.volume << " against " << volume;
        if (volume > 1e-3 * rock.volume)
        {
            ++touching;
            const Vec3 centroid = (rock.volume * pos - inside.volume * inside.centroid) / volume;
            const double centroidError = norm(sum.moment / sum.volume - centroid) / 0.08;
            maxCentroidError = std::max(maxCentroidError, centroidError);
            EXPECT_LT(centroidError, 1e-9) << "pose " << k;
        }
        const TriangleSum prisms = overTriangles(rock, pos, q, container, depth, nullptr);
        if (volume - prisms.volume > 0.01 * rock.volume) ++prismsUnder;
    }
    std::printf("container, in its corners: %d poses overlapping; volume error %.2e of the rock's,"
                " centroid %.2e of its size; normal prisms: %d poses under by > 1 %% of the rock\n",
                touching, maxVolumeError, maxCentroidError, prismsUnder);
    EXPECT_GT(touching, 150);
    EXPECT_GT(prismsUnder, 30);
}


// A particle face lying exactly in a bisector plane (a cube turned 45
// degrees about a box's edge, its face through the edge, on either side):
// that face carries flux and must be kept, not dropped as a face coplanar
// with a clipping plane is (an earlier version lost half the overlap)
TEST(polyhedraOverlap, faceInBisectorPlane)
{
    const Vec3 lo(-0.3, -0.2, -0.15), hi(0.3, 0.2, 0.15);
    const TriangleMesh box = test::closedBox(lo, hi);
    const std::vector<double> depth = wallDepths(box);
    const WallSidePlanes sides = wallSidePlanes(box);
    const ConvexShape cube = makeCube(0.04);
    const Quaternion q{std::cos(pi / 8), 0, std::sin(pi / 8), 0};   // 45 degrees about y
    const Vec3 m(std::sqrt(0.5), 0, -std::sqrt(0.5));   // the top's bisector with the x = 0.3 face
    for (const double side : {1.0, -1.0})
    {
        // The face's centre on the bisector x - z = 0.15, 1 cm into the box
        const Vec3 pos = Vec3(0.29, 0, 0.14) - side * 0.02 * m;
        const test::ExactOverlap ref = test::exactOverlap(worldVertices(cube, pos, q), box.points);
        const TriangleSum sum = overTriangles(cube, pos, q, box, depth, &sides);
        EXPECT_NEAR(sum.volume, ref.volume, 1e-12 * cube.volume) << (side > 0 ? "top's side" : "side's side");
        EXPECT_LT(norm(sum.moment / sum.volume - ref.centroid), 1e-12) << (side > 0 ? "top's side" : "side's side");
    }
}

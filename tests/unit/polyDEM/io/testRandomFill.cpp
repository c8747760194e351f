// Tests of the size distributions, random sequential addition and lattice fills.

#include "TestMeshes.hpp"

#include "polyDEM/Error.hpp"
#include "polyDEM/MeshQueries.hpp"
#include "polyDEM/RandomFill.hpp"
#include "polyDEM/StlReader.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace polydem;
using namespace polydem::test;

namespace
{

constexpr double pi = 3.14159265358979323846;

// Pairwise (O(N^2), independent of the grid) smallest surface gap
double smallestGap(const std::vector<SphereSeed>& a, const std::vector<SphereSeed>& b = {})
{
    double g = 1e300;
    for (std::size_t i = 0; i < a.size(); ++i)
    {
        for (std::size_t j = i + 1; j < a.size(); ++j)
        {
            g = std::min(g, norm(a[i].position - a[j].position) - a[i].radius - a[j].radius);
        }
        for (const SphereSeed& o : b)
        {
            g = std::min(g, norm(a[i].position - o.position) - a[i].radius - o.radius);
        }
    }
    return g;
}

double solidVolume(const std::vector<SphereSeed>& s)
{
    double v = 0;
    for (const auto& p : s)
    {
        v += 4.0 / 3.0 * pi * std::pow(p.radius, 3);
    }
    return v;
}

void checkMoments(const SizeDistribution& d, double mean, double sd)
{
    std::mt19937_64 rng(42);
    const int n = 200000;
    double s = 0, s2 = 0;
    for (int i = 0; i < n; ++i)
    {
        const double x = d.sample(rng);
        ASSERT_GE(x, d.minDiameter());
        ASSERT_LE(x, d.maxDiameter());
        s += x;
        s2 += x * x;
    }
    const double m = s / n;
    const double v = s2 / n - m * m;
    // Five standard errors of the mean; the sd to a few per cent
    EXPECT_NEAR(m, mean, 5 * sd / std::sqrt(double(n)));
    EXPECT_NEAR(std::sqrt(std::max(v, 0.0)), sd, 0.02 * sd + 1e-15);
}

std::string entryOf(const std::function<void()>& f)
{
    try
    {
        f();
    }
    catch (const Error& e)
    {
        return e.entry();
    }
    return "<no error>";
}

} // namespace


TEST(SizeDistribution, moments)
{
    checkMoments(SizeDistribution::uniform(1e-3, 3e-3), 2e-3, 2e-3 / std::sqrt(12.0));
    // Truncation at +-4 sd barely changes the moments (sd factor 0.99945)
    checkMoments(SizeDistribution::normal(5e-3, 1e-3, 1e-3, 9e-3), 5e-3, 0.99945e-3);
    // Discrete: fractions are normalised (here 1:3)
    const double m = 0.25 * 1e-3 + 0.75 * 2e-3;
    const double sd = std::sqrt(0.25 * 1e-6 + 0.75 * 4e-6 - m * m);
    checkMoments(SizeDistribution::discrete({{1e-3, 1.0}, {2e-3, 3.0}}), m, sd);

    std::mt19937_64 rng(1);
    EXPECT_EQ(SizeDistribution::fixedDiameter(0.01).sample(rng), 0.01);
    // Half-normal: truncated at the mean, mean = mu + sd sqrt(2/pi)
    checkMoments(SizeDistribution::normal(1.0, 0.1, 1.0, 2.0), 1.0 + 0.1 * std::sqrt(2 / pi),
                 0.1 * std::sqrt(1 - 2 / pi));
}

TEST(SizeDistribution, validationNamesEntries)
{
    EXPECT_EQ(entryOf([] { SizeDistribution::fixedDiameter(-1); }), "diameter");
    EXPECT_EQ(entryOf([] { SizeDistribution::fixedDiameter(NAN); }), "diameter");
    EXPECT_EQ(entryOf([] { SizeDistribution::uniform(0, 1); }), "min");
    EXPECT_EQ(entryOf([] { SizeDistribution::uniform(2, 1); }), "max");
    EXPECT_EQ(entryOf([] { SizeDistribution::normal(1, -1, 0.5, 2); }), "sd");
    EXPECT_EQ(entryOf([] { SizeDistribution::normal(1, 0.01, 2, 3); }), "mean");
    EXPECT_EQ(entryOf([] { SizeDistribution::discrete({}); }), "fractions");
    EXPECT_EQ(entryOf([] { SizeDistribution::discrete({{1, 0}}); }), "fractions");
    EXPECT_EQ(entryOf([] { SizeDistribution::discrete({{1, 1}, {-1, 1}}); }), "fractions");
    EXPECT_EQ(entryOf([] { FillRegion::box({0, 0, 0}, {1, 0, 1}); }), "max");
}

TEST(RandomFill, boxNoOverlapInsideDeterministic)
{
    const FillRegion box = FillRegion::box({0, 0, 0}, {1, 1, 1});
    const SizeDistribution d = SizeDistribution::fixedDiameter(0.1);
    // Volume fraction 0.3: well within reach of random sequential addition
    const std::size_t n = std::size_t(0.3 / (pi / 6 * 1e-3));
    const auto a = randomFill(box, d, n, 2024);
    ASSERT_EQ(a.size(), n);
    EXPECT_GE(smallestGap(a), 0.0);
    for (const auto& s : a)
    {
        EXPECT_TRUE(box.contains(s.position, s.radius));
    }
    EXPECT_NEAR(solidVolume(a) / box.volume(), 0.3, 0.002);

    const auto b = randomFill(box, d, n, 2024);
    ASSERT_EQ(b.size(), n);
    for (std::size_t i = 0; i < n; ++i)
    {
        EXPECT_EQ(a[i].position.x, b[i].position.x);
        EXPECT_EQ(a[i].position.y, b[i].position.y);
        EXPECT_EQ(a[i].position.z, b[i].position.z);
    }
    const auto c = randomFill(box, d, n, 2025);
    EXPECT_NE(a[0].position.x, c[0].position.x);
}

TEST(RandomFill, polydisperseGapAndObstacles)
{
    const FillRegion box = FillRegion::box({0, 0, 0}, {1, 0.5, 0.5});
    const SizeDistribution d = SizeDistribution::uniform(0.02, 0.08);
    const auto first = randomFill(box, d, 300, 1, 0.005);
    ASSERT_EQ(first.size(), 300u);
    EXPECT_GE(smallestGap(first), 0.005 - 1e-15);
    // Largest first
    EXPECT_GE(first.front().radius, first.back().radius);

    // A second insertion avoids the first, and a big obstacle sphere
    std::vector<SphereSeed> obstacles = first;
    obstacles.push_back({{0.5, 0.25, 0.25}, 0.2});
    const auto second = randomFill(box, d, 200, 2, 0.0, obstacles);
    ASSERT_EQ(second.size(), 200u);
    EXPECT_GE(smallestGap(second, obstacles), 0.0);
}

TEST(RandomFill, tooManyThrowsWithProgress)
{
    const FillRegion box = FillRegion::box({0, 0, 0}, {0.5, 0.5, 0.5});
    try
    {
        randomFill(box, SizeDistribution::fixedDiameter(0.1), 1000, 3, 0, {}, 2000);
        FAIL() << "an impossible fill succeeded";
    }
    catch (const Error& e)
    {
        const std::string what = e.what();
        EXPECT_NE(what.find("placed only"), std::string::npos) << what;
        EXPECT_NE(what.find("of 1000 particles"), std::string::npos) << what;
        EXPECT_NE(what.find("volume fraction reached"), std::string::npos) << what;
    }
    // A particle larger than the region
    EXPECT_THROW(randomFill(box, SizeDistribution::fixedDiameter(0.6), 1, 3), Error);
}

TEST(RandomFill, insideStlCylinder)
{
    // Through a file, as a user would: write, read back, fill
    const std::string path = tempPath("cylinder.stl");
    writeStl(path, cylinder(0.5, 1.0, 48), true);
    const TriangleMesh cyl = readStl(path);
    std::remove(path.c_str());
    ASSERT_TRUE(isClosed(cyl));

    const FillRegion region = FillRegion::insideMesh(cyl);
    EXPECT_EQ(region.source, path);
    const SizeDistribution d = SizeDistribution::normal(0.06, 0.01, 0.04, 0.08);
    const auto s = randomFill(region, d, 600, 9);
    ASSERT_EQ(s.size(), 600u);
    EXPECT_GE(smallestGap(s), 0.0);
    for (const auto& p : s)
    {
        EXPECT_TRUE(insideClosedMesh(cyl, p.position));
        EXPECT_GE(distanceToSurface(cyl, p.position), p.radius);
        // And inside the true cylinder the mesh approximates (from inside)
        EXPECT_LE(std::hypot(p.position.x, p.position.y) + p.radius, 0.5 + 1e-12);
    }

    // Clipped to the lower half
    const FillRegion lower = FillRegion::insideMesh(cyl, {-1, -1, -1}, {1, 1, 0.5});
    EXPECT_NEAR(lower.volume(), 0.5 * std::abs(enclosedVolume(cyl)), 0.02);
    const auto t = randomFill(lower, d, 200, 10);
    for (const auto& p : t)
    {
        EXPECT_LE(p.position.z + p.radius, 0.5);
        EXPECT_GE(distanceToSurface(cyl, p.position), p.radius);
    }

    TriangleMesh open = cyl;
    open.triangles.pop_back();
    EXPECT_THROW(FillRegion::insideMesh(open), Error);
}

TEST(RandomFill, lattice)
{
    const FillRegion box = FillRegion::box({0, 0, 0}, {1, 1, 1});
    const auto all = fillLattice(box, 0.1, 0.1);
    EXPECT_EQ(all.size(), 1000u);
    EXPECT_GE(smallestGap(all), -1e-12);
    EXPECT_EQ(fillLattice(box, 0.1, 0.1, 123).size(), 123u);
    const auto sparse = fillLattice(box, 0.1, 0.2);
    EXPECT_EQ(sparse.size(), 125u);
    // Obstacle in the middle removes the sites it covers
    const auto holed = fillLattice(box, 0.1, 0.1, 0, {{{0.5, 0.5, 0.5}, 0.2}});
    EXPECT_LT(holed.size(), 1000u);
    EXPECT_GE(smallestGap(holed, {{{0.5, 0.5, 0.5}, 0.2}}), -1e-12);
    EXPECT_THROW(fillLattice(box, 0.1, 0.05), Error);
}

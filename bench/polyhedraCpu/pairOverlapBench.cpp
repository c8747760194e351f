// pairOverlapBench: time the polyhedron-polyhedron narrow phase alone
// (polyDEM::polyhedronOverlap) on pairs of the bench's rocks at the overlaps
// of a settled pile, one thread, as the pair kernel calls it for a pair that
// touched at the step before (its cached contact normal passed in).
//
// Usage: pairOverlapBench [--shapes FILE] [--pairs N] [--fraction F] [--repeat R]
//   N pairs (default 20000) of two random rocks of FILE (rocks.shapes) in random
//   orientations, B moved along a random direction until the overlap volume is
//   F (default 4e-3) of the smaller rock's: the overlap of a rock carrying a
//   few layers of the pile (Kv 4e7 N/m3). Seed 3, so every engine gets the
//   same pairs. The pairs are evaluated R times (default 20).
// Prints the sum of the overlap volumes (a check that two engines computed
// the same contacts) and, last, `us per touching pair: X`.
#include "polyDEM/PolyhedronOverlap.hpp"
#include "rockShapes.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

using namespace polydem;

namespace
{

struct PairPose
{
    int a = 0, b = 0;
    Vec3 posB;
    Quaternion qA, qB;
    Vec3 normal; //!< the contact normal, the pair kernel's cached axis
};

Quaternion randomRotation(std::mt19937_64& rng)
{
    std::uniform_real_distribution<double> u(0, 1);
    const double r = u(rng), s = u(rng), t = u(rng);
    Quaternion q;
    q.w = std::sqrt(1 - r) * std::sin(2 * M_PI * s);
    q.x = std::sqrt(1 - r) * std::cos(2 * M_PI * s);
    q.y = std::sqrt(r) * std::sin(2 * M_PI * t);
    q.z = std::sqrt(r) * std::cos(2 * M_PI * t);
    return q;
}

Vec3 randomDirection(std::mt19937_64& rng)
{
    std::uniform_real_distribution<double> u(0, 1);
    const double z = 2 * u(rng) - 1, phi = 2 * M_PI * u(rng);
    const double r = std::sqrt(1 - z * z);
    return Vec3(r * std::cos(phi), r * std::sin(phi), z);
}

// The engine passes touchedBefore for a pair that touched at its last
// evaluation; engines from before that argument have no such skip
OverlapResult evaluate(const ConvexPolyhedron& A, const ConvexPolyhedron& B, const PairPose& p, Vec3& axis)
{
#ifdef PD_OVERLAP_HAS_TOUCHED_BEFORE
    return polyhedronOverlap(A, Vec3(), p.qA, B, p.posB, p.qB, &axis, false, true);
#else
    return polyhedronOverlap(A, Vec3(), p.qA, B, p.posB, p.qB, &axis, false);
#endif
}

} // namespace

int main(int argc, char** argv)
{
    std::string shapesFile = "rocks.shapes";
    int nPairs = 20000, repeat = 20;
    double fraction = 4e-3;
    for (int i = 1; i < argc; ++i)
    {
        const std::string a = argv[i];
        if (a == "--shapes" && i + 1 < argc) shapesFile = argv[++i];
        else if (a == "--pairs" && i + 1 < argc) nPairs = std::atoi(argv[++i]);
        else if (a == "--fraction" && i + 1 < argc) fraction = std::atof(argv[++i]);
        else if (a == "--repeat" && i + 1 < argc) repeat = std::atoi(argv[++i]);
        else
        {
            std::fprintf(stderr, "usage: pairOverlapBench [--shapes FILE] [--pairs N] "
                                 "[--fraction F] [--repeat R]\n");
            return 2;
        }
    }
    const std::vector<ConvexShape> shapes = bench::readShapes(shapesFile);
    std::vector<ConvexPolyhedron> views;
    for (const ConvexShape& s : shapes) views.push_back(s.view());

    std::mt19937_64 rng(3);
    std::vector<PairPose> pairs;
    while (int(pairs.size()) < nPairs)
    {
        PairPose p;
        p.a = int(rng() % views.size());
        p.b = int(rng() % views.size());
        p.qA = randomRotation(rng);
        p.qB = randomRotation(rng);
        const Vec3 dir = randomDirection(rng);
        const ConvexPolyhedron& A = views[p.a];
        const ConvexPolyhedron& B = views[p.b];
        const double target = fraction * std::fmin(A.volume, B.volume);
        double lo = 0, hi = A.boundingRadius + B.boundingRadius;
        for (int it = 0; it < 60; ++it)
        {
            const double mid = 0.5 * (lo + hi);
            const double v = polyhedronOverlap(A, Vec3(), p.qA, B, mid * dir, p.qB).volume;
            (v > target ? lo : hi) = mid;
        }
        p.posB = lo * dir;
        const OverlapResult r = polyhedronOverlap(A, Vec3(), p.qA, B, p.posB, p.qB);
        if (!r.touching) continue;
        p.normal = r.normal;
        pairs.push_back(p);
    }

    double sumVolume = 0;
    const auto t0 = std::chrono::steady_clock::now();
    for (int k = 0; k < repeat; ++k)
    {
        for (const PairPose& p : pairs)
        {
            Vec3 axis = p.normal;
            sumVolume += evaluate(views[p.a], views[p.b], p, axis).volume;
        }
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("pairs: %d x %d, overlap %.3g of the smaller volume\n", nPairs, repeat, fraction);
    std::printf("sum of overlap volumes: %.12e m3\n", sumVolume);
    std::printf("us per touching pair: %.4g\n", 1e6 * seconds / (double(nPairs) * repeat));
    return 0;
}

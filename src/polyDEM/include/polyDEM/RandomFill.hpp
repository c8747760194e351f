// polyDEM: random non-overlapping sphere fill of a region with a particle
// size distribution, for initial conditions and insertion.
//
// Random sequential addition (RSA; Widom 1966): sample every diameter first,
// place the largest first (smaller ones then fill the gaps), try uniform
// random centres and accept the first that overlaps nothing. Overlap checks
// go through a hashed grid, so a fill costs O(N). RSA of equal spheres jams
// near a volume fraction of 0.38 (Torquato et al. 2006); in practice aim for
// 0.3 or less and let the particles settle. The result depends only on the
// inputs and the seed (own uniform/normal transforms over std::mt19937_64,
// whose sequence the standard fixes), so runs repeat across platforms.
#pragma once

#include "polyDEM/TriangleMesh.hpp"
#include "polyDEM/Vec3.hpp"

#include <cstddef>
#include <cstdint>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace polydem
{

//- A particle diameter distribution (by number)
struct SizeDistribution
{
    enum class Kind
    {
        fixed,    //!< all equal: diameter
        uniform,  //!< uniform in [min, max]
        normal,   //!< normal(mean, sd) truncated to [min, max]
        discrete  //!< list of (diameter, number fraction); fractions are normalised
    };

    Kind kind = Kind::fixed;
    double diameter = 0;
    double min = 0;
    double max = 0;
    double mean = 0;
    double sd = 0;
    std::vector<std::pair<double, double>> fractions;
    //- Input file, for error messages
    std::string source;

    static SizeDistribution fixedDiameter(double d);
    static SizeDistribution uniform(double dmin, double dmax);
    static SizeDistribution normal(double mean, double sd, double dmin, double dmax);
    static SizeDistribution discrete(std::vector<std::pair<double, double>> fractions);

    //- Throws polydem::Error naming the entry at fault ("diameter", "min",
    //  "max", "mean", "sd", "fractions")
    void validate() const;

    //- One diameter
    double sample(std::mt19937_64& rng) const;

    double minDiameter() const;
    double maxDiameter() const;
};

//- Where spheres go: an axis-aligned box, or inside a closed triangle
//  surface (optionally intersected with a box). Spheres lie fully inside.
struct FillRegion
{
    enum class Kind
    {
        box,
        mesh
    };

    Kind kind = Kind::box;
    //- The box, or for a mesh region the clipping box when clip is set
    Vec3 min, max;
    bool clip = false;
    TriangleMesh mesh;
    //- Input file, for error messages
    std::string source;

    static FillRegion box(const Vec3& min, const Vec3& max);
    //- Throws if the surface is not closed
    static FillRegion insideMesh(TriangleMesh mesh);
    static FillRegion insideMesh(TriangleMesh mesh, const Vec3& clipMin, const Vec3& clipMax);

    //- Sphere (centre, radius) fully inside (slow path for meshes: O(triangles))
    bool contains(const Vec3& centre, double radius) const;

    //- Bounding box of the region
    std::pair<Vec3, Vec3> bounds() const;

    //- Volume: exact for a box and a whole mesh, a Monte Carlo estimate
    //  (relative error ~1e-2) for a clipped mesh
    double volume() const;
};

struct SphereSeed
{
    Vec3 position;
    double radius = 0;
};

//- Place count spheres with diameters from sizes inside region, at least gap
//  apart (surface to surface) from each other and from the obstacles (spheres
//  already placed, e.g. by an earlier insertion). Deterministic for a seed.
//  Gives up when one sphere finds no place in maxAttempts tries, throwing
//  polydem::Error with how many of how many were placed and the volume
//  fraction reached; with partial, returns the spheres placed until then
//  instead (an inflow tops a region up with what fits).
std::vector<SphereSeed> randomFill
(
    const FillRegion& region,
    const SizeDistribution& sizes,
    std::size_t count,
    std::uint64_t seed,
    double gap = 0,
    const std::vector<SphereSeed>& obstacles = {},
    std::size_t maxAttempts = 20000,
    bool partial = false
);

//- Simple cubic lattice of equal spheres (diameter d, centre spacing
//  spacing >= d) over the region's bounding box, keeping the sites fully inside
//  and clear of obstacles; at most maxCount (0: all)
std::vector<SphereSeed> fillLattice
(
    const FillRegion& region,
    double diameter,
    double spacing,
    std::size_t maxCount = 0,
    const std::vector<SphereSeed>& obstacles = {}
);

} // namespace polydem

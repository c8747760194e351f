// polyDEM: random sequential addition fill and lattice fill. See RandomFill.hpp.

#include "polyDEM/RandomFill.hpp"

#include "polyDEM/Error.hpp"
#include "polyDEM/MeshQueries.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <sstream>
#include <unordered_map>

namespace polydem
{

namespace
{

constexpr double pi = 3.14159265358979323846;

// Uniform in [0, 1) from the top 53 bits: the same on every platform
// (std::uniform_real_distribution is implementation-defined)
double uniform01(std::mt19937_64& rng)
{
    return double(rng() >> 11) * 0x1.0p-53;
}

// Standard normal by Box-Muller (one value per call: simple and reproducible)
double standardNormal(std::mt19937_64& rng)
{
    const double u1 = 1.0 - uniform01(rng); // (0, 1]: log is finite
    const double u2 = uniform01(rng);
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * pi * u2);
}

double normalCdf(double x)
{
    return 0.5 * std::erfc(-x / std::sqrt(2.0));
}

std::string str(double v)
{
    std::ostringstream s;
    s.precision(6);
    s << v;
    return s.str();
}

bool finitePositive(double v)
{
    return std::isfinite(v) && v > 0;
}

struct CellKey
{
    std::int64_t i, j, k;
    bool operator==(const CellKey& o) const { return i == o.i && j == o.j && k == o.k; }
};

struct CellKeyHash
{
    std::size_t operator()(const CellKey& c) const
    {
        std::uint64_t h = std::uint64_t(c.i) * 0x9E3779B97F4A7C15ull;
        h ^= std::uint64_t(c.j) * 0xC2B2AE3D27D4EB4Full + (h << 6) + (h >> 2);
        h ^= std::uint64_t(c.k) * 0x165667B19E3779F9ull + (h << 6) + (h >> 2);
        return std::size_t(h ^ (h >> 31));
    }
};

// Hashed grid of spheres. Cell size h = 2 rmax + gap (rmax: the largest
// sphere to be placed), so a candidate checks its own and the 26 neighbouring
// cells. A sphere larger than rmax (an obstacle) is entered in every cell of
// its centre +- (R - rmax), which keeps that 27-cell query exact.
class SphereGrid
{
public:
    SphereGrid(const Vec3& origin, double h) : origin_(origin), h_(h) {}

    CellKey cellOf(const Vec3& p) const
    {
        return {std::int64_t(std::floor((p.x - origin_.x) / h_)),
                std::int64_t(std::floor((p.y - origin_.y) / h_)),
                std::int64_t(std::floor((p.z - origin_.z) / h_))};
    }

    //- Enter sphere index at centre c with extent e >= 0, restricted to the
    //  cells of [lo, hi] (padded by one cell) since nothing is queried elsewhere
    void insert(int index, const Vec3& c, double e, const Vec3& lo, const Vec3& hi)
    {
        CellKey a = cellOf(c - Vec3{e, e, e}), b = cellOf(c + Vec3{e, e, e});
        const CellKey l = cellOf(lo), u = cellOf(hi);
        a = {std::max(a.i, l.i - 1), std::max(a.j, l.j - 1), std::max(a.k, l.k - 1)};
        b = {std::min(b.i, u.i + 1), std::min(b.j, u.j + 1), std::min(b.k, u.k + 1)};
        for (std::int64_t i = a.i; i <= b.i; ++i)
            for (std::int64_t j = a.j; j <= b.j; ++j)
                for (std::int64_t k = a.k; k <= b.k; ++k)
                    cells_[{i, j, k}].push_back(index);
    }

    //- Any sphere closer than r + R + gap (surface distance below gap)?
    bool overlaps(const Vec3& p, double r, double gap,
                  const std::vector<SphereSeed>& spheres) const
    {
        const CellKey c = cellOf(p);
        for (int di = -1; di <= 1; ++di)
            for (int dj = -1; dj <= 1; ++dj)
                for (int dk = -1; dk <= 1; ++dk)
                {
                    const auto it = cells_.find({c.i + di, c.j + dj, c.k + dk});
                    if (it == cells_.end())
                    {
                        continue;
                    }
                    for (int m : it->second)
                    {
                        const double reach = r + spheres[m].radius + gap;
                        if (normSqr(spheres[m].position - p) < reach * reach)
                        {
                            return true;
                        }
                    }
                }
        return false;
    }

private:
    Vec3 origin_;
    double h_;
    std::unordered_map<CellKey, std::vector<int>, CellKeyHash> cells_;
};

// Fast "sphere inside region" for mesh regions: a lazily filled voxel cache
// of (inside, distance to surface) at voxel centres decides most candidates
// from the voxel alone, since every point of a voxel of half-diagonal hd lies
// within hd of its centre. Only voxels near the surface need the exact O(triangles) test.
class RegionTester
{
public:
    RegionTester(const FillRegion& region, double voxel)
        : region_(region), s_(voxel), hd_(0.5 * std::sqrt(3.0) * voxel)
    {
        origin_ = region.bounds().first;
    }

    bool contains(const Vec3& p, double r)
    {
        if (region_.kind == FillRegion::Kind::box)
        {
            return region_.contains(p, r);
        }
        if (region_.clip && !boxContains(p, r))
        {
            return false;
        }
        const CellKey c{std::int64_t(std::floor((p.x - origin_.x) / s_)),
                        std::int64_t(std::floor((p.y - origin_.y) / s_)),
                        std::int64_t(std::floor((p.z - origin_.z) / s_))};
        auto it = cache_.find(c);
        if (it == cache_.end())
        {
            const Vec3 centre = origin_ + s_ * Vec3{c.i + 0.5, c.j + 0.5, c.k + 0.5};
            double w, d;
            windingAndDistance(region_.mesh, centre, w, d);
            it = cache_.emplace(c, Voxel{std::abs(w) > 0.5, d}).first;
        }
        const Voxel& v = it->second;
        if (v.distance > hd_)
        {
            // The whole voxel lies on one side of the surface
            if (!v.inside)
            {
                return false;
            }
            if (v.distance - hd_ >= r)
            {
                return true;
            }
        }
        if (v.distance + hd_ < r)
        {
            return false;
        }
        double w, d;
        windingAndDistance(region_.mesh, p, w, d);
        return std::abs(w) > 0.5 && d >= r;
    }

private:
    struct Voxel
    {
        bool inside;
        double distance;
    };

    bool boxContains(const Vec3& p, double r) const
    {
        for (int d = 0; d < 3; ++d)
        {
            if (p[d] - r < region_.min[d] || p[d] + r > region_.max[d])
            {
                return false;
            }
        }
        return true;
    }

    const FillRegion& region_;
    double s_, hd_;
    Vec3 origin_;
    std::unordered_map<CellKey, Voxel, CellKeyHash> cache_;
};

void checkObstacles(const std::vector<SphereSeed>& obstacles, const std::string& source)
{
    for (std::size_t i = 0; i < obstacles.size(); ++i)
    {
        const SphereSeed& o = obstacles[i];
        if (!std::isfinite(o.position.x) || !std::isfinite(o.position.y)
            || !std::isfinite(o.position.z) || !std::isfinite(o.radius) || o.radius < 0)
        {
            throw Error("obstacle sphere " + std::to_string(i)
                            + " has a non-finite position or an invalid radius",
                        source);
        }
    }
}

} // namespace


// * * * * * * * * * * * * * * * SizeDistribution  * * * * * * * * * * * * * //

SizeDistribution SizeDistribution::fixedDiameter(double d)
{
    SizeDistribution s;
    s.kind = Kind::fixed;
    s.diameter = d;
    s.validate();
    return s;
}


SizeDistribution SizeDistribution::uniform(double dmin, double dmax)
{
    SizeDistribution s;
    s.kind = Kind::uniform;
    s.min = dmin;
    s.max = dmax;
    s.validate();
    return s;
}


SizeDistribution SizeDistribution::normal(double mean, double sd, double dmin, double dmax)
{
    SizeDistribution s;
    s.kind = Kind::normal;
    s.mean = mean;
    s.sd = sd;
    s.min = dmin;
    s.max = dmax;
    s.validate();
    return s;
}


SizeDistribution SizeDistribution::discrete(std::vector<std::pair<double, double>> fractions)
{
    SizeDistribution s;
    s.kind = Kind::discrete;
    s.fractions = std::move(fractions);
    s.validate();
    return s;
}


void SizeDistribution::validate() const
{
    auto rangeCheck = [&]()
    {
        if (!finitePositive(min))
        {
            throw Error("minimum diameter must be positive and finite, got " + str(min),
                        source, "min");
        }
        if (!std::isfinite(max) || max < min)
        {
            throw Error("maximum diameter must be finite and >= min (" + str(min) + "), got "
                            + str(max),
                        source, "max");
        }
    };

    switch (kind)
    {
        case Kind::fixed:
            if (!finitePositive(diameter))
            {
                throw Error("diameter must be positive and finite, got " + str(diameter),
                            source, "diameter");
            }
            break;
        case Kind::uniform:
            rangeCheck();
            break;
        case Kind::normal:
        {
            rangeCheck();
            if (!std::isfinite(mean))
            {
                throw Error("mean must be finite", source, "mean");
            }
            if (!std::isfinite(sd) || sd < 0)
            {
                throw Error("standard deviation must be >= 0 and finite, got " + str(sd),
                            source, "sd");
            }
            if (sd == 0)
            {
                if (mean < min || mean > max)
                {
                    throw Error("with sd = 0 the mean (" + str(mean) + ") must lie in [min, max]",
                                source, "mean");
                }
                break;
            }
            // Rejection sampling needs the window to hold a reasonable share
            const double mass = normalCdf((max - mean) / sd) - normalCdf((min - mean) / sd);
            if (!(mass >= 1e-4))
            {
                throw Error("[min, max] = [" + str(min) + ", " + str(max) + "] holds only "
                                + str(mass) + " of the normal distribution (mean " + str(mean)
                                + ", sd " + str(sd) + ")",
                            source, "mean");
            }
            break;
        }
        case Kind::discrete:
        {
            if (fractions.empty())
            {
                throw Error("discrete distribution needs at least one (diameter fraction) pair",
                            source, "fractions");
            }
            double total = 0;
            for (const auto& f : fractions)
            {
                if (!finitePositive(f.first))
                {
                    throw Error("diameter must be positive and finite, got " + str(f.first),
                                source, "fractions");
                }
                if (!std::isfinite(f.second) || f.second < 0)
                {
                    throw Error("number fraction must be >= 0 and finite, got " + str(f.second),
                                source, "fractions");
                }
                total += f.second;
            }
            if (!(total > 0))
            {
                throw Error("number fractions sum to zero", source, "fractions");
            }
            break;
        }
    }
}


double SizeDistribution::sample(std::mt19937_64& rng) const
{
    switch (kind)
    {
        case Kind::fixed:
            return diameter;
        case Kind::uniform:
            return min + (max - min) * uniform01(rng);
        case Kind::normal:
        {
            if (sd == 0)
            {
                return mean;
            }
            // Rejection: exact truncation; validate() ensured acceptance >= 1e-4
            for (;;)
            {
                const double d = mean + sd * standardNormal(rng);
                if (d >= min && d <= max)
                {
                    return d;
                }
            }
        }
        case Kind::discrete:
        {
            double total = 0;
            for (const auto& f : fractions)
            {
                total += f.second;
            }
            double u = uniform01(rng) * total;
            for (const auto& f : fractions)
            {
                if (u < f.second)
                {
                    return f.first;
                }
                u -= f.second;
            }
            // Round-off: the last class with a non-zero fraction
            for (auto it = fractions.rbegin(); it != fractions.rend(); ++it)
            {
                if (it->second > 0)
                {
                    return it->first;
                }
            }
            return fractions.back().first;
        }
    }
    return diameter;
}


double SizeDistribution::minDiameter() const
{
    switch (kind)
    {
        case Kind::fixed: return diameter;
        case Kind::uniform: return min;
        case Kind::normal: return sd == 0 ? mean : min;
        case Kind::discrete:
        {
            double d = std::numeric_limits<double>::infinity();
            for (const auto& f : fractions)
            {
                if (f.second > 0) d = std::min(d, f.first);
            }
            return d;
        }
    }
    return diameter;
}


double SizeDistribution::maxDiameter() const
{
    switch (kind)
    {
        case Kind::fixed: return diameter;
        case Kind::uniform: return max;
        case Kind::normal: return sd == 0 ? mean : max;
        case Kind::discrete:
        {
            double d = 0;
            for (const auto& f : fractions)
            {
                if (f.second > 0) d = std::max(d, f.first);
            }
            return d;
        }
    }
    return diameter;
}


// * * * * * * * * * * * * * * * * FillRegion  * * * * * * * * * * * * * * * //

FillRegion FillRegion::box(const Vec3& lo, const Vec3& hi)
{
    FillRegion r;
    r.kind = Kind::box;
    r.min = lo;
    r.max = hi;
    for (int d = 0; d < 3; ++d)
    {
        if (!std::isfinite(lo[d]) || !std::isfinite(hi[d]))
        {
            throw Error("box corners must be finite", "", "min");
        }
        if (!(hi[d] > lo[d]))
        {
            throw Error("box max must exceed min in every direction", "", "max");
        }
    }
    return r;
}


FillRegion FillRegion::insideMesh(TriangleMesh mesh)
{
    if (!isClosed(mesh))
    {
        throw Error("filling region surface is not closed (every edge must be shared by "
                    "exactly two triangles)",
                    mesh.source);
    }
    FillRegion r;
    r.kind = Kind::mesh;
    r.source = mesh.source;
    const auto bb = boundingBox(mesh);
    r.min = bb.first;
    r.max = bb.second;
    r.mesh = std::move(mesh);
    return r;
}


FillRegion FillRegion::insideMesh(TriangleMesh mesh, const Vec3& clipMin, const Vec3& clipMax)
{
    FillRegion box = FillRegion::box(clipMin, clipMax);
    FillRegion r = insideMesh(std::move(mesh));
    r.min = box.min;
    r.max = box.max;
    r.clip = true;
    return r;
}


bool FillRegion::contains(const Vec3& centre, double radius) const
{
    if (kind == Kind::box || clip)
    {
        for (int d = 0; d < 3; ++d)
        {
            if (centre[d] - radius < min[d] || centre[d] + radius > max[d])
            {
                return false;
            }
        }
    }
    if (kind == Kind::mesh)
    {
        double w, dist;
        windingAndDistance(mesh, centre, w, dist);
        return std::abs(w) > 0.5 && dist >= radius;
    }
    return true;
}


std::pair<Vec3, Vec3> FillRegion::bounds() const
{
    if (kind == Kind::box)
    {
        return {min, max};
    }
    auto bb = boundingBox(mesh);
    if (clip)
    {
        for (int d = 0; d < 3; ++d)
        {
            bb.first[d] = std::max(bb.first[d], min[d]);
            bb.second[d] = std::min(bb.second[d], max[d]);
        }
    }
    return bb;
}


double FillRegion::volume() const
{
    const auto bb = bounds();
    const Vec3 ext = bb.second - bb.first;
    if (ext.x <= 0 || ext.y <= 0 || ext.z <= 0)
    {
        return 0;
    }
    if (kind == Kind::box)
    {
        return ext.x * ext.y * ext.z;
    }
    if (!clip)
    {
        return std::abs(enclosedVolume(mesh));
    }
    // Clipped mesh: Monte Carlo over the bounds, fixed seed (repeatable)
    std::mt19937_64 rng(12345);
    const int samples = 10000;
    int inside = 0;
    for (int i = 0; i < samples; ++i)
    {
        const Vec3 p = bb.first + cmul(ext, Vec3{uniform01(rng), uniform01(rng), uniform01(rng)});
        inside += insideClosedMesh(mesh, p) ? 1 : 0;
    }
    return ext.x * ext.y * ext.z * inside / samples;
}


// * * * * * * * * * * * * * * * * * Fills  * * * * * * * * * * * * * * * * * //

std::vector<SphereSeed> randomFill
(
    const FillRegion& region,
    const SizeDistribution& sizes,
    std::size_t count,
    std::uint64_t seed,
    double gap,
    const std::vector<SphereSeed>& obstacles,
    std::size_t maxAttempts,
    bool partial
)
{
    sizes.validate();
    if (!std::isfinite(gap) || gap < 0)
    {
        throw Error("gap must be >= 0 and finite, got " + str(gap), region.source, "gap");
    }
    checkObstacles(obstacles, region.source);
    if (count == 0)
    {
        return {};
    }
    maxAttempts = std::max<std::size_t>(maxAttempts, 1);

    std::mt19937_64 rng(seed);

    // All diameters first, largest first: big ones cannot squeeze in later
    std::vector<double> radii(count);
    for (double& r : radii)
    {
        r = 0.5 * sizes.sample(rng);
    }
    std::sort(radii.begin(), radii.end(), std::greater<double>());
    const double rmax = radii.front();

    const auto [lo, hi] = region.bounds();
    const double h = 2 * rmax + gap;
    SphereGrid grid(lo, h);
    RegionTester tester(region, 2 * rmax);

    // Obstacles first, then placed spheres, in one array the grid indexes
    std::vector<SphereSeed> spheres;
    spheres.reserve(obstacles.size() + count);
    for (const SphereSeed& o : obstacles)
    {
        const int index = int(spheres.size());
        spheres.push_back(o);
        grid.insert(index, o.position, std::max(0.0, o.radius - rmax), lo, hi);
    }

    double placedVolume = 0;
    for (std::size_t n = 0; n < count; ++n)
    {
        const double r = radii[n];
        bool placed = false;
        const Vec3 a = lo + Vec3{r, r, r}, b = hi - Vec3{r, r, r};
        if (a.x <= b.x && a.y <= b.y && a.z <= b.z)
        {
            const Vec3 ext = b - a;
            for (std::size_t attempt = 0; attempt < maxAttempts; ++attempt)
            {
                const Vec3 p = a + cmul(ext, Vec3{uniform01(rng), uniform01(rng), uniform01(rng)});
                // Cheap overlap test before the (for meshes) costlier region test
                if (grid.overlaps(p, r, gap, spheres) || !tester.contains(p, r))
                {
                    continue;
                }
                const int index = int(spheres.size());
                spheres.push_back({p, r});
                grid.insert(index, p, 0.0, lo, hi);
                placedVolume += 4.0 / 3.0 * pi * r * r * r;
                placed = true;
                break;
            }
        }
        if (!placed && partial)
        {
            break;
        }
        if (!placed)
        {
            const double v = region.volume();
            std::ostringstream msg;
            msg << "random fill placed only " << n << " of " << count
                << " particles: no free position for a particle of diameter " << str(2 * r)
                << " after " << maxAttempts << " attempts; volume fraction reached "
                << str(v > 0 ? placedVolume / v : 0) << " of region volume " << str(v)
                << " (random sequential addition jams near 0.38)."
                << " Enlarge the region or reduce the number or size of particles";
            throw Error(msg.str(), region.source);
        }
    }

    return std::vector<SphereSeed>(spheres.begin() + std::ptrdiff_t(obstacles.size()),
                                   spheres.end());
}


std::vector<SphereSeed> fillLattice
(
    const FillRegion& region,
    double diameter,
    double spacing,
    std::size_t maxCount,
    const std::vector<SphereSeed>& obstacles
)
{
    if (!finitePositive(diameter))
    {
        throw Error("diameter must be positive and finite, got " + str(diameter),
                    region.source, "diameter");
    }
    if (!std::isfinite(spacing) || spacing < diameter)
    {
        throw Error("lattice spacing must be finite and >= diameter (" + str(diameter)
                        + "), got " + str(spacing),
                    region.source, "spacing");
    }
    checkObstacles(obstacles, region.source);
    const double r = 0.5 * diameter;
    const auto [lo, hi] = region.bounds();

    SphereGrid grid(lo, diameter);
    for (std::size_t i = 0; i < obstacles.size(); ++i)
    {
        grid.insert(int(i), obstacles[i].position, std::max(0.0, obstacles[i].radius - r), lo, hi);
    }
    RegionTester tester(region, diameter);

    // Sites centred in the bounding box so the margins are symmetric
    std::int64_t n[3];
    Vec3 start;
    for (int d = 0; d < 3; ++d)
    {
        const double span = hi[d] - lo[d] - diameter;
        n[d] = span < 0 ? 0 : std::int64_t(std::floor(span / spacing + 1e-12)) + 1;
        start[d] = 0.5 * (lo[d] + hi[d]) - 0.5 * double(n[d] - 1) * spacing;
    }
    std::vector<SphereSeed> out;
    for (std::int64_t k = 0; k < n[2]; ++k)
        for (std::int64_t j = 0; j < n[1]; ++j)
            for (std::int64_t i = 0; i < n[0]; ++i)
            {
                if (maxCount > 0 && out.size() >= maxCount)
                {
                    return out;
                }
                const Vec3 p = start + spacing * Vec3{double(i), double(j), double(k)};
                // Radius shrunk by 1e-12 relative: sites exactly touching the
                // region's walls must not be lost to round-off
                const double rTest = r * (1 - 1e-12);
                if (tester.contains(p, rTest) && !grid.overlaps(p, rTest, 0.0, obstacles))
                {
                    out.push_back({p, r});
                }
            }
    return out;
}

} // namespace polydem

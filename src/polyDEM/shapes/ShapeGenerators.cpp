// polyDEM shapes: generators of convex particle shapes (see ShapeGenerators.hpp).

#include "ShapeGenerators.hpp"
#include "ConvexShapeBuilder.hpp"

#include "polyDEM/Error.hpp"

#include <cmath>
#include <random>
#include <string>
#include <vector>

namespace polydem
{

namespace
{
constexpr double pi = 3.14159265358979323846;
const double phi = 0.5 * (1.0 + std::sqrt(5.0)); // golden ratio

ConvexShape regularSolid(const std::vector<Vec3>& points, const std::string& name, double d)
{
    ConvexShape s = buildConvexShape(points, name);
    scaleToEquivalentDiameter(s, d);
    return s;
}

//- Uniform deviate in (0, 1) from the raw 64-bit stream (portable)
double uniform01(std::mt19937_64& rng)
{
    return (double(rng() >> 11) + 0.5) * (1.0 / 9007199254740992.0);
}

Vec3 randomUnitVector(std::mt19937_64& rng)
{
    // Box-Muller: three normal deviates give an isotropic direction
    double g[4];
    for (int i = 0; i < 4; i += 2)
    {
        const double r = std::sqrt(-2.0 * std::log(uniform01(rng)));
        const double t = 2.0 * pi * uniform01(rng);
        g[i] = r * std::cos(t);
        g[i + 1] = r * std::sin(t);
    }
    const Vec3 v(g[0], g[1], g[2]);
    return v / norm(v);
}
} // namespace


ConvexShape makeBox(double a, double b, double c)
{
    if (!(a > 0 && b > 0 && c > 0))
    {
        throw Error("box edges must be positive");
    }
    std::vector<Vec3> p;
    for (int i = 0; i < 8; ++i)
    {
        p.emplace_back((i & 1 ? 0.5 : -0.5) * a, (i & 2 ? 0.5 : -0.5) * b, (i & 4 ? 0.5 : -0.5) * c);
    }
    return buildConvexShape(p, "box");
}


ConvexShape makeCube(double a)
{
    ConvexShape s = makeBox(a, a, a);
    s.name = "cube";
    return s;
}


ConvexShape makeTetrahedron(double d)
{
    return regularSolid({{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}}, "tetrahedron", d);
}


ConvexShape makeOctahedron(double d)
{
    return regularSolid({{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}},
                        "octahedron", d);
}


ConvexShape makeIcosahedron(double d)
{
    std::vector<Vec3> p;
    for (int s1 = -1; s1 <= 1; s1 += 2)
    {
        for (int s2 = -1; s2 <= 1; s2 += 2)
        {
            p.emplace_back(0, s1, s2 * phi);
            p.emplace_back(s1, s2 * phi, 0);
            p.emplace_back(s2 * phi, 0, s1);
        }
    }
    return regularSolid(p, "icosahedron", d);
}


ConvexShape makeDodecahedron(double d)
{
    std::vector<Vec3> p;
    for (int i = 0; i < 8; ++i)
    {
        p.emplace_back(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1);
    }
    for (int s1 = -1; s1 <= 1; s1 += 2)
    {
        for (int s2 = -1; s2 <= 1; s2 += 2)
        {
            p.emplace_back(0, s1 / phi, s2 * phi);
            p.emplace_back(s1 / phi, s2 * phi, 0);
            p.emplace_back(s2 * phi, 0, s1 / phi);
        }
    }
    return regularSolid(p, "dodecahedron", d);
}


ConvexShape makeRock(double d, double elongation, double flatness, int nPoints,
                     std::uint64_t seed)
{
    if (!(elongation > 0 && elongation <= 1))
    {
        throw Error("rock elongation (b/a) must be in (0, 1], got " + std::to_string(elongation));
    }
    if (!(flatness > 0 && flatness <= 1))
    {
        throw Error("rock flatness (c/b) must be in (0, 1], got " + std::to_string(flatness));
    }
    // A simplicial hull of n points has 2n - 4 faces: cap them
    const int maxPoints = (kMaxPolyhedronFaces + 4) / 2;
    if (nPoints < 4 || nPoints > maxPoints)
    {
        throw Error("rock point count must be in 4.." + std::to_string(maxPoints)
                    + " (a hull of n points has up to 2n-4 faces, at most "
                    + std::to_string(kMaxPolyhedronFaces) + "), got " + std::to_string(nPoints));
    }
    std::mt19937_64 rng(seed);
    const Vec3 semiAxes(1.0, elongation, elongation * flatness);
    std::vector<Vec3> p;
    for (int i = 0; i < nPoints; ++i)
    {
        p.push_back(cmul(semiAxes, randomUnitVector(rng)));
    }
    ConvexShape s = buildConvexShape(p, "rock");
    scaleToEquivalentDiameter(s, d);
    return s;
}


double measuredAspectRatio(const ConvexShape& s)
{
    const Vec3 L = bodyExtents(s);
    return L.x / (0.5 * (L.y + L.z));
}


ConvexShape makeSettlingParticle(double d, double aspectRatio, int facets)
{
    if (facets < 4 || facets % 2 != 0 || facets > kMaxPolyhedronFaces)
    {
        throw Error("settling particle facet count C must be even and in 4.."
                    + std::to_string(kMaxPolyhedronFaces)
                    + " (a closed triangulated convex surface with V vertices has F = 2V - 4 "
                      "facets), got " + std::to_string(facets));
    }
    if (!(aspectRatio >= 1))
    {
        throw Error("settling particle aspect ratio AR must be >= 1, got "
                    + std::to_string(aspectRatio));
    }
    const int n = facets / 2 + 2;
    const double goldenAngle = pi * (3.0 - std::sqrt(5.0));
    // Try a few spiral phases in case a rare placement makes 4 points coplanar
    for (int attempt = 0; attempt < 64; ++attempt)
    {
        std::vector<Vec3> p;
        for (int i = 0; i < n; ++i)
        {
            const double x = 1.0 - (2.0 * i + 1.0) / n;
            const double r = std::sqrt(1.0 - x * x);
            const double t = i * goldenAngle + 0.1 * attempt;
            p.emplace_back(aspectRatio * x, r * std::cos(t), r * std::sin(t));
        }
        ConvexShape s = buildConvexShape(p, "settling");
        if (s.nFaces() != facets || s.nVertices() != n)
        {
            continue;
        }
        // Stretch along the long principal axis to the exact aspect ratio
        for (int k = 0; k < 4; ++k)
        {
            const double stretch = aspectRatio / measuredAspectRatio(s);
            if (std::fabs(stretch - 1.0) < 1e-15)
            {
                break;
            }
            std::vector<Vec3> q = s.vertices;
            for (Vec3& v : q)
            {
                v.x *= stretch;
            }
            s = buildConvexShape(q, "settling");
        }
        if (s.nFaces() != facets
            || std::fabs(measuredAspectRatio(s) - aspectRatio) > 1e-12 * aspectRatio)
        {
            continue;
        }
        scaleToEquivalentDiameter(s, d);
        s.name = "settling_AR" + std::to_string(aspectRatio).substr(0, 4) + "_C"
                 + std::to_string(facets);
        return s;
    }
    throw Error("could not place " + std::to_string(n) + " points for C = "
                + std::to_string(facets) + ", AR = " + std::to_string(aspectRatio));
}

} // namespace polydem

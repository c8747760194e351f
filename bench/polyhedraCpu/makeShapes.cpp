// makeShapes: write random convex rocks (polyDEMShapes::makeRock, CGAL) as a
// plain-text shape file that polyhedraBench reads without CGAL (the GPU
// machine has none). Every field of polydem::ConvexShape is written with 17
// significant digits, so the shapes are exactly those made here.
//
// Usage: makeShapes OUT nShapes d elongation flatness points firstSeed
#include "ShapeGenerators.hpp"

#include <cstdio>
#include <cstdlib>
#include <string>

using namespace polydem;

int main(int argc, char** argv)
{
    if (argc < 8)
    {
        std::fprintf(stderr, "usage: makeShapes OUT nShapes d elongation flatness points firstSeed\n");
        return 2;
    }
    const int n = std::atoi(argv[2]);
    const double d = std::atof(argv[3]), el = std::atof(argv[4]), fl = std::atof(argv[5]);
    const int np = std::atoi(argv[6]);
    const long seed = std::atol(argv[7]);
    FILE* f = std::fopen(argv[1], "w");
    if (!f) return 1;
    std::fprintf(f, "# polyDEM convex shapes (bench/polyhedraCpu/makeShapes): makeRock(d %g, "
                    "elongation %g, flatness %g, points %d, seeds %ld..%ld)\n",
                 d, el, fl, np, seed, seed + n - 1);
    std::fprintf(f, "shapes %d\n", n);
    for (int k = 0; k < n; ++k)
    {
        const ConvexShape s = makeRock(d, el, fl, np, std::uint64_t(seed + k));
        std::fprintf(f, "shape rock%d %d %d %d\n", k, s.nVertices(), s.nFaces(), s.nEdges());
        std::fprintf(f, "properties %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g\n", s.volume,
                     s.surfaceArea, s.equivalentDiameter, s.sphericity, s.boundingRadius,
                     s.inertiaPerDensity.x, s.inertiaPerDensity.y, s.inertiaPerDensity.z);
        for (const Vec3& v : s.vertices) std::fprintf(f, "v %.17g %.17g %.17g\n", v.x, v.y, v.z);
        for (int i = 0; i < s.nFaces(); ++i)
        {
            std::fprintf(f, "f %.17g %.17g %.17g %.17g %d", s.faceNormals[i].x, s.faceNormals[i].y,
                         s.faceNormals[i].z, s.faceOffsets[i], s.faceStart[i + 1] - s.faceStart[i]);
            for (int j = s.faceStart[i]; j < s.faceStart[i + 1]; ++j) std::fprintf(f, " %d", s.faceVertex[j]);
            std::fprintf(f, "\n");
        }
        for (const auto& e : s.edges) std::fprintf(f, "e %d %d\n", e.a, e.b);
    }
    std::fclose(f);
    std::printf("wrote %d shapes to %s\n", n, argv[1]);
    return 0;
}

// The wall floor depths (WallDepths.hpp) of a closed UV sphere of radius 1
// with nu x nv quads (2 nu (nv - 1) triangles), with a cap (maxDepth) and
// without: the worst case for the shrinking ball, whose balls inside a round
// body reach the whole surface unless capped. Prints the seconds and the
// depths found. Usage: sphereDepths NU NV [MAXDEPTH]
#include "polyDEM/WallDepths.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>

using namespace polydem;

int main(int argc, char** argv)
{
    if (argc < 3)
    {
        std::fprintf(stderr, "usage: %s NU NV [MAXDEPTH]\n", argv[0]);
        return 2;
    }
    const int nu = std::atoi(argv[1]), nv = std::atoi(argv[2]);
    const double cap = argc > 3 ? std::atof(argv[3]) : kUnboundedWallDepth;
    TriangleMesh m;
    for (int j = 0; j <= nv; ++j)
        for (int i = 0; i < nu; ++i)
        {
            const double th = M_PI * j / nv, ph = 2 * M_PI * i / nu;
            m.points.push_back(Vec3(std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th)));
        }
    auto id = [&](int i, int j) { return j * nu + (i % nu); };
    for (int j = 0; j < nv; ++j)
        for (int i = 0; i < nu; ++i)
        {
            const int a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
            if (j > 0) m.triangles.push_back({a, d, b});
            if (j < nv - 1) m.triangles.push_back({b, d, c});
        }
    const auto t0 = std::chrono::steady_clock::now();
    const std::vector<double> depth = wallDepths(m, cap);
    const double dt = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    double lo = 1e300, hi = 0;
    for (double d : depth)
    {
        lo = std::min(lo, d);
        hi = std::max(hi, d);
    }
    std::printf("%zu triangles, cap %g: %.3f s, depths %.4f..%.4f\n", m.size(), cap, dt, lo, hi);
    std::printf("seconds: %.6f\n", dt);
    return 0;
}

// Cost of polyhedronTriangleOverlap against a finely tessellated closed
// cylinder (100 strips of 3.6 degrees, as the brash-ice bow's), with each
// triangle's normal prism against its solid bounded by the bisector planes
// (WallSidePlanes.hpp); 0.05 m cubes pressed onto the curved side and onto
// the rim of an end. bench/wallSidePlanes/run
#include "ShapeGenerators.hpp"
#include "polyDEM/WallDepths.hpp"
#include "polyDEM/WallSidePlanes.hpp"
#include "polyDEM/MeshQueries.hpp"
#include "polyDEM/PolyhedronOverlap.hpp"
#include <chrono>
#include <cstdio>
#include <random>
using namespace polydem;
int main()
{
    const int nSeg = 100; const double R = 0.1, H = 0.5;
    TriangleMesh m;
    for (int k = 0; k < 2; ++k)
        for (int i = 0; i < nSeg; ++i)
        {
            const double a = 2 * M_PI * i / nSeg;
            m.points.push_back(Vec3(R * cos(a), R * sin(a), k * H));
        }
    m.points.push_back(Vec3(0, 0, 0)); m.points.push_back(Vec3(0, 0, H));
    const int c0 = 2 * nSeg, c1 = 2 * nSeg + 1;
    for (int i = 0; i < nSeg; ++i)
    {
        const int j = (i + 1) % nSeg;
        m.triangles.push_back({i, j, nSeg + j});
        m.triangles.push_back({i, nSeg + j, nSeg + i});
        m.triangles.push_back({c0, j, i});
        m.triangles.push_back({c1, nSeg + i, nSeg + j});
    }
    const auto depth = wallDepths(m);
    const auto sides = wallSidePlanes(m);
    const ConvexShape cube = makeCube(0.05);
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> u(0, 1);
    std::normal_distribution<double> g;
    struct Pose { Vec3 x; Quaternion q; std::vector<int> tris; };
    std::vector<Pose> poses;
    for (int k = 0; k < 2000; ++k)
    {
        Pose p;
        p.q = normalised(Quaternion{g(rng), g(rng), g(rng), g(rng)});
        const double a = 2 * M_PI * u(rng);
        const double r = R + 0.02 - 0.02 * u(rng);
        // Half on the side, half at the rim of the top end
        const double z = k % 2 ? 0.1 + 0.3 * u(rng) : H + 0.02 - 0.02 * u(rng);
        p.x = Vec3(r * cos(a), r * sin(a), z);
        for (size_t t = 0; t < m.size(); ++t)
        {
            const auto& tri = m.triangles[t];
            if (norm(closestPointOnTriangle(p.x, m.points[tri[0]], m.points[tri[1]], m.points[tri[2]]) - p.x) < cube.boundingRadius)
                p.tris.push_back(int(t));
        }
        poses.push_back(p);
    }
    double sums[2] = {0, 0}, times[2];
    size_t calls = 0;
    for (int mode = 0; mode < 2; ++mode)
    {
        const auto t0 = std::chrono::steady_clock::now();
        for (int rep = 0; rep < 5; ++rep)
        for (const Pose& p : poses)
            for (int t : p.tris)
            {
                const auto& tri = m.triangles[t];
                const int s0 = sides.start[t];
                const OverlapResult r = polyhedronTriangleOverlap(cube.view(), p.x, p.q, m.points[tri[0]], m.points[tri[1]], m.points[tri[2]], depth[t],
                    mode ? sides.normal.data() + s0 : nullptr, mode ? sides.offset.data() + s0 : nullptr, mode ? sides.start[t + 1] - s0 : 0);
                if (r.touching) sums[mode] += r.volume;
                if (mode == 0 && rep == 0) ++calls;
            }
        times[mode] = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    }
    double planes = 0; for (size_t t = 0; t < m.size(); ++t) planes += sides.start[t + 1] - sides.start[t];
    printf("%zu triangles, %.2f side planes each; %zu triangle calls per pass over %zu poses\n", m.size(), planes / m.size(), calls, poses.size());
    printf("prisms: %.3f s, volume sum %.6e\nbisector solids: %.3f s, volume sum %.6e\nratio: %.2f\n", times[0], sums[0], times[1], sums[1], times[1] / times[0]);
}

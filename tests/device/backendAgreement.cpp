// The CPU (OpenMP) and CUDA back ends run the same source: after 1000 steps of
// a small packed case their particle positions agree to 1e-9 relative.
// Here also: the CPU back end gives the same bits on 1 and 2 threads (the
// force sums do not depend on the thread schedule).
//
// Usage: backendAgreement spheres|polyhedra [steps]
// Exit: 0 agree, 1 differ, 77 CUDA part skipped (no device) after the CPU part passed.
#include "polyDEM/Error.hpp"
#include "polyDEM/RandomFill.hpp"
#include "polyDEM/System.hpp"

#include <omp.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <string>

using namespace polydem;

namespace
{

//- A box as a ConvexShape, built analytically (the GPU machine has no CGAL)
ConvexShape analyticBox(double a, double b, double c)
{
    ConvexShape s;
    s.name = "box";
    const double h[3] = {0.5 * a, 0.5 * b, 0.5 * c};
    for (int k = 0; k < 8; ++k)
        s.vertices.push_back(Vec3((k & 1 ? 1 : -1) * h[0], (k & 2 ? 1 : -1) * h[1], (k & 4 ? 1 : -1) * h[2]));
    // faces CCW seen from outside
    const int f[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
    const Vec3 n[6] = {Vec3(-1, 0, 0), Vec3(1, 0, 0), Vec3(0, -1, 0), Vec3(0, 1, 0), Vec3(0, 0, -1), Vec3(0, 0, 1)};
    s.faceStart = {0};
    for (int k = 0; k < 6; ++k)
    {
        for (int j = 0; j < 4; ++j) s.faceVertex.push_back(f[k][j]);
        s.faceStart.push_back(int(s.faceVertex.size()));
        s.faceNormals.push_back(n[k]);
        s.faceOffsets.push_back(h[k / 2]);
    }
    for (int i = 0; i < 8; ++i)
        for (int j = i + 1; j < 8; ++j)
            if (__builtin_popcount(i ^ j) == 1) s.edges.push_back({i, j});
    s.volume = a * b * c;
    s.surfaceArea = 2 * (a * b + b * c + a * c);
    s.boundingRadius = std::sqrt(h[0] * h[0] + h[1] * h[1] + h[2] * h[2]);
    s.equivalentDiameter = std::cbrt(6 * s.volume / M_PI);
    s.inertiaPerDensity = (s.volume / 12) * Vec3(b * b + c * c, a * a + c * c, a * a + b * b);
    return s;
}

bool polyhedra = false;

SimulationConfig packedCase(const std::string& device)
{
    SimulationConfig c;
    c.materials.push_back({"glass", 5e6, 0.3, 2500});
    PairProperties pp;
    pp.restitution = 0.5;
    pp.friction = 0.5;
    pp.rollingFriction = 0.05;
    c.pairs = {pp};
    c.contact.law = ContactLaw::hertzMindlin;
    c.contact.rolling = RollingModel::elasticPlastic;
    ParticleType t;
    t.name = "beads";
    t.radius = 0.002;
    c.types.push_back(t);
    c.gravity = Vec3(0, 0, -9.81);
    c.timeStep = 2e-5;
    const double L = 0.03;
    auto plane = [](Vec3 p, Vec3 n) { PlaneWall w; w.point = p; w.normal = n; w.name = "wall"; return w; };
    c.planes = {plane(Vec3(0, 0, 0), Vec3(0, 0, 1)), plane(Vec3(0, 0, 0), Vec3(1, 0, 0)),
                plane(Vec3(L, 0, 0), Vec3(-1, 0, 0)), plane(Vec3(0, 0, 0), Vec3(0, 1, 0)),
                plane(Vec3(0, L, 0), Vec3(0, -1, 0))};
    c.device = device;
    c.source = "backendAgreement";
    if (polyhedra)
    {
        c.contact.law = ContactLaw::overlapVolume;
        c.contact.rolling = RollingModel::none;
        c.contact.volumetricStiffness = 1e9;
        c.timeStep = 4e-6;
        c.shapes = {analyticBox(0.004, 0.003, 0.0025), analyticBox(0.0035, 0.0035, 0.0035)};
        ParticleType p1, p2;
        p1.name = "slab";
        p1.shape = ShapeKind::polyhedron;
        p1.shapeIndex = 0;
        p2.name = "cube";
        p2.shape = ShapeKind::polyhedron;
        p2.shapeIndex = 1;
        c.types = {p1, p2};
    }
    return c;
}

//- Settle a random fill into a packed bed (CPU), the start of every comparison
Snapshot packedStart()
{
    System s(packedCase("cpu"));
    // Polyhedra cost more per contact: fewer of them, a lower fill
    const auto seeds = randomFill(FillRegion::box(Vec3(0, 0, 0), Vec3(0.03, 0.03, polyhedra ? 0.03 : 0.15)),
                                  SizeDistribution::uniform(0.0035, 0.0045), polyhedra ? 150 : 800, 5);
    std::vector<Vec3> x;
    std::vector<double> r;
    for (const auto& q : seeds) { x.push_back(q.position); r.push_back(q.radius); }
    Snapshot st;
    st.particles = s.makeSpheres(0, x, r, 0);
    if (polyhedra)
    {
        // Same places, random orientations, alternating shapes
        for (std::size_t i = 0; i < x.size(); ++i)
        {
            st.particles.type[i] = int(i % 2);
            st.particles.mass[i] = 0;
            st.particles.orientation[i] = normalised(Quaternion{std::cos(0.7 * i), std::sin(1.3 * i),
                                                                std::cos(2.1 * i), std::sin(0.5 * i)});
        }
        s.completeMassProperties(st.particles);
    }
    s.initialise(st);
    s.advance(polyhedra ? 20000 : 15000);
    return s.engine().snapshot();
}

ParticleState run(const std::string& device, const Snapshot& start, int steps)
{
    System s(packedCase(device));
    s.initialise(start);
    s.advance(steps);
    return s.engine().particles();
}

double maxRelativeDifference(const ParticleState& a, const ParticleState& b)
{
    std::map<std::int64_t, std::size_t> where;
    for (std::size_t i = 0; i < b.size(); ++i) where[b.id[i]] = i;
    double worst = 0;
    double scale = 0;
    for (std::size_t i = 0; i < a.size(); ++i) scale = std::max(scale, norm(a.position[i]));
    for (std::size_t i = 0; i < a.size(); ++i)
    {
        auto it = where.find(a.id[i]);
        if (it == where.end()) return INFINITY;
        worst = std::max(worst, norm(a.position[i] - b.position[it->second]) / scale);
    }
    return a.size() == b.size() ? worst : INFINITY;
}

} // namespace

int main(int argc, char** argv)
{
    if (argc < 2 || (std::strcmp(argv[1], "spheres") != 0 && std::strcmp(argv[1], "polyhedra") != 0))
    {
        std::fprintf(stderr, "usage: backendAgreement spheres|polyhedra [steps]\n");
        return 2;
    }
    polyhedra = std::strcmp(argv[1], "polyhedra") == 0;
    const int steps = argc > 2 ? std::atoi(argv[2]) : 1000;
    const Snapshot start = packedStart();
    std::printf("packed case: %zu %s, %d steps\n", start.particles.size(), argv[1], steps);

    omp_set_num_threads(1);
    const ParticleState one = run("cpu", start, steps);
    omp_set_num_threads(2);
    const ParticleState two = run("cpu", start, steps);
    const double dThreads = maxRelativeDifference(one, two);
    std::printf("cpu 1 thread vs 2 threads: max relative position difference %.3g\n", dThreads);
    if (dThreads != 0)
    {
        std::printf("FAIL: the CPU back end depends on the thread count\n");
        return 1;
    }

    ParticleState gpu;
    try
    {
        gpu = run("cuda", start, steps);
    }
    catch (const std::exception& e)
    {
        std::printf("cuda back end not available here (%s): skipped\n", e.what());
        return 77;
    }
    const double d = maxRelativeDifference(one, gpu);
    std::printf("cpu vs cuda: max relative position difference %.3g (limit 1e-9)\n", d);
    return d <= 1e-9 ? 0 : 1;
}

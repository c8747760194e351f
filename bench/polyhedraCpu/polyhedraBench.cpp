// polyhedraBench: time polyDEM on random convex rocks settling into a dense
// pile in a box. Host code only (polyDEM API, no CGAL): the shapes come from
// a plain-text file made by makeShapes (rocks.shapes, 10 rocks of 20 faces,
// d_eq 5 mm), so the same driver runs on the GPU machine.
//
// Usage: polyhedraBench N steps device threads [--shapes FILE] [--warmup S] [--dt S]
//                       [--layers L]
//   N        number of rocks; they start on a loose cubic lattice (spacing
//            1.02 x the largest bounding diameter) of `layers` layers
//            (default 12) in a box whose floor is sqrt(N/layers) cells
//            square, with random shapes and orientations (seed 1), falling
//            at 0.5 m/s under gravity; overlapVolume law (Kv 4e7 N/m3,
//            e 0.3, mu 0.5), density 2700. The column collapses into a
//            dense bed in ~1100 steps of 1e-4 s.
//   steps    timed steps (the clock covers System::advance() only)
//   device   cpu | cuda
//   threads  OpenMP threads of the cpu back end (0: default)
//   --warmup untimed steps first (the lattice collapses into a pile)
// Prints key: value lines; the last is `particle-steps/s: X`.
#include "polyDEM/System.hpp"
#include "rockShapes.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

using namespace polydem;

namespace
{

PlaneWall plane(const Vec3& point, const Vec3& normal, const std::string& name)
{
    PlaneWall w;
    w.name = name;
    w.point = point;
    w.normal = normal;
    return w;
}

[[noreturn]] void usage()
{
    std::fprintf(stderr, "usage: polyhedraBench N steps cpu|cuda threads [--shapes FILE] "
                         "[--warmup STEPS] [--dt S] [--layers L]\n");
    std::exit(2);
}

} // namespace

int main(int argc, char** argv)
{
    if (argc < 5) usage();
    const long n = std::atol(argv[1]);
    const long steps = std::atol(argv[2]);
    const std::string device = argv[3];
    const int threads = std::atoi(argv[4]);
    std::string shapesFile = "rocks.shapes";
    long warmup = 0;
    double dt = 1e-4;
    long layers = 12;
    for (int i = 5; i < argc; ++i)
    {
        const std::string a = argv[i];
        if (a == "--shapes" && i + 1 < argc) shapesFile = argv[++i];
        else if (a == "--warmup" && i + 1 < argc) warmup = std::atol(argv[++i]);
        else if (a == "--dt" && i + 1 < argc) dt = std::atof(argv[++i]);
        else if (a == "--layers" && i + 1 < argc) layers = std::max(1L, std::atol(argv[++i]));
        else usage();
    }
    if (threads > 0) setenv("OMP_NUM_THREADS", std::to_string(threads).c_str(), 1);

    try
    {
        SimulationConfig c;
        c.device = device;
        c.source = "polyhedraBench";
        c.timeStep = dt;
        c.materials.push_back({"granite", 5e9, 0.25, 2700});
        PairProperties pp;
        pp.restitution = 0.3;
        pp.friction = 0.5;
        c.pairs = {pp};
        c.contact.law = ContactLaw::overlapVolume;
        c.contact.volumetricStiffness = 4e7;
        c.contact.tangentialStiffnessRatio = 2.0 / 7.0;
        c.shapes = bench::readShapes(shapesFile);
        double rb = 0;
        int maxFaces = 0;
        for (std::size_t k = 0; k < c.shapes.size(); ++k)
        {
            ParticleType t;
            t.name = c.shapes[k].name;
            t.shape = ShapeKind::polyhedron;
            t.shapeIndex = int(k);
            c.types.push_back(t);
            rb = std::max(rb, c.shapes[k].boundingRadius);
            maxFaces = std::max(maxFaces, c.shapes[k].nFaces());
        }

        // Lattice: floor nx x nx cells, nz ~ layers
        const double s = 2.04 * rb;
        const long nx = std::max(2L, long(std::ceil(std::sqrt(double(n) / layers))));
        const long nz = (n + nx * nx - 1) / (nx * nx);
        const double L = nx * s;
        c.planes.push_back(plane(Vec3(0, 0, 0), Vec3(0, 0, 1), "floor"));
        c.planes.push_back(plane(Vec3(0, 0, 0), Vec3(1, 0, 0), "x0"));
        c.planes.push_back(plane(Vec3(L, 0, 0), Vec3(-1, 0, 0), "x1"));
        c.planes.push_back(plane(Vec3(0, 0, 0), Vec3(0, 1, 0), "y0"));
        c.planes.push_back(plane(Vec3(0, L, 0), Vec3(0, -1, 0), "y1"));

        System sys(c);
        Snapshot st;
        st.particles.resize(std::size_t(n));
        std::mt19937_64 rng(1);
        auto uniform = [&rng]() { return double(rng() >> 11) * 0x1.0p-53; };
        for (long i = 0; i < n; ++i)
        {
            const long ix = i % nx, iy = (i / nx) % nx, iz = i / (nx * nx);
            auto& p = st.particles;
            p.id[i] = i;
            p.type[i] = int(uniform() * c.types.size()) % int(c.types.size());
            p.position[i] = Vec3((ix + 0.5) * s, (iy + 0.5) * s, (iz + 0.5) * s);
            const double u1 = uniform(), u2 = uniform(), u3 = uniform();
            const double a = std::sqrt(1 - u1), b = std::sqrt(u1);
            p.orientation[i] = normalised(Quaternion{b * std::cos(2 * M_PI * u3), a * std::sin(2 * M_PI * u2),
                                                     a * std::cos(2 * M_PI * u2), b * std::sin(2 * M_PI * u3)});
            p.velocity[i] = Vec3(0.05 * (uniform() - 0.5), 0.05 * (uniform() - 0.5), -0.5);
        }
        sys.completeMassProperties(st.particles);
        const double dtMax = sys.criticalTimeStep(st.particles);
        sys.initialise(std::move(st));

        std::printf("particles: %ld\nshapes: %zu (up to %d faces) from %s\ndevice: %s\nthreads: %d\n"
                    "time step: %g s (stability limit %g s)\nbox: %ld x %ld cells of %g m, %ld layers\n",
                    n, c.shapes.size(), maxFaces, shapesFile.c_str(), device.c_str(), threads, dt, dtMax,
                    nx, nx, s, nz);
        std::fflush(stdout);

        const auto w0 = std::chrono::steady_clock::now();
        if (warmup > 0) sys.advance(warmup);
        const Statistics sw = sys.engine().statistics();
        const auto w1 = std::chrono::steady_clock::now();
        std::printf("warmup: %ld steps, %.2f s, contacts/particle %.2f (+%.2f walls)\n", warmup,
                    std::chrono::duration<double>(w1 - w0).count(), double(sw.contacts) / n,
                    double(sw.wallContacts) / n);
        std::fflush(stdout);

        const auto t0 = std::chrono::steady_clock::now();
        sys.advance(steps);
        const Statistics s1 = sys.engine().statistics(); // copies back: also a device sync
        const auto t1 = std::chrono::steady_clock::now();
        const double sec = std::chrono::duration<double>(t1 - t0).count();
        const Energies e = sys.engine().energies();
        std::printf("timed: %ld steps, %.3f s\n", steps, sec);
        std::printf("contacts/particle at the end: %.2f (+%.2f walls), particles in contact %.2f %%\n",
                    double(s1.contacts) / n, double(s1.wallContacts) / n,
                    100.0 * double(s1.particlesInContact) / n);
        std::printf("kinetic energy per particle: %.3g J\n", e.kinetic() / n);
        std::printf("steps/s: %.1f\n", steps / sec);
        std::printf("contact-steps/s: %.4g\n", double(s1.contacts + s1.wallContacts) * steps / sec);
        std::printf("particle-steps/s: %.4g\n", double(n) * steps / sec);
    }
    catch (const Error& err)
    {
        std::fprintf(stderr, "polyhedraBench: %s\n", err.what());
        return 1;
    }
    return 0;
}

// spheresBench: time polyDEM on a bed of equal spheres settling in a box.
//
// Usage: spheresBench N steps device threads [options]
//   N        number of spheres (d = 4 mm, glass-like, Hertz-Mindlin, e 0.5, mu 0.5)
//   steps    time steps to time (the clock covers System::advance() only)
//   device   cpu | cuda
//   threads  OpenMP threads of the cpu back end (ignored by cuda)
// Options:
//   --layout random|lattice  random: RSA fill (randomFill, seed 1) of the lower part of a
//                            box 50 d x 50 d wide, the spheres then settle (default);
//                            lattice: a dense simple-cubic bed (spacing 1.001 d) in a
//                            square box, for large GPU runs without a settling phase
//   --dt S                   time step [s] (default 2e-5)
//   --write-data FILE        write the initial spheres as a LIGGGHTS data file
//                            (atom_style granular) and the box as FILE.box (include file)
//   --warmup STEPS           untimed steps first (default 0)
// Prints key: value lines; the last ones are the figures the run scripts read.
#include "polyDEM/RandomFill.hpp"
#include "polyDEM/System.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
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
    std::fprintf(stderr, "usage: spheresBench N steps cpu|cuda threads [--layout random|lattice] "
                         "[--dt S] [--write-data FILE] [--warmup STEPS]\n");
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
    std::string layout = "random", dataFile;
    double dt = 2e-5;
    long warmup = 0;
    for (int a = 5; a < argc; ++a)
    {
        const std::string k = argv[a];
        if (a + 1 >= argc) usage();
        if (k == "--layout") layout = argv[++a];
        else if (k == "--dt") dt = std::atof(argv[++a]);
        else if (k == "--write-data") dataFile = argv[++a];
        else if (k == "--warmup") warmup = std::atol(argv[++a]);
        else usage();
    }
    if (n <= 0 || steps < 0 || (layout != "random" && layout != "lattice")) usage();

    // Before the back end (and its OpenMP runtime) is loaded
    if (threads > 0) setenv("OMP_NUM_THREADS", std::to_string(threads).c_str(), 1);

    const double d = 0.004, r = 0.5 * d;
    const double E = 5e6, nu = 0.3, rho = 2500;

    // Box: random layout 50 d x 50 d footprint, spheres placed in the lower
    // 0.07 m (volume fraction ~0.24), a bed of ~7 layers once settled.
    // Lattice layout: a cube of n^(1/3) spheres a side, spacing 1.001 d.
    Vec3 lo(0, 0, 0), hi;
    std::vector<Vec3> x;
    if (layout == "random")
    {
        const double L = 50 * d;
        const double fillHeight = 0.07 * std::max(1.0, double(n) / 20000.0);
        hi = Vec3(L, L, 1.5 * fillHeight);
        const auto seeds = randomFill(FillRegion::box(lo, Vec3(L, L, fillHeight)),
                                      SizeDistribution::fixedDiameter(d), std::size_t(n), 1);
        for (const auto& s : seeds) x.push_back(s.position);
    }
    else
    {
        const int side = int(std::ceil(std::cbrt(double(n))));
        const double a = 1.001 * d;
        hi = Vec3(side * a, side * a, 1.2 * side * a);
        for (long k = 0; k < n; ++k)
        {
            const long ix = k % side, iy = (k / side) % side, iz = k / (long(side) * side);
            x.push_back(Vec3((ix + 0.5) * a, (iy + 0.5) * a, (iz + 0.5) * a));
        }
    }

    SimulationConfig cfg;
    cfg.materials.push_back({"glass", E, nu, rho});
    PairProperties pp;
    pp.restitution = 0.5;
    pp.friction = 0.5;
    cfg.pairs = {pp};
    cfg.contact.law = ContactLaw::hertzMindlin;
    ParticleType t;
    t.name = "sphere";
    t.radius = r;
    cfg.types.push_back(t);
    cfg.gravity = Vec3(0, 0, -9.81);
    cfg.skinFraction = 0.2;
    cfg.timeStep = dt;
    cfg.device = device;
    cfg.source = "spheresBench";
    cfg.planes = {plane(lo, Vec3(1, 0, 0), "xmin"), plane(hi, Vec3(-1, 0, 0), "xmax"),
                  plane(lo, Vec3(0, 1, 0), "ymin"), plane(hi, Vec3(0, -1, 0), "ymax"),
                  plane(lo, Vec3(0, 0, 1), "zmin"), plane(hi, Vec3(0, 0, -1), "zmax")};

    if (!dataFile.empty())
    {
        std::ofstream f(dataFile);
        f.precision(17);
        f << "LIGGGHTS data file written by spheresBench (N = " << n << ")\n\n"
          << n << " atoms\n1 atom types\n\n"
          << lo.x << " " << hi.x << " xlo xhi\n"
          << lo.y << " " << hi.y << " ylo yhi\n"
          << lo.z << " " << hi.z << " zlo zhi\n\nAtoms\n\n";
        for (long i = 0; i < n; ++i)
        {
            // atom_style granular: id type diameter density x y z
            f << i + 1 << " 1 " << d << " " << rho << " " << x[i].x << " " << x[i].y << " " << x[i].z << "\n";
        }
        std::ofstream b(dataFile + ".box");
        b.precision(17);
        b << "variable xlo equal " << lo.x << "\nvariable xhi equal " << hi.x << "\n"
          << "variable ylo equal " << lo.y << "\nvariable yhi equal " << hi.y << "\n"
          << "variable zlo equal " << lo.z << "\nvariable zhi equal " << hi.z << "\n";
    }

    try
    {
        System sys(cfg);
        Snapshot st;
        st.particles = sys.makeSpheres(0, x, {}, 0);
        std::printf("particles: %ld\nlayout: %s\ndevice: %s\nthreads: %d\ntime step: %g s "
                    "(stability limit %g s)\n",
                    n, layout.c_str(), device.c_str(), threads, dt,
                    sys.criticalTimeStep(st.particles));
        sys.initialise(st);
        if (warmup > 0) sys.advance(warmup);

        const auto t0 = std::chrono::steady_clock::now();
        sys.advance(steps);
        const Statistics s = sys.engine().statistics();  // copies back: also a device sync
        const auto t1 = std::chrono::steady_clock::now();
        const double sec = std::chrono::duration<double>(t1 - t0).count();

        const ParticleState p = sys.engine().particles();
        double zSum = 0, zMax = -1e300, ke = 0;
        for (std::size_t i = 0; i < p.size(); ++i)
        {
            zSum += p.position[i].z;
            zMax = std::max(zMax, p.position[i].z);
            ke += 0.5 * p.mass[i] * normSqr(p.velocity[i]);
        }
        std::printf("steps: %ld\nsimulated time: %g s\n", steps, sys.engine().time());
        std::printf("particles left: %zu\n", s.particles);
        std::printf("neighbour list builds: %zu\n", s.neighbourListBuilds);
        std::printf("contacts: %zu\nwall contacts: %zu\n", s.contacts, s.wallContacts);
        std::printf("mean z: %.6g m\nmax z: %.6g m\nkinetic energy: %.6g J\n",
                    zSum / double(p.size()), zMax, ke);
        std::printf("advance time: %.4f s\n", sec);
        std::printf("particle-steps/s: %.6g\n", double(n) * double(steps) / sec);
    }
    catch (const std::exception& e)
    {
        std::fprintf(stderr, "spheresBench: %s\n", e.what());
        return 1;
    }
    return 0;
}

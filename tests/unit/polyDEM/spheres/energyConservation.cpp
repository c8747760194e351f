// With e = 1 and no friction, 1000 spheres in a closed box under gravity:
// the total energy (kinetic + gravitational + elastic) drifts less than 0.1 %
// over 1e5 steps (velocity Verlet is symplectic for conservative contacts).
#include "TestCase.hpp"

#include "polyDEM/RandomFill.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace polydem;

TEST(EnergyConservation, elasticFrictionlessBox)
{
    const double r = 0.002, L = 0.06;
    SimulationConfig cfg = test::sphereConfig(ContactLaw::hertzMindlin, 1.0, 0.0, r, 5e6);
    cfg.gravity = Vec3(0, 0, -9.81);
    cfg.planes = {test::plane(Vec3(0, 0, 0), Vec3(1, 0, 0)), test::plane(Vec3(L, 0, 0), Vec3(-1, 0, 0)),
                  test::plane(Vec3(0, 0, 0), Vec3(0, 1, 0)), test::plane(Vec3(0, L, 0), Vec3(0, -1, 0)),
                  test::plane(Vec3(0, 0, 0), Vec3(0, 0, 1)), test::plane(Vec3(0, 0, L), Vec3(0, 0, -1))};
    cfg.timeStep = 1e-6;  // replaced below by a fraction of the stability limit
    System probe(cfg);
    const auto seeds = randomFill(FillRegion::box(Vec3(0, 0, 0), Vec3(L, L, L)),
                                  SizeDistribution::fixedDiameter(2 * r), 1000, 7);
    std::vector<Vec3> x;
    for (const auto& s : seeds) x.push_back(s.position);
    Snapshot st;
    st.particles = probe.makeSpheres(0, x, {}, 0);
    std::mt19937_64 rng(3);
    std::normal_distribution<double> g(0, 0.1);
    for (auto& v : st.particles.velocity) v = Vec3(g(rng), g(rng), g(rng));

    // 1/5 of the stability limit: ~40 steps per collision at these speeds
    cfg.timeStep = 0.2 * probe.criticalTimeStep(st.particles);
    System s(cfg);
    s.initialise(st);
    const double e0 = s.engine().energies().total();
    double worst = 0;
    for (int block = 0; block < 100; ++block)
    {
        s.advance(1000);
        const Energies e = s.engine().energies();
        worst = std::max(worst, std::fabs(e.total() - e0) / std::fabs(e0));
    }
    const auto st1 = s.engine().statistics();
    EXPECT_GT(st1.neighbourListBuilds, 2u) << "particles must have moved";
    EXPECT_LT(worst, 1e-3) << "relative energy drift over 1e5 steps";
    std::printf("time step %.3g s, worst relative energy error %.3g\n", cfg.timeStep, worst);
}

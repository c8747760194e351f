// Outlets and the removal log (Config::outlets, Engine::takeRemoved), the
// external forces through addParticles, and the normal/frictional split of
// the wall load (WallLoad::normalForce, contacts):
//  - spheres moving at constant speed (no gravity, no contacts) into an
//    outlet box and out of the domain box are removed at a neighbour-list
//    rebuild, each reported once with its id, its mass and the region that
//    removed it (the outlet's index, -1 for the domain); present + removed =
//    inserted at every step
//  - addParticles keeps the external forces of the particles present (a
//    coupled run's inflow) and gives the new ones none
//  - a sphere on a 30 deg incline (mu = 0.3 > tan 30 / 3.5: it rolls
//    without slipping): the frictional part of its load never exceeds mu
//    times the normal part, and once rolling is steady the normal part is
//    m g cos 30 and the frictional part m g sin 30 / 3.5 (solid sphere);
//    one contact (the sliding case, friction = mu N, is the case test
//    demFoam_iceResistance_incline with a cube)
#include "TestCase.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

using namespace polydem;

namespace
{

const double r = 0.005;

} // namespace


TEST(Outlets, removedCountedPerRegion)
{
    SimulationConfig cfg = test::sphereConfig(ContactLaw::hertzMindlin, 0.3, 0.5, r);
    cfg.gravity = Vec3(0, 0, 0);
    cfg.timeStep = 1e-5;
    cfg.domainMin = Vec3(-1, -1, -1);
    cfg.domainMax = Vec3(1, 0.2, 1);
    OutletRegion out;
    out.name = "downstream";
    out.min = Vec3(0.2, -1, -1);
    out.max = Vec3(1, 1, 1);
    cfg.outlets.push_back(out);

    System s(cfg);
    Snapshot st;
    std::vector<Vec3> x;
    for (int i = 0; i < 10; ++i) x.push_back(Vec3(0.015 * i, 0, 0));  // all start inside
    st.particles = s.makeSpheres(0, x, {}, 0);
    // Five go downstream (+x), five sideways out of the domain (+y)
    for (int i = 0; i < 10; ++i)
    {
        st.particles.velocity[i] = i % 2 ? Vec3(0, 1, 0) : Vec3(1, 0, 0);
    }
    const double m = st.particles.mass[0];
    s.initialise(st);

    std::set<std::int64_t> seen;
    int outlet = 0, domain = 0;
    for (int k = 0; k < 100; ++k)
    {
        s.advance(1000);
        for (const RemovedParticle& q : s.engine().takeRemoved())
        {
            EXPECT_TRUE(seen.insert(q.id).second) << "particle " << q.id << " removed twice";
            EXPECT_DOUBLE_EQ(q.mass, m);
            if (q.id % 2)
            {
                EXPECT_EQ(q.region, -1) << "particle " << q.id << " left through the side";
                EXPECT_GT(q.position.y, cfg.domainMax.y - 0.01);
                ++domain;
            }
            else
            {
                EXPECT_EQ(q.region, 0) << "particle " << q.id << " went downstream";
                EXPECT_GT(q.position.x, out.min.x - 0.01);
                ++outlet;
            }
        }
        EXPECT_EQ(s.engine().particles().size() + seen.size(), 10u);
    }
    // 1 s at 1 m/s: all are out (the outlet starts at x = 0.2 m, the domain ends at y = 0.2 m)
    EXPECT_EQ(outlet, 5);
    EXPECT_EQ(domain, 5);
    EXPECT_EQ(s.engine().particles().size(), 0u);
    EXPECT_TRUE(s.engine().takeRemoved().empty());
}


TEST(Outlets, addParticlesKeepsExternalForces)
{
    SimulationConfig cfg = test::sphereConfig(ContactLaw::hertzMindlin, 0.3, 0.5, r);
    cfg.gravity = Vec3(0, 0, 0);
    cfg.timeStep = 1e-5;
    System s(cfg);
    Snapshot st;
    st.particles = s.makeSpheres(0, {Vec3(0, 0, 0), Vec3(0.1, 0, 0)}, {}, 0);
    s.initialise(st);
    const double m = st.particles.mass[0];
    const Vec3 F0(1e-3, 0, 0), F1(0, 2e-3, 0);
    {
        const ParticleState p = s.engine().particles();
        std::vector<Vec3> F(2);
        for (int i = 0; i < 2; ++i) F[i] = p.id[i] == 0 ? F0 : F1;
        s.engine().setExternalForces(F, {});
    }
    s.addParticles(s.makeSpheres(0, {Vec3(0.2, 0, 0)}, {}, 2));
    const int n = 1000;
    s.advance(n);
    const ParticleState p = s.engine().particles();
    ASSERT_EQ(p.size(), 3u);
    const double t = n * cfg.timeStep;
    for (size_t i = 0; i < p.size(); ++i)
    {
        const Vec3 F = p.id[i] == 0 ? F0 : (p.id[i] == 1 ? F1 : Vec3());
        // v = F t / m (constant force from rest; leapfrog is exact for it)
        EXPECT_NEAR(norm(p.velocity[i] - (t / m) * F), 0, 1e-9 * (1 + norm(F) * t / m))
            << "particle " << p.id[i];
    }
}


TEST(Outlets, wallLoadSplitOnIncline)
{
    const double mu = 0.3, theta = M_PI / 6, g = 9.81;
    SimulationConfig cfg = test::sphereConfig(ContactLaw::hertzMindlin, 0.3, mu, r);
    cfg.gravity = Vec3(g * std::sin(theta), 0, -g * std::cos(theta));
    cfg.timeStep = 2e-6;
    cfg.planes.push_back(test::plane(Vec3(0, 0, 0), Vec3(0, 0, 1)));
    System s(cfg);
    Snapshot st;
    st.particles = s.makeSpheres(0, {Vec3(0, 0, r - 1e-6)}, {}, 0);
    s.initialise(st);
    s.engine().enableWallLoads(true);
    const double m = st.particles.mass[0];
    int rolling = 0;
    for (int k = 0; k < 20000; ++k)
    {
        s.advance(1);
        const WallLoad l = s.engine().wallLoads()[0];
        if (l.contacts == 0) continue;
        EXPECT_DOUBLE_EQ(l.contacts, 1);
        const double N = norm(l.normalForce), F = norm(l.frictionForce());
        // A sphere rolls without slipping when mu > tan(theta)/3.5: here
        // mu = 0.3 > 0.165, so it rolls and static friction is below mu N;
        // it must never exceed it
        EXPECT_LE(F, mu * N * (1 + 1e-9));
        if (k > 10000)
        {
            // Rolling without slip: friction = m g sin / 3.5 (solid sphere,
            // I = 2/5 m r^2); normal = m g cos
            EXPECT_NEAR(N, m * g * std::cos(theta), 1e-3 * m * g);
            EXPECT_NEAR(F, m * g * std::sin(theta) / 3.5, 2e-3 * m * g);
            ++rolling;
        }
    }
    EXPECT_GT(rolling, 9000);
}

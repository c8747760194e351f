// Spheres among polyhedra under the volumetric law: a sphere resting on a
// cube resting on a plane is in equilibrium (forces balance to round-off),
// and sphere-sphere lens contacts conserve momentum exactly.
#include "PolyhedraCase.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace polydem;

TEST(PolyhedraMixed, sphereOnCubeOnPlaneComesToRest)
{
    const double a = 0.01, r = 0.004;
    SimulationConfig cfg = test::polyhedronConfig(makeCube(a), 0.3, 0.5);
    ParticleType sphere;
    sphere.name = "ball";
    sphere.radius = r;
    cfg.types.push_back(sphere);
    cfg.timeStep = 2e-6;
    cfg.planes.push_back(test::plane(Vec3(0, 0, 0), Vec3(0, 0, 1)));
    System s(cfg);
    Snapshot st = test::polyhedraAt(s, {Vec3(0, 0, 0.5 * a)}, {});
    ParticleState ball = s.makeSpheres(1, {Vec3(0, 0, a + r + 1e-4)}, {}, 1);
    st.particles.resize(2);
    st.particles.id[1] = 1;
    st.particles.type[1] = 1;
    st.particles.radius[1] = r;
    st.particles.mass[1] = ball.mass[0];
    st.particles.inertia[1] = ball.inertia[0];
    st.particles.position[1] = ball.position[0];
    s.initialise(st);
    s.advance(200000);  // 0.4 s
    const auto p = s.engine().particles();
    for (std::size_t i = 0; i < p.size(); ++i)
    {
        EXPECT_LT(norm(p.velocity[i]), 1e-5);
        EXPECT_LT(std::hypot(p.position[i].x, p.position[i].y), 1e-9) << "no sideways push";
    }
    // the ball rests on the top face: its centre a little less than a + r up
    const std::size_t ib = p.id[0] == 1 ? 0 : 1;
    EXPECT_NEAR(p.position[ib].z, a + r, 0.02 * r);
}

TEST(PolyhedraMixed, sphereLensContactConservesMomentum)
{
    const double r = 0.004;
    SimulationConfig cfg = test::polyhedronConfig(makeCube(0.01), 0.5, 0.3);
    ParticleType sphere;
    sphere.name = "ball";
    sphere.radius = r;
    cfg.types = {sphere};
    cfg.shapes.clear();
    cfg.gravity = Vec3(0, 0, 0);
    cfg.timeStep = 1e-6;
    System s(cfg);
    Snapshot st;
    st.particles = s.makeSpheres(0, {Vec3(0, 0, 0), Vec3(2 * r + 1e-5, 0.3 * r, 0)}, {}, 0);
    st.particles.velocity[0] = Vec3(0.5, 0, 0);
    s.initialise(st);
    s.advance(20000);
    const auto p = s.engine().particles();
    const Vec3 P = p.mass[0] * p.velocity[0] + p.mass[1] * p.velocity[1];
    EXPECT_NEAR(P.x, p.mass[0] * 0.5, 1e-15);
    EXPECT_NEAR(P.y, 0, 1e-15);
    EXPECT_GT(norm(p.velocity[1]), 0.1) << "they must have collided";
}

// Wall loads (Engine::wallLoads, wallLoadSum): the load of the particles on
// each wall is the reaction to the wall's contact forces on them.
//  - A sphere resting on a plane, and on a triangle-mesh floor: the load is
//    its weight m g, the torque about a point O is (x - O) x m g (x the
//    centre: the contact point lies below it, on the line of the weight).
//  - At every step, with friction and rolling resistance, a single particle's
//    load equals m g - F and its torque about O -(x - O) x (F - m g) - T
//    (F, T the particle's total force and torque: gravity and that wall only)
//    to round-off; the per-step sum over n steps is n times the mean.
//  - Turning the loads on changes no particle's trajectory by a bit.
#include "TestCase.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace polydem;

namespace
{

TriangleMesh flatMesh(double L, int n)
{
    TriangleMesh m;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i)
            m.points.push_back(Vec3(-L + 2 * L * i / n, -L + 2 * L * j / n, 0));
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
        {
            const int a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
            m.triangles.push_back({a, b, d});
            m.triangles.push_back({a, d, c});
        }
    m.source = "flatMesh";
    return m;
}

const double r = 0.005;
const Vec3 g(0, 0, -9.81);
const Vec3 O(0.02, -0.01, 0.03);

SimulationConfig floorConfig(bool mesh)
{
    SimulationConfig cfg = test::sphereConfig(ContactLaw::hertzMindlin, 0.3, 0.5, r);
    cfg.contact.rolling = RollingModel::elasticPlastic;
    cfg.pairs[0].rollingFriction = 0.05;
    cfg.gravity = g;
    cfg.timeStep = 2e-6;
    if (mesh)
    {
        MeshWall w;
        w.name = "floor";
        w.mesh = flatMesh(0.05, 4);
        w.loadPoint = O;
        cfg.meshes.push_back(w);
    }
    else
    {
        PlaneWall w = test::plane(Vec3(0, 0, 0), Vec3(0, 0, 1));
        w.loadPoint = O;
        cfg.planes.push_back(w);
    }
    return cfg;
}

//- A sphere dropped with spin and sideways speed onto the floor
Snapshot dropped(System& s)
{
    Snapshot st;
    st.particles = s.makeSpheres(0, {Vec3(0.003, 0.001, r + 2e-4)}, {}, 0);
    st.particles.velocity[0] = Vec3(0.005, -0.002, -0.1);
    st.particles.omega[0] = Vec3(1, 1, 0.5);
    return st;
}

double relErr(const Vec3& a, const Vec3& b, double scale)
{
    return norm(a - b) / scale;
}

void checkFloor(bool mesh)
{
    System s(floorConfig(mesh));
    s.initialise(dropped(s));
    s.engine().enableWallLoads(true);
    ASSERT_TRUE(s.engine().wallLoadsEnabled());
    const double m = s.engine().particles().mass[0];
    const double W = m * norm(g);

    // Every step: the reaction of the particle's wall force, to round-off
    Vec3 sumF, sumT;
    int touching = 0;
    const int nSteps = 20000;
    for (int k = 0; k < nSteps; ++k)
    {
        s.advance(1);
        const ParticleState p = s.engine().particles();
        const std::vector<WallLoad> loads = s.engine().wallLoads();
        ASSERT_EQ(loads.size(), 1u);
        const Vec3 f = p.force[0] - m * g;    // the wall's force on the particle
        const Vec3 expectF = -1.0 * f;
        const Vec3 expectT = -1.0 * (cross(p.position[0] - O, f) + p.torque[0]);
        if (norm(f) > 0) ++touching;
        EXPECT_LE(relErr(loads[0].force, expectF, W), 1e-12) << "step " << k;
        EXPECT_LE(relErr(loads[0].torque, expectT, W * 0.05), 1e-12) << "step " << k;
        EXPECT_LE(norm(loads[0].point - O), 0.0);
        sumF += loads[0].force;
        sumT += loads[0].torque;
    }
    EXPECT_GT(touching, nSteps / 2) << "the sphere must roll on the floor";
    const WallLoadSum sum = s.engine().wallLoadSum();
    EXPECT_EQ(sum.steps, nSteps);
    EXPECT_LE(relErr(sum.sum[0].force, sumF, nSteps * W), 1e-12);
    EXPECT_LE(relErr(sum.sum[0].torque, sumT, nSteps * W * 0.05), 1e-12);

    // At rest (set down without sideways motion or spin, the bounce damped
    // out): the weight, and its moment about O
    System rest(floorConfig(mesh));
    Snapshot st;
    st.particles = rest.makeSpheres(0, {Vec3(0.003, 0.001, r + 1e-6)}, {}, 0);
    rest.initialise(st);
    rest.engine().enableWallLoads(true);
    rest.advance(20000);
    const ParticleState p = rest.engine().particles();
    ASSERT_LT(norm(p.velocity[0]), 1e-6) << "not at rest yet";
    const std::vector<WallLoad> loads = rest.engine().wallLoads();
    EXPECT_LE(relErr(loads[0].force, m * g, W), 1e-6);
    const Vec3 T = cross(p.position[0] - O, m * g);
    EXPECT_LE(relErr(loads[0].torque, T, W * norm(p.position[0] - O)), 1e-6);

    // Reset: the sum starts again
    rest.engine().resetWallLoadSum();
    rest.advance(10);
    EXPECT_EQ(rest.engine().wallLoadSum().steps, 10);
    EXPECT_LE(relErr(rest.engine().wallLoadSum().sum[0].force, 10.0 * m * g, 10 * W), 1e-6);
}

} // namespace

TEST(WallLoads, restingSphereOnPlane)
{
    checkFloor(false);
}

TEST(WallLoads, restingSphereOnMesh)
{
    checkFloor(true);
}

// A rotating drum of planes and a mesh with many particles: the loads
// summed over the walls balance gravity and the particles' force and torque
// sums (the pair forces cancel), and the loads leave the motion unchanged.
TEST(WallLoads, manyParticlesBalanceAndNoEffectOnMotion)
{
    auto run = [](bool loads, std::vector<WallLoad>* out, ParticleState* state) {
        SimulationConfig cfg = test::sphereConfig(ContactLaw::linearSpringDashpot, 0.5, 0.4, r);
        cfg.contact.normalStiffness = 2e3;
        cfg.contact.rolling = RollingModel::constantTorque;
        cfg.pairs[0].rollingFriction = 0.02;
        cfg.gravity = g;
        cfg.timeStep = 2e-5;
        WallMotion spin;
        spin.kind = MotionKind::rotation;
        spin.origin = Vec3(0, 0, 0.03);
        spin.axis = Vec3(0, 1, 0);
        spin.omega = 2.0;
        MeshWall floor;
        floor.name = "floor";
        floor.mesh = flatMesh(0.05, 4);
        floor.motion = spin;
        floor.loadPoint = spin.origin;
        cfg.meshes.push_back(floor);
        for (double sx : {-1.0, 1.0})
        {
            PlaneWall w = test::plane(Vec3(sx * 0.03, 0, 0), Vec3(-sx, 0, 0), "side");
            w.motion = spin;
            w.loadPoint = spin.origin;
            cfg.planes.push_back(w);
        }
        System s(cfg);
        std::vector<Vec3> x;
        for (int i = 0; i < 5; ++i)
            for (int j = 0; j < 4; ++j)
                for (int k = 0; k < 3; ++k)
                    x.push_back(Vec3(-0.022 + 0.011 * i, -0.015 + 0.011 * j, 0.006 + 0.011 * k));
        Snapshot st;
        st.particles = s.makeSpheres(0, x, {}, 0);
        s.initialise(st);
        s.engine().enableWallLoads(loads);
        s.advance(3000);
        if (out) *out = s.engine().wallLoads();
        *state = s.engine().particles();
    };
    std::vector<WallLoad> loads;
    ParticleState with, without;
    run(true, &loads, &with);
    run(false, nullptr, &without);
    ASSERT_EQ(with.size(), without.size());
    for (size_t i = 0; i < with.size(); ++i)
    {
        EXPECT_EQ(with.position[i].x, without.position[i].x);
        EXPECT_EQ(with.position[i].z, without.position[i].z);
        EXPECT_EQ(with.velocity[i].x, without.velocity[i].x);
        EXPECT_EQ(with.omega[i].y, without.omega[i].y);
    }
    ASSERT_EQ(loads.size(), 3u);
    const Vec3 O(0, 0, 0.03);
    Vec3 F, T, wF, wT;
    double W = 0;
    for (size_t i = 0; i < with.size(); ++i)
    {
        const Vec3 f = with.force[i] - with.mass[i] * g;
        F -= f;
        T -= cross(with.position[i] - O, f) + with.torque[i];
        W += with.mass[i] * norm(g);
    }
    for (const WallLoad& l : loads)
    {
        wF += l.force;
        wT += l.torque;
        EXPECT_LE(norm(l.point - O), 1e-15);
    }
    EXPECT_GT(norm(wF), 0.5 * W) << "the particles must rest on the walls";
    EXPECT_LE(norm(wF - F), 1e-9 * W);
    EXPECT_LE(norm(wT - T), 1e-9 * W * 0.05);
}

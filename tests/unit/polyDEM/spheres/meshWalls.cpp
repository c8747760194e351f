// Triangle-mesh walls behave like the surface they tessellate: a sphere hitting
// a shared edge or vertex of a flat mesh rebounds as from a plane (each touch
// counted once), a sphere rolls across triangle edges as on a plane, and a
// rotating mesh drags particles at the wall speed.
#include "TestCase.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace polydem;

namespace
{

//- Square [-L, L]^2 at z = 0 split into n x n cells, two triangles each
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

double bounce(const Vec3& at, bool useMesh)
{
    const double r = 0.005, v0 = 0.5;
    SimulationConfig cfg = test::sphereConfig(ContactLaw::hertzMindlin, 0.6, 0.0, r);
    cfg.timeStep = 1e-6;
    if (useMesh)
    {
        MeshWall w;
        w.name = "floor";
        w.mesh = flatMesh(0.05, 4);
        cfg.meshes.push_back(w);
    }
    else
    {
        cfg.planes.push_back(test::plane(Vec3(0, 0, 0), Vec3(0, 0, 1)));
    }
    System s(cfg);
    Snapshot st;
    st.particles = s.makeSpheres(0, {at + Vec3(0, 0, r + 1e-5)}, {}, 0);
    st.particles.velocity[0] = Vec3(0, 0, -v0);
    s.initialise(st);
    bool touched = false;
    for (int k = 0; k < 100000; ++k)
    {
        s.advance(1);
        const auto n = s.engine().statistics().wallContacts;
        EXPECT_LE(n, 1u) << "one touch of a flat surface must count once";
        if (n > 0) touched = true;
        if (touched && n == 0) break;
    }
    return s.engine().particles().velocity[0].z / v0;
}

} // namespace

TEST(MeshWalls, edgeAndVertexHitsReboundLikePlane)
{
    const double ePlane = bounce(Vec3(0.003, 0.001, 0), false);
    EXPECT_NEAR(ePlane, 0.6, 0.012);
    // interior of a triangle, the diagonal edge, a vertex shared by 6 triangles
    for (const Vec3& at : {Vec3(0.013, 0.004, 0), Vec3(0.0125, 0.0125, 0), Vec3(0, 0, 0)})
    {
        EXPECT_NEAR(bounce(at, true), ePlane, 1e-6 * ePlane);
    }
}

TEST(MeshWalls, rollsAcrossTriangles)
{
    const double r = 0.004, v0 = 0.5, E = 1e7, nu = 0.3, rho = 2500;
    SimulationConfig cfg = test::sphereConfig(ContactLaw::hertzMindlin, 0.5, 0.3, r, E, nu, rho);
    cfg.gravity = Vec3(0, 0, -9.81);
    cfg.timeStep = 2e-6;
    MeshWall w;
    w.name = "floor";
    w.mesh = flatMesh(0.5, 40);  // 2.5 cm cells: the sphere crosses many edges
    cfg.meshes.push_back(w);
    System s(cfg);
    const double m = rho * 4.0 / 3.0 * M_PI * r * r * r;
    const double eff = 1.0 / (2 * (1 - nu * nu) / E);
    const double d = std::pow(m * 9.81 / (4.0 / 3.0 * eff * std::sqrt(r)), 2.0 / 3.0);
    Snapshot st;
    st.particles = s.makeSpheres(0, {Vec3(-0.3, 0.001, r - d)}, {}, 0);
    st.particles.velocity[0] = Vec3(v0, 0.1 * v0, 0);
    s.initialise(st);
    s.advance(100000);
    const auto p = s.engine().particles();
    const double speed = std::hypot(p.velocity[0].x, p.velocity[0].y);
    EXPECT_NEAR(speed / std::hypot(v0, 0.1 * v0), 5.0 / 7.0, 0.01 * 5.0 / 7.0);
    EXPECT_NEAR(p.position[0].z, r - d, 0.05 * d) << "no bumps at triangle edges";
}

TEST(MeshWalls, rotatingDrumDragsParticle)
{
    // A sphere resting on the inside of a drum (no gravity, pressed outwards by
    // a constant external force) is taken along until it rolls without slip:
    // its contact point then moves with the wall material.
    const double r = 0.003, R = 0.05, rpm = 30;
    SimulationConfig cfg = test::sphereConfig(ContactLaw::hertzMindlin, 0.5, 0.8, r);
    cfg.timeStep = 2e-6;
    MeshWall w;
    w.name = "drum";
    const int n = 120;
    for (int k = 0; k < n; ++k)
    {
        const double a = 2 * M_PI * k / n;
        w.mesh.points.push_back(Vec3(R * std::cos(a), R * std::sin(a), -0.02));
        w.mesh.points.push_back(Vec3(R * std::cos(a), R * std::sin(a), 0.02));
    }
    for (int k = 0; k < n; ++k)
    {
        const int a = 2 * k, b = 2 * k + 1, c = 2 * ((k + 1) % n), d = c + 1;
        w.mesh.triangles.push_back({a, c, d});
        w.mesh.triangles.push_back({a, d, b});
    }
    w.motion.kind = MotionKind::rotation;
    w.motion.axis = Vec3(0, 0, 1);
    w.motion.omega = rpm * 2 * M_PI / 60;
    cfg.meshes.push_back(w);
    System s(cfg);
    Snapshot st;
    st.particles = s.makeSpheres(0, {Vec3(R - r, 0, 0)}, {}, 0);
    s.initialise(st);
    const double m = st.particles.mass[0];
    s.engine().setExternalForces({Vec3(20 * m * 9.81, 0, 0)}, {});
    s.advance(50000);  // 0.1 s
    const auto p = s.engine().particles();
    const Vec3 x = p.position[0];
    const Vec3 radial = Vec3(x.x, x.y, 0) / std::hypot(x.x, x.y);
    const Vec3 contact = x + r * radial;
    const Vec3 vContact = p.velocity[0] + cross(p.omega[0], r * radial);
    const Vec3 vWall = cross(Vec3(0, 0, w.motion.omega), contact);
    EXPECT_GT(norm(p.velocity[0]), 0.2 * norm(vWall)) << "the drum must take the particle along";
    EXPECT_LT(norm(vContact - vWall), 0.02 * norm(vWall)) << "rolling without slip on the wall";
}

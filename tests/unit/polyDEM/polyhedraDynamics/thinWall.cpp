// A cube gliding past a thin closed body (a slab 0.1 m thick, the cube's
// own size) 5 mm off its face never touches it: no wall contact, velocity
// and spin unchanged. Each triangle's wall solid stops at the body's middle
// (wallDepths); with prisms of unlimited depth the far face's reach through
// the slab onto the cube (the brash-ice hull's phantom contacts), which the
// control run shows. Pressed against the face, the cube rebounds with the
// input restitution (face contact, as on a plane), also across two triangles.
#include "PolyhedraCase.hpp"
#include "TestMeshes.hpp"

#include "polyDEM/WallDepths.hpp"
#include "polyDEM/PolyhedronOverlap.hpp"

#include <gtest/gtest.h>

#include <algorithm>

using namespace polydem;

namespace
{

const double a = 0.1;   // cube edge = slab thickness

SimulationConfig slabConfig(double e, bool floors)
{
    SimulationConfig cfg = test::polyhedronConfig(makeCube(a), e, 0.5, 1e8);
    cfg.gravity = Vec3(0, 0, 0);
    cfg.timeStep = 1e-4;
    MeshWall w;
    w.name = "slab";
    w.mesh = test::closedBox(Vec3(-1, -0.05, -0.25), Vec3(1, 0.05, 0.25));
    if (!floors)
    {
        // Given depths are kept by System: the old, unlimited prisms
        w.wallDepth.assign(w.mesh.size(), kUnboundedWallDepth);
    }
    cfg.meshes.push_back(w);
    return cfg;
}

//- Steps with a wall contact while the cube glides 1 m along the face
int glide(bool floors, Vec3& v, Vec3& omega)
{
    System s(slabConfig(0.5, floors));
    Snapshot st = test::polyhedraAt(s, {Vec3(-0.5, -0.05 - 0.5 * a - 0.005, 0)}, {});
    st.particles.velocity[0] = Vec3(1, 0, 0);
    s.initialise(st);
    int touching = 0;
    for (int k = 0; k < 10000; ++k)
    {
        s.advance(1);
        if (s.engine().statistics().wallContacts > 0) ++touching;
    }
    const auto p = s.engine().particles();
    v = p.velocity[0];
    omega = p.omega[0];
    return touching;
}

} // namespace


TEST(PolyhedraWalls, glidesPastThinBodyUntouched)
{
    Vec3 v, omega;
    EXPECT_EQ(glide(true, v, omega), 0);
    EXPECT_LT(norm(v - Vec3(1, 0, 0)), 1e-12);
    EXPECT_LT(norm(omega), 1e-12);

    // Control: the test can fail. Unlimited prisms reach the cube through
    // the slab and throw it
    const int phantom = glide(false, v, omega);
    std::printf("unlimited prisms: %d of 10000 steps with a wall contact, v (%g %g %g)\n",
                phantom, v.x, v.y, v.z);
    EXPECT_GT(phantom, 0);
    EXPECT_GT(norm(v - Vec3(1, 0, 0)), 0.1);
}


TEST(PolyhedraWalls, reboundsFromThinBody)
{
    const double v0 = 0.2;
    // Within one triangle of the face, and across the face's diagonal (the
    // contact split between two triangles: one contact, so the same
    // restitution; e 0.21 for 0.3 when each triangle was a contact with its
    // own dashpot, which goes with the root of its area)
    for (const Vec3 at : {Vec3(0.6, 0, -0.1), Vec3(0, 0, 0)})
    {
        for (double e : {0.3, 0.8})
        {
            SimulationConfig cfg = slabConfig(e, true);
            cfg.timeStep = 1e-5;   // 500 steps per contact
            System s(cfg);
            Snapshot st = test::polyhedraAt(s, {at + Vec3(0, -0.05 - 0.5 * a - 1e-4, 0)}, {});
            st.particles.velocity[0] = Vec3(0, v0, 0);
            s.initialise(st);
            bool touched = false;
            int most = 0;
            for (int k = 0; k < 20000; ++k)
            {
                s.advance(1);
                const int c = int(s.engine().statistics().wallContacts);
                most = std::max(most, c);
                touched = touched || c > 0;
                if (touched && c == 0) break;
            }
            const auto p = s.engine().particles();
            EXPECT_EQ(most, 1) << "one contact at x = " << at.x;
            EXPECT_NEAR(-p.velocity[0].y / v0, e, 0.03 * e) << "at x = " << at.x;
            EXPECT_LT(std::fabs(p.velocity[0].x) + std::fabs(p.velocity[0].z), 1e-9 * v0);
        }
    }
}


// A cube on a finely tessellated floor (0.025 m squares: a resting face
// covers 32 triangles) rests at the plane's depth mg/(Kn A) and, pushed at
// 1 m/s, slides v^2/(2 mu g) before it stops (one contact: all triangles
// counted, one friction history carried as it crosses triangle edges)
TEST(PolyhedraWalls, slidesOnFineMeshAsOnPlane)
{
    const double mu = 0.4, g = 9.81, v0 = 1.0, Kn = 1e8;
    TriangleMesh floor;
    const int n = 80;
    const double h = 0.025;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) floor.points.push_back(Vec3(-0.5 + i * h, -1 + j * h, 0));
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
        {
            const int p = j * (n + 1) + i;
            floor.triangles.push_back({p, p + 1, p + n + 2});
            floor.triangles.push_back({p, p + n + 2, p + n + 1});
        }
    floor.source = "fineFloor";
    SimulationConfig cfg = test::polyhedronConfig(makeCube(a), 0.3, mu, Kn);
    cfg.timeStep = 2e-5;
    MeshWall w;
    w.name = "floor";
    w.mesh = floor;
    cfg.meshes.push_back(w);
    System s(cfg);
    // Off the grid lines, so that the face starts across 4 x 4 squares
    Snapshot st = test::polyhedraAt(s, {Vec3(0.0113, -0.5137, 0.5 * a)}, {});
    s.initialise(st);
    s.advance(20000);   // 0.4 s: settled
    auto p = s.engine().particles();
    const double mass = p.mass[0];
    const double sink = mass * g / (Kn * a * a);
    EXPECT_NEAR(0.5 * a - p.position[0].z, sink, 0.02 * sink) << "rest depth";
    EXPECT_EQ(s.engine().statistics().wallContacts, 1u);

    st = s.engine().snapshot();
    const double y0 = p.position[0].y;
    st.particles.velocity[0] = Vec3(0, v0, 0);
    s.initialise(st);
    for (int k = 0; k < 100000; ++k)
    {
        s.advance(100);
        if (norm(s.engine().particles().velocity[0]) < 1e-6) break;
    }
    p = s.engine().particles();
    const double slid = p.position[0].y - y0;
    const double expected = v0 * v0 / (2 * mu * g);
    std::printf("fine floor: rest depth %.4g (mg/(Kn A) %.4g), slid %.4f m (v^2/(2 mu g) %.4f)\n",
                0.5 * a - p.position[0].z, sink, slid, expected);
    EXPECT_NEAR(slid, expected, 0.02 * expected);
    EXPECT_LT(std::fabs(p.position[0].x - 0.0113), 1e-3) << "straight";
}


// A cube resting on a closed body with a quarter of its base over the edge
// (its centre of mass over the body) stays where it is, tilted so that the
// overlap's centroid is under its centre: a triangular overlap of depth
// 2 mg/(Kn L a) at the edge (L: the supported length), the centre sunk by
// two thirds of that. The edge is convex: the side face's solid meets the
// top's on their bisector, so only a sliver of depth ~ the sink is the side
// face's (a sideways push ~ sink/L of the weight, far below friction).
// With each face's normal prism the side face's prism (0.1 m deep) held the
// whole supported part again, with the same upward area vector: twice the
// stiffness, and the cube sank and tilted half as much (2.18e-5 m and
// 4.4e-4 rad against 4.36e-5 and 8.7e-4).
TEST(PolyhedraWalls, restsOverConvexEdge)
{
    const double mu = 0.5, g = 9.81, Kn = 1e8;
    const double overhang = 0.25 * a, L = a - overhang;
    SimulationConfig cfg = test::polyhedronConfig(makeCube(a), 0.3, mu, Kn);
    cfg.timeStep = 2e-5;
    MeshWall w;
    w.name = "table";
    w.mesh = test::closedBox(Vec3(-0.5, -0.5, -0.2), Vec3(0.5, 0.5, 0));
    cfg.meshes.push_back(w);
    System s(cfg);
    const Vec3 x0(0.5 + overhang - 0.5 * a, 0.0137, 0.5 * a);
    Snapshot st = test::polyhedraAt(s, {x0}, {});
    s.initialise(st);
    s.advance(20000);   // 0.4 s: settled
    const auto p = s.engine().particles();
    const double mass = p.mass[0];
    const double edgeDepth = 2 * mass * g / (Kn * L * a);
    const double sink = 2.0 / 3.0 * edgeDepth;
    const Vec3 up = rotate(p.orientation[0], Vec3(0, 0, 1));
    const double tilt = std::atan2(up.x, up.z);   // about +y: the overhanging side down
    // The base's centre: the centre moves (a/2) sin(tilt) as the cube tilts
    const double slid = p.position[0].x - 0.5 * a * up.x - x0.x;
    std::printf("cube over a convex edge: base slid %.3g m, sank %.4g (2/3 of 2 mg/(Kn L a): %.4g),"
                " tilt %.4g rad (2 mg/(Kn L^2 a): %.4g)\n",
                slid, 0.5 * a - p.position[0].z, sink, tilt, edgeDepth / L);
    EXPECT_LT(std::fabs(slid), 1e-6) << "held by friction";
    EXPECT_NEAR(0.5 * a - p.position[0].z, sink, 0.03 * sink) << "rest depth";
    EXPECT_NEAR(tilt, edgeDepth / L, 0.05 * edgeDepth / L) << "tilt";
}

// Insertion (polyDEM/Insertion.hpp): the particles of a list insertion are
// the ones listed; a random fill places N non-overlapping particles inside
// its region, clear of the particles present, the same bits for the same
// seed; polyhedra get one of their shapes and a unit orientation; and
// System::addParticles refuses particles the time step cannot resolve; and
// insertionOverlaps finds listed particles that overlap each other, the
// particles present or a wall (against exact geometry: depths of spheres,
// the overlap volume of cubes known by hand).
#include "polyDEM/Error.hpp"
#include "polyDEM/Insertion.hpp"
#include "polyDEM/InsertionChecks.hpp"
#include "polyDEM/System.hpp"

#include "ShapeGenerators.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

using namespace polydem;

namespace
{

const double rho = 2500;

//- Types: 0 sphere (d = 4 mm), 1..2 the two shapes of a polyhedral type
//  (cubes of 3 and 4 mm)
SimulationConfig config()
{
    SimulationConfig c;
    c.materials.push_back({"glass", 1e7, 0.3, rho});
    PairProperties pp;
    pp.restitution = 0.5;
    pp.friction = 0.3;
    c.pairs = {pp};
    c.contact.law = ContactLaw::overlapVolume;
    c.contact.volumetricStiffness = 1e9;
    c.shapes = {makeCube(0.003), makeCube(0.004)};
    ParticleType sphere;
    sphere.name = "bead";
    sphere.radius = 0.002;
    c.types.push_back(sphere);
    for (int k = 0; k < 2; ++k)
    {
        ParticleType t;
        t.name = "cube_" + std::to_string(k);
        t.shape = ShapeKind::polyhedron;
        t.shapeIndex = k;
        t.radius = c.shapes[k].boundingRadius;
        c.types.push_back(t);
    }
    c.gravity = Vec3(0, 0, 0);
    c.timeStep = 1e-6;
    c.device = "cpu";
    c.source = "test";
    return c;
}

InsertionTypes spheres() { return {0, 1, false}; }
InsertionTypes cubes() { return {1, 2, true}; }

RandomFillInsertion fill(const InsertionTypes& types, std::size_t n, std::uint64_t seed)
{
    RandomFillInsertion f;
    f.types = types;
    f.region = FillRegion::box(Vec3(0, 0, 0), Vec3(0.05, 0.04, 0.03));
    f.sizes = types.polyhedron
        ? SizeDistribution::discrete({{2 * config().types[1].radius, 1.0}, {2 * config().types[2].radius, 1.0}})
        : SizeDistribution::uniform(0.002, 0.004);
    f.number = n;
    f.seed = seed;
    f.gap = 1e-4;
    f.velocity = Vec3(0.1, -0.2, 0.3);
    return f;
}

bool sameBits(const ParticleState& a, const ParticleState& b)
{
    auto same = [](const auto& x, const auto& y)
    {
        return x.size() == y.size()
            && (x.empty() || std::memcmp(x.data(), y.data(), x.size() * sizeof(x[0])) == 0);
    };
    return same(a.id, b.id) && same(a.type, b.type) && same(a.radius, b.radius) && same(a.mass, b.mass)
        && same(a.inertia, b.inertia) && same(a.position, b.position)
        && same(a.orientation, b.orientation) && same(a.velocity, b.velocity) && same(a.omega, b.omega);
}

} // namespace


TEST(Insertion, listReproducesTheParticles)
{
    const System system(config());
    std::vector<ListedParticle> list(3);
    list[0].position = Vec3(0.01, 0.02, 0.03);
    list[0].velocity = Vec3(1, 2, 3);
    list[0].omega = Vec3(-1, 0, 4);
    list[0].orientation = normalised(Quaternion{0.9, 0.1, -0.3, 0.2});
    list[0].type = 1;
    list[0].radius = config().types[1].radius;
    list[1] = list[0];
    list[1].position = Vec3(0.04, 0.02, 0.03);
    list[1].type = 2;
    list[1].radius = config().types[2].radius;
    list[2] = list[0];
    list[2].position = Vec3(0.07, 0.02, 0.03);
    list[2].orientation = Quaternion();

    const ParticleState p = insertList(system, cubes(), list, 10);
    ASSERT_EQ(p.size(), list.size());
    for (std::size_t i = 0; i < p.size(); ++i)
    {
        EXPECT_EQ(p.id[i], std::int64_t(10 + i));
        EXPECT_EQ(p.type[i], list[i].type);
        for (int k = 0; k < 3; ++k)
        {
            EXPECT_EQ(p.position[i][k], list[i].position[k]);
            EXPECT_EQ(p.velocity[i][k], list[i].velocity[k]);
            EXPECT_EQ(p.omega[i][k], list[i].omega[k]);
        }
        EXPECT_EQ(p.orientation[i].w, list[i].orientation.w);
        EXPECT_EQ(p.orientation[i].x, list[i].orientation.x);
        EXPECT_EQ(p.orientation[i].y, list[i].orientation.y);
        EXPECT_EQ(p.orientation[i].z, list[i].orientation.z);
        const ConvexShape& shape = system.config().shapes[system.config().types[p.type[i]].shapeIndex];
        EXPECT_DOUBLE_EQ(p.mass[i], rho * shape.volume);
        EXPECT_DOUBLE_EQ(p.radius[i], shape.boundingRadius);
        EXPECT_DOUBLE_EQ(p.inertia[i].x, rho * shape.inertiaPerDensity.x);
    }

    // Spheres: a listed diameter is kept, mass from it
    std::vector<ListedParticle> beads(1);
    beads[0].position = Vec3(0, 0, 0);
    beads[0].radius = 0.003;
    const ParticleState s = insertList(system, spheres(), beads, 0);
    ASSERT_EQ(s.size(), 1u);
    EXPECT_EQ(s.radius[0], 0.003);
    EXPECT_DOUBLE_EQ(s.mass[0], rho * 4.0 / 3.0 * M_PI * std::pow(0.003, 3));
}


TEST(Insertion, randomFillPlacesNonOverlappingParticlesInTheRegion)
{
    const System system(config());

    // Obstacles: particles already there
    std::vector<ListedParticle> present(2);
    present[0].position = Vec3(0.025, 0.02, 0.015);
    present[0].radius = 0.006;
    present[1].position = Vec3(0.01, 0.01, 0.01);
    present[1].radius = 0.004;
    const ParticleState obstacles = insertList(system, spheres(), present, 0);

    const RandomFillInsertion f = fill(spheres(), 150, 7);
    const InsertedParticles ins = insertRandomFill(system, f, obstacles, nextParticleId(obstacles));
    const ParticleState& p = ins.particles;
    ASSERT_EQ(p.size(), f.number);

    double volume = 0;
    for (std::size_t i = 0; i < p.size(); ++i)
    {
        EXPECT_EQ(p.id[i], std::int64_t(2 + i));
        EXPECT_EQ(p.type[i], 0);
        EXPECT_GE(p.radius[i], 0.001 - 1e-15);
        EXPECT_LE(p.radius[i], 0.002 + 1e-15);
        EXPECT_TRUE(f.region.contains(p.position[i], p.radius[i])) << "particle " << i;
        EXPECT_EQ(p.velocity[i].x, f.velocity.x);
        EXPECT_EQ(p.velocity[i].z, f.velocity.z);
        EXPECT_GT(p.mass[i], 0);
        for (std::size_t j = 0; j < i; ++j)
        {
            EXPECT_GE(norm(p.position[i] - p.position[j]), p.radius[i] + p.radius[j] + f.gap - 1e-12)
                << "particles " << i << " and " << j << " overlap";
        }
        for (std::size_t j = 0; j < obstacles.size(); ++j)
        {
            EXPECT_GE(norm(p.position[i] - obstacles.position[j]),
                      p.radius[i] + obstacles.radius[j] + f.gap - 1e-12)
                << "particle " << i << " overlaps obstacle " << j;
        }
        volume += 4.0 / 3.0 * M_PI * std::pow(p.radius[i], 3);
    }
    EXPECT_NEAR(ins.volume, volume, 1e-12 * volume);
}


TEST(Insertion, randomFillIsDeterministicForASeed)
{
    const System system(config());
    for (const InsertionTypes& t : {spheres(), cubes()})
    {
        const auto a = insertRandomFill(system, fill(t, 60, 3), {}, 0);
        const auto b = insertRandomFill(system, fill(t, 60, 3), {}, 0);
        const auto c = insertRandomFill(system, fill(t, 60, 4), {}, 0);
        EXPECT_TRUE(sameBits(a.particles, b.particles)) << "same seed, different particles";
        EXPECT_FALSE(sameBits(a.particles, c.particles)) << "another seed, the same particles";
    }
}


TEST(Insertion, randomFillOfPolyhedra)
{
    const System system(config());
    RandomFillInsertion f = fill(cubes(), 80, 5);
    const InsertedParticles ins = insertRandomFill(system, f, {}, 0);
    const ParticleState& p = ins.particles;
    ASSERT_EQ(p.size(), f.number);
    int perType[3] = {0, 0, 0};
    double volume = 0;
    for (std::size_t i = 0; i < p.size(); ++i)
    {
        ASSERT_TRUE(p.type[i] == 1 || p.type[i] == 2);
        ++perType[p.type[i]];
        const ConvexShape& shape = system.config().shapes[system.config().types[p.type[i]].shapeIndex];
        // The bounding sphere placed is the shape's
        EXPECT_DOUBLE_EQ(p.radius[i], shape.boundingRadius);
        EXPECT_TRUE(f.region.contains(p.position[i], p.radius[i]));
        EXPECT_DOUBLE_EQ(p.mass[i], rho * shape.volume);
        const Quaternion& q = p.orientation[i];
        EXPECT_NEAR(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z, 1, 1e-14);
        volume += shape.volume;
    }
    EXPECT_GT(perType[1], 0);
    EXPECT_GT(perType[2], 0);
    EXPECT_NEAR(ins.volume, volume, 1e-12 * volume);

    // One given orientation for all
    f.fixedOrientation = true;
    f.orientation = normalised(Quaternion{0.5, 0.5, -0.5, 0.5});
    const ParticleState g = insertRandomFill(system, f, {}, 0).particles;
    ASSERT_EQ(g.size(), f.number);
    for (std::size_t i = 0; i < g.size(); ++i)
    {
        EXPECT_EQ(g.orientation[i].w, f.orientation.w);
        EXPECT_EQ(g.orientation[i].z, f.orientation.z);
    }
    // The positions and shapes do not depend on the orientations
    for (std::size_t i = 0; i < g.size(); ++i)
    {
        EXPECT_EQ(g.position[i].x, p.position[i].x);
        EXPECT_EQ(g.type[i], p.type[i]);
    }
}


TEST(Insertion, randomFillThatDoesNotFitThrows)
{
    const System system(config());
    RandomFillInsertion f = fill(spheres(), 100000, 1);
    EXPECT_THROW(insertRandomFill(system, f, {}, 0), Error);
}


TEST(Insertion, idsAndAppend)
{
    const System system(config());
    ParticleState a = insertRandomFill(system, fill(spheres(), 5, 1), {}, 0).particles;
    EXPECT_EQ(nextParticleId(ParticleState()), 0);
    EXPECT_EQ(nextParticleId(a), 5);
    const ParticleState b = insertRandomFill(system, fill(spheres(), 4, 2), a, nextParticleId(a)).particles;
    appendParticles(a, b);
    ASSERT_EQ(a.size(), 9u);
    EXPECT_EQ(a.force.size(), 9u);
    EXPECT_EQ(a.id[5], 5);
    EXPECT_EQ(a.position[8].x, b.position[3].x);
    EXPECT_EQ(nextParticleId(a), 9);
}


TEST(Insertion, addParticlesChecksTheContactStability)
{
    SimulationConfig c = config();
    c.timeStep = 1e-2;   // far above 1/10 of the contact duration of these beads
    System system(c);
    Snapshot empty;
    system.initialise(empty);
    const ParticleState p = insertRandomFill(system, fill(spheres(), 10, 1), {}, 0).particles;
    try
    {
        system.addParticles(p, "the particles of insertion 'release'");
        FAIL() << "an unstable time step was accepted";
    }
    catch (const Error& err)
    {
        EXPECT_EQ(err.entry(), "timeStep");
        EXPECT_EQ(err.file(), "test");
        EXPECT_NE(err.message().find("contact-stability limit"), std::string::npos) << err.message();
        EXPECT_NE(err.message().find("insertion 'release'"), std::string::npos) << err.message();
    }
    EXPECT_EQ(system.engine().particles().size(), 0u);

    // A stable one goes in
    System stable(config());
    stable.initialise(empty);
    stable.addParticles(p, "the particles of insertion 'release'");
    EXPECT_EQ(stable.engine().particles().size(), p.size());
}


namespace
{

ParticleState listed(const System& system, const InsertionTypes& types,
                     const std::vector<std::pair<Vec3, int>>& at, double radius = 0)
{
    std::vector<ListedParticle> list(at.size());
    for (std::size_t i = 0; i < at.size(); ++i)
    {
        list[i].position = at[i].first;
        list[i].type = at[i].second;
        list[i].radius = radius > 0 ? radius : system.config().types[at[i].second].radius;
    }
    return insertList(system, types, list, 0);
}

} // namespace


TEST(InsertionOverlaps, spheresByDepth)
{
    SimulationConfig c = config();
    const System system(c);
    // d = 4 mm: centres 3.96 mm apart overlap by 1 % of d (the tolerance),
    // 3.9 mm apart by 2.5 %, one point by 100 %
    const ParticleState clear = listed(system, spheres(), {{Vec3(0, 0, 0), 0}, {Vec3(0.00397, 0, 0), 0}});
    EXPECT_TRUE(insertionOverlaps(c, clear, ParticleState(), true).empty());

    const ParticleState deep = listed(system, spheres(), {{Vec3(0, 0, 0), 0}, {Vec3(0.0039, 0, 0), 0}});
    const auto o = insertionOverlaps(c, deep, ParticleState(), true);
    ASSERT_EQ(o.size(), 1u);
    EXPECT_EQ(o[0].particle, 0u);
    EXPECT_EQ(o[0].otherIndex, 1u);
    EXPECT_NEAR(o[0].measure, 0.1e-3 / 4e-3, 1e-12);
    EXPECT_FALSE(o[0].byVolume);

    const ParticleState same = listed(system, spheres(), {{Vec3(0.01, 0, 0), 0}, {Vec3(0.01, 0, 0), 0}});
    const auto s = insertionOverlaps(c, same, ParticleState(), true);
    ASSERT_EQ(s.size(), 1u);
    EXPECT_NEAR(s[0].measure, 1.0, 1e-12);

    // Against a particle already present (its id is named)
    ParticleState present = listed(system, spheres(), {{Vec3(0, 0, 0.0035), 0}});
    present.id[0] = 77;
    const auto q = insertionOverlaps(c, clear, present, true);
    ASSERT_EQ(q.size(), 1u);
    EXPECT_EQ(q[0].partner, InsertionOverlap::Partner::present);
    EXPECT_EQ(q[0].otherId, 77);
}


TEST(InsertionOverlaps, cubesByVolume)
{
    SimulationConfig c = config();
    const System system(c);
    // Two 4 mm cubes face to face exactly touching: clear; 0.4 mm closer
    // they share a 4 x 4 x 0.4 mm slab, 10 % of a cube's volume
    const ParticleState touch = listed(system, cubes(), {{Vec3(0, 0, 0), 2}, {Vec3(0.004, 0, 0), 2}});
    EXPECT_TRUE(insertionOverlaps(c, touch, ParticleState(), true).empty());
    const ParticleState deep = listed(system, cubes(), {{Vec3(0, 0, 0), 2}, {Vec3(0.0036, 0, 0), 2}});
    const auto o = insertionOverlaps(c, deep, ParticleState(), true);
    ASSERT_EQ(o.size(), 1u);
    EXPECT_TRUE(o[0].byVolume);
    EXPECT_NEAR(o[0].measure, 0.1, 1e-9);
}


TEST(InsertionOverlaps, walls)
{
    SimulationConfig c = config();
    PlaneWall floor;
    floor.name = "floor";
    floor.point = Vec3(0, 0, 0);
    floor.normal = Vec3(0, 0, 1);
    c.planes.push_back(floor);
    const System system(c);

    // A cube resting on the floor: clear; centre below the floor: refused
    const ParticleState resting = listed(system, cubes(), {{Vec3(0, 0, 0.002), 2}});
    EXPECT_TRUE(insertionOverlaps(c, resting, ParticleState(), true).empty());
    const ParticleState below = listed(system, cubes(), {{Vec3(0, 0, -0.001), 2}});
    const auto b = insertionOverlaps(c, below, ParticleState(), true);
    ASSERT_EQ(b.size(), 1u);
    EXPECT_TRUE(b[0].behindWall);
    EXPECT_EQ(b[0].wall, "floor");

    // A cube sunk 1 mm into it: a quarter of its volume
    const ParticleState sunk = listed(system, cubes(), {{Vec3(0, 0, 0.001), 2}});
    const auto v = insertionOverlaps(c, sunk, ParticleState(), true);
    ASSERT_EQ(v.size(), 1u);
    EXPECT_NEAR(v[0].measure, 0.25, 1e-9);

    // A sphere 0.2 mm into it: 5 % of its diameter
    const ParticleState bead = listed(system, spheres(), {{Vec3(0, 0, 0.0018), 0}});
    const auto s = insertionOverlaps(c, bead, ParticleState(), true);
    ASSERT_EQ(s.size(), 1u);
    EXPECT_NEAR(s[0].measure, 0.05, 1e-9);
}


TEST(InsertionOverlaps, meshWalls)
{
    // A 1 m square floor of two triangles (counter-clockwise seen from +z,
    // the particles' side) and the same floor as 2 x 40 x 40 small ones:
    // both must give the exact sunk volume and depth
    for (int n : {1, 40})
    {
        SimulationConfig c = config();
        MeshWall w;
        w.name = "tray";
        const double h = 1.0 / n;
        for (int i = 0; i <= n; ++i)
            for (int j = 0; j <= n; ++j)
                w.mesh.points.push_back(Vec3(-0.5 + i * h, -0.5 + j * h, 0));
        auto id = [n](int i, int j) { return i * (n + 1) + j; };
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j)
            {
                w.mesh.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
                w.mesh.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
            }
        c.meshes.push_back(w);
        const System system(c);
        const ParticleState clear = listed(system, cubes(), {{Vec3(0.01, 0.02, 0.002), 2}});
        EXPECT_TRUE(insertionOverlaps(c, clear, ParticleState(), true).empty()) << n;
        const ParticleState sunk = listed(system, cubes(), {{Vec3(0.01, 0.02, 0.001), 2}});
        const auto v = insertionOverlaps(c, sunk, ParticleState(), true);
        ASSERT_EQ(v.size(), 1u) << n;
        EXPECT_EQ(v[0].wall, "tray");
        EXPECT_NEAR(v[0].measure, 0.25, 1e-9) << n;
        const ParticleState bead = listed(system, spheres(), {{Vec3(0.01, 0.02, 0.0018), 0}});
        const auto s = insertionOverlaps(c, bead, ParticleState(), true);
        ASSERT_EQ(s.size(), 1u) << n;
        EXPECT_NEAR(s[0].measure, 0.05, 1e-9) << n;
    }
}

// A column of 10 cubes stays standing: lateral drift below 1 % of the edge
// over 1 s (face contacts carry the load without spurious torques).
#include "PolyhedraCase.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace polydem;

TEST(PolyhedraStacking, columnOfTenCubes)
{
    const double a = 0.01, g = 9.81;
    SimulationConfig cfg = test::polyhedronConfig(makeCube(a), 0.3, 0.5);
    cfg.timeStep = 2e-6;
    cfg.planes.push_back(test::plane(Vec3(0, 0, 0), Vec3(0, 0, 1)));
    System s(cfg);
    // Stack at the static overlaps: contact k carries (10 - k) cubes
    const double m = 2500 * a * a * a, kA = cfg.contact.volumetricStiffness * a * a;
    std::vector<Vec3> x;
    double z = 0;
    for (int k = 0; k < 10; ++k)
    {
        const double d = (10 - k) * m * g / kA;
        z += (k == 0 ? 0.5 * a : a) - d;
        x.push_back(Vec3(0, 0, z));
    }
    Snapshot st = test::polyhedraAt(s, x, {});
    s.initialise(st);
    s.advance(500000);  // 1 s
    const auto p = s.engine().particles();
    double drift = 0;
    for (std::size_t i = 0; i < p.size(); ++i)
    {
        drift = std::max(drift, std::hypot(p.position[i].x, p.position[i].y));
    }
    EXPECT_LT(drift, 0.01 * a);
    EXPECT_LT(s.engine().energies().kinetic(), 1e-9);
}

// With e = 1 and no friction, a cube in a random orientation bouncing on a
// plane for 100 impacts keeps its total energy (kinetic + gravitational +
// the exact elastic energy Kn * first moment of the overlap) within 0.5 %.
#include "PolyhedraCase.hpp"

#include <gtest/gtest.h>

using namespace polydem;

TEST(PolyhedraEnergy, cubeBouncing100Impacts)
{
    const double a = 0.01;
    SimulationConfig cfg = test::polyhedronConfig(makeCube(a), 1.0, 0.0);
    cfg.timeStep = 2e-6;
    cfg.planes.push_back(test::plane(Vec3(0, 0, 0), Vec3(0, 0, 1)));
    System s(cfg);
    const Quaternion q = normalised(Quaternion{0.8, 0.3, -0.4, 0.2});
    Snapshot st = test::polyhedraAt(s, {Vec3(0, 0, 0.02)}, {q});
    st.particles.omega[0] = Vec3(3, -2, 5);
    s.initialise(st);
    const double e0 = s.engine().energies().total();
    int impacts = 0;
    bool inContact = false;
    double worst = 0;
    for (int k = 0; k < 20000000 && impacts < 100; ++k)
    {
        s.advance(10);
        const bool c = s.engine().statistics().wallContacts > 0;
        if (c && !inContact) ++impacts;
        inContact = c;
        if (!c)
        {
            const double e = s.engine().energies().total();
            worst = std::max(worst, std::fabs(e - e0) / e0);
        }
    }
    EXPECT_EQ(impacts, 100);
    EXPECT_LT(worst, 5e-3);
    std::printf("impacts %d, worst relative energy error between impacts %.3g\n", impacts, worst);
}

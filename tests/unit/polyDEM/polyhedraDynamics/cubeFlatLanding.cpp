// A cube landing flat on a plane rebounds with the input coefficient of
// restitution within 3 % (face contact: V = A d, a linear spring Kn A).
#include "PolyhedraCase.hpp"

#include <gtest/gtest.h>

using namespace polydem;

TEST(PolyhedraRestitution, cubeLandingFlat)
{
    const double a = 0.01, v0 = 0.5;
    for (double e : {0.3, 0.6, 0.9})
    {
        SimulationConfig cfg = test::polyhedronConfig(makeCube(a), e, 0.0);
        cfg.gravity = Vec3(0, 0, 0);
        cfg.timeStep = 1e-6;
        cfg.planes.push_back(test::plane(Vec3(0, 0, 0), Vec3(0, 0, 1)));
        System s(cfg);
        Snapshot st = test::polyhedraAt(s, {Vec3(0, 0, 0.5 * a + 1e-5)}, {});
        st.particles.velocity[0] = Vec3(0, 0, -v0);
        s.initialise(st);
        bool touched = false;
        for (int k = 0; k < 100000; ++k)
        {
            s.advance(1);
            const bool c = s.engine().statistics().wallContacts > 0;
            touched = touched || c;
            if (touched && !c) break;
        }
        const auto p = s.engine().particles();
        EXPECT_NEAR(p.velocity[0].z / v0, e, 0.03 * e);
        EXPECT_LT(norm(p.omega[0]), 1e-9) << "a flat landing must not spin the cube";
    }
}

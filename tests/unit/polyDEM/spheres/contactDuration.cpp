// Hertz contact duration against the analytic elastic result
//     t_c = 2.87 (m*^2 / (R* E*^2 v))^(1/5)      (Hertz 1882; e.g. Johnson 1985)
// within 3 %, for a head-on impact of two equal spheres at several speeds.
#include "TestCase.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace polydem;

TEST(HertzContactDuration, matchesAnalytic)
{
    const double r = 0.005, E = 1e7, nu = 0.3, rho = 2500;
    for (double v0 : {0.1, 0.5, 2.0})
    {
        SimulationConfig cfg = test::sphereConfig(ContactLaw::hertzMindlin, 1.0, 0.0, r, E, nu, rho);
        cfg.timeStep = 2e-7;
        System s(cfg);
        Snapshot st;
        st.particles = s.makeSpheres(0, {Vec3(-r, 0, 0), Vec3(r, 0, 0)}, {}, 0);
        st.particles.velocity[0] = Vec3(0.5 * v0, 0, 0);
        st.particles.velocity[1] = Vec3(-0.5 * v0, 0, 0);
        s.initialise(st);
        int steps = 0;
        bool started = false;
        for (int k = 0; k < 1000000; ++k)
        {
            s.advance(1);
            const bool c = s.engine().statistics().contacts > 0;
            if (c) { started = true; ++steps; }
            if (started && !c) break;
        }
        const double m = rho * 4.0 / 3.0 * M_PI * r * r * r;
        const double mStar = 0.5 * m, rStar = 0.5 * r;
        const double eStar = E / (2 * (1 - nu * nu));
        const double tc = 2.87 * std::pow(mStar * mStar / (rStar * eStar * eStar * v0), 0.2);
        const double measured = steps * cfg.timeStep;
        EXPECT_NEAR(measured, tc, 0.03 * tc) << "impact speed " << v0;
    }
}

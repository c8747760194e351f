// A solid sphere launched sliding without spin on a plane ends in pure
// rolling at 5/7 of its initial speed (angular momentum about the contact
// point is conserved while it slides), within 1 %.
#include "TestCase.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace polydem;

TEST(RollingTransition, fiveSevenths)
{
    for (ContactLaw law : {ContactLaw::hertzMindlin, ContactLaw::linearSpringDashpot})
    {
        const double r = 0.005, v0 = 1.0, E = 1e7, nu = 0.3, rho = 2500;
        SimulationConfig cfg = test::sphereConfig(law, 0.5, 0.3, r, E, nu, rho);
        cfg.gravity = Vec3(0, 0, -9.81);
        cfg.timeStep = 2e-6;
        cfg.planes.push_back(test::plane(Vec3(0, 0, 0), Vec3(0, 0, 1)));
        System s(cfg);
        // Start at the static overlap so that the sphere does not bounce
        const double m = rho * 4.0 / 3.0 * M_PI * r * r * r;
        const double eStar = E / (1 - nu * nu);  // sphere on a rigid-as-same-material plane pair
        double d;
        if (law == ContactLaw::hertzMindlin)
        {
            const double eff = 1.0 / (2 * (1 - nu * nu) / E);
            d = std::pow(m * 9.81 / (4.0 / 3.0 * eff * std::sqrt(r)), 2.0 / 3.0);
        }
        else
        {
            d = m * 9.81 / cfg.contact.normalStiffness;
        }
        (void)eStar;
        Snapshot st;
        st.particles = s.makeSpheres(0, {Vec3(0, 0, r - d)}, {}, 0);
        st.particles.velocity[0] = Vec3(v0, 0, 0);
        s.initialise(st);
        // Sliding lasts 2 v0 / (7 mu g) ~ 0.1 s; run 0.3 s
        s.advance(150000);
        const auto p = s.engine().particles();
        EXPECT_NEAR(p.velocity[0].x / v0, 5.0 / 7.0, 0.01 * 5.0 / 7.0);
        // rolling: contact point at rest, v = -omega_y r ... omega_y = v / r
        EXPECT_NEAR(p.omega[0].y * r / p.velocity[0].x, 1.0, 0.01);
    }
}

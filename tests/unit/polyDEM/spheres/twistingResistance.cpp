// Twisting resistance: a sphere resting on a plane and spinning about the
// contact normal feels M = mu_t R* Fn = mu_t r m g, so its spin decays
// linearly, w(t) = w0 - (mu_t r m g / I) t with I = 2/5 m r^2, and stops at
// t_stop = w0 I / (mu_t r m g); it then stays at rest. Without the option the
// spin is untouched (a normal spin makes no slip at a point contact).
#include "TestCase.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace polydem;

namespace
{

struct SpinRun
{
    double wHalf;   //!< spin at half the analytic stopping time
    double wEnd;    //!< spin at 1.5 stopping times
};

SpinRun spinDown(ContactLaw law, bool twisting, double muT, double w0, double& tStop)
{
    const double r = 0.005, E = 1e7, nu = 0.3, rho = 2500, g = 9.81;
    SimulationConfig cfg = test::sphereConfig(law, 0.5, 0.5, r, E, nu, rho);
    cfg.gravity = Vec3(0, 0, -g);
    cfg.timeStep = 2e-6;
    cfg.contact.twisting = twisting;
    cfg.pairs[0].twistingFriction = muT;
    cfg.planes.push_back(test::plane(Vec3(0, 0, 0), Vec3(0, 0, 1)));
    System s(cfg);
    const double m = rho * 4.0 / 3.0 * M_PI * r * r * r;
    // Start at the static overlap, so that Fn = m g from the first step
    double d;
    if (law == ContactLaw::hertzMindlin)
    {
        const double eff = 1.0 / (2 * (1 - nu * nu) / E);
        d = std::pow(m * g / (4.0 / 3.0 * eff * std::sqrt(r)), 2.0 / 3.0);
    }
    else
    {
        d = m * g / cfg.contact.normalStiffness;
    }
    Snapshot st;
    st.particles = s.makeSpheres(0, {Vec3(0, 0, r - d)}, {}, 0);
    st.particles.omega[0] = Vec3(0, 0, w0);
    s.initialise(st);
    const double I = 0.4 * m * r * r;
    tStop = w0 * I / (muT * r * m * g);
    const int64_t half = int64_t(std::llround(0.5 * tStop / cfg.timeStep));
    s.advance(half);
    SpinRun out;
    out.wHalf = s.engine().particles().omega[0].z;
    s.advance(2 * half);
    out.wEnd = s.engine().particles().omega[0].z;
    return out;
}

} // namespace

TEST(TwistingResistance, spinDecaysAsTheAnalyticTorque)
{
    for (ContactLaw law : {ContactLaw::hertzMindlin, ContactLaw::linearSpringDashpot})
    {
        const double w0 = 20.0, muT = 0.1;
        double tStop = 0;
        const SpinRun run = spinDown(law, true, muT, w0, tStop);
        // Linear decay: half the spin is left at half the stopping time (1 %)
        EXPECT_NEAR(run.wHalf / w0, 0.5, 0.01) << "law " << int(law);
        // At rest afterwards, not spinning backwards
        EXPECT_LT(std::fabs(run.wEnd), 1e-6 * w0) << "law " << int(law);

        double tOff = 0;
        const SpinRun free = spinDown(law, false, muT, w0, tOff);
        EXPECT_NEAR(free.wEnd / w0, 1.0, 1e-9) << "law " << int(law);
    }
}

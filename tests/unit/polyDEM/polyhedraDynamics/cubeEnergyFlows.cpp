// Energy flows with polyhedra (overlapVolume law, one thread: the fused
// force pass): a cube sliding on a plane comes to rest having dissipated
// its kinetic energy (1 %, and the balance wallWork = dissipation + change of
// energy to 1e-3); two cubes hitting off-centre dissipate in their contact
// the kinetic energy they lose (0.2 %); on a belt (a plane moving along itself
// at U) a cube ends moving with it, the belt having done m U^2 of work, half
// of it dissipated (1 %).
#include "PolyhedraCase.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace polydem;

namespace
{

constexpr double a = 0.01, g = 9.81, Kn = 1e10;
const double m = 2500 * a * a * a;

SimulationConfig cubeOnPlane(double beltSpeed)
{
    SimulationConfig cfg = test::polyhedronConfig(makeCube(a), 0.3, 0.4, Kn);
    cfg.timeStep = 2e-6;
    PlaneWall p = test::plane(Vec3(0, 0, 0), Vec3(0, 0, 1));
    p.motion.kind = beltSpeed != 0 ? MotionKind::translation : MotionKind::fixed;
    p.motion.velocity = Vec3(beltSpeed, 0, 0);
    cfg.planes.push_back(p);
    return cfg;
}

double imbalance(const EnergyFlows& f, const Energies& e0, const Energies& e1, double scale)
{
    return (f.wallWork - f.dissipation() - (e1.total() - e0.total())) / scale;
}

} // namespace

TEST(PolyhedraEnergyFlows, cubeSlidesToRest)
{
    const double v0 = 0.3;
    const SimulationConfig cfg = cubeOnPlane(0);
    System s(cfg);
    // Resting at its static overlap, m g = Kn A d
    const double d = m * g / (Kn * a * a);
    Snapshot st = test::polyhedraAt(s, {Vec3(0, 0, 0.5 * a - d)}, {});
    st.particles.velocity[0] = Vec3(v0, 0, 0);
    s.initialise(st);
    s.engine().enableEnergyFlows(true);
    const Energies e0 = s.engine().energies();
    s.advance(50000);   // stops after v0 / (mu g) = 0.076 s; 0.1 s
    const EnergyFlows f = s.engine().energyFlows();
    const Energies e1 = s.engine().energies();
    const double ke0 = 0.5 * m * v0 * v0;
    std::printf("cubeSlidesToRest: KE left %.2e of KE0, dissipated/KE0 = %.6f, imbalance %.2e\n",
                e1.kinetic() / ke0, f.wallDissipation / ke0, imbalance(f, e0, e1, ke0));
    EXPECT_LT(e1.kinetic(), 1e-4 * ke0) << "must have stopped";
    EXPECT_NEAR(f.wallDissipation / ke0, 1.0, 0.01);
    EXPECT_NEAR(imbalance(f, e0, e1, ke0), 0.0, 1e-3);
}

TEST(PolyhedraEnergyFlows, cubeOnBelt)
{
    const double U = 0.3;
    const SimulationConfig cfg = cubeOnPlane(U);
    System s(cfg);
    const double d = m * g / (Kn * a * a);
    Snapshot st = test::polyhedraAt(s, {Vec3(0, 0, 0.5 * a - d)}, {});
    s.initialise(st);
    s.engine().enableEnergyFlows(true);
    const Energies e0 = s.engine().energies();
    s.advance(50000);   // reaches U after U / (mu g) = 0.076 s; 0.1 s
    const EnergyFlows f = s.engine().energyFlows();
    const Energies e1 = s.engine().energies();
    const double v = s.engine().particles().velocity[0].x;
    std::printf("cubeOnBelt: v/U = %.6f, work/(m U^2) = %.6f, dissipated/(m U^2 / 2) = %.6f, imbalance %.2e\n",
                v / U, f.wallWork / (m * U * U), f.wallDissipation / (0.5 * m * U * U),
                imbalance(f, e0, e1, f.wallWork));
    EXPECT_NEAR(v / U, 1.0, 1e-3);
    EXPECT_NEAR(f.wallWork / (m * U * U), 1.0, 0.01);
    EXPECT_NEAR(f.wallDissipation / (0.5 * m * U * U), 1.0, 0.01);
    EXPECT_NEAR(imbalance(f, e0, e1, f.wallWork), 0.0, 1e-3);
}

TEST(PolyhedraEnergyFlows, cubePairOffCentre)
{
    SimulationConfig cfg = test::polyhedronConfig(makeCube(a), 0.3, 0.4, Kn);
    cfg.gravity = Vec3();
    cfg.timeStep = 1e-6;
    System s(cfg);
    const Quaternion q = normalised(Quaternion{0.9, 0.1, 0.2, 0.3});
    Snapshot st = test::polyhedraAt(s, {Vec3(-0.8 * a, 0, 0), Vec3(0.8 * a, 0.3 * a, 0.1 * a)},
                                    {Quaternion(), q});
    st.particles.velocity[0] = Vec3(0.5, 0, 0);
    st.particles.velocity[1] = Vec3(-0.5, 0, 0);
    s.initialise(st);
    s.engine().enableEnergyFlows(true);
    const Energies e0 = s.engine().energies();
    bool touched = false;
    for (int k = 0; k < 400 && !(touched && s.engine().statistics().contacts == 0); ++k)
    {
        s.advance(100);
        touched = touched || s.engine().statistics().contacts > 0;
    }
    ASSERT_TRUE(touched);
    ASSERT_EQ(s.engine().statistics().contacts, 0u) << "still in contact";
    const EnergyFlows f = s.engine().energyFlows();
    const Energies e1 = s.engine().energies();
    const double lost = e0.kinetic() - e1.kinetic();
    std::printf("cubePairOffCentre: KE lost %.4f of KE0, dissipated/lost = %.6f\n",
                lost / e0.kinetic(), f.pairDissipation / lost);
    EXPECT_GT(lost, 0.1 * e0.kinetic());
    EXPECT_NEAR(f.pairDissipation / lost, 1.0, 2e-3);
}

// Energy flows (Engine::enableEnergyFlows): the energy the contacts dissipate
// and the work the moving walls do, against analytic results and against the
// energy balance  wallWork = dissipation + change of (kinetic + gravitational
// + elastic) energy, which holds to the time step's discretisation error
// (checked to 1e-3 of the energy exchanged; measured 2e-5 to 2e-4).
//   - a sphere launched sliding on a plane ends rolling at 5/7 of its speed:
//     friction dissipates m v0^2 / 7 (0.5 %);
//   - a sphere at rest on a belt (a plane moving along itself at U) ends
//     rolling with its bottom at U: the belt does 2 m U^2 / 7 of work, of
//     which m U^2 / 7 is dissipated (1 %);
//   - a rolling sphere stopped by rolling resistance (constant torque and
//     elastic-plastic spring-dashpot) dissipates all its kinetic energy (1 %);
//   - an off-centre pair dissipates the kinetic energy it loses (0.2 %), and the
//     running dissipation never decreases;
//   - an external force (the fluid's, in a coupled run) does work F . dx:
//     on a free sphere exactly the kinetic energy it gains (1e-12), and
//     pulling a sphere along a plane, friction dissipates the analytic share
//     of that work (1 %) and wallWork + externalWork = dissipation + change
//     of energy (1e-3);
//   - turning energy flows on changes no trajectory (bit for bit).
#include "TestCase.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace polydem;

namespace
{

constexpr double r = 0.005, E = 1e7, nu = 0.3, rho = 2500, g = 9.81;
const double m = rho * 4.0 / 3.0 * M_PI * r * r * r;

//- Static overlap of the sphere's weight on a plane of the same material
double restingOverlap(const SimulationConfig& cfg)
{
    if (cfg.contact.law == ContactLaw::hertzMindlin)
    {
        const double eff = 1.0 / (2 * (1 - nu * nu) / E);
        return std::pow(m * g / (4.0 / 3.0 * eff * std::sqrt(r)), 2.0 / 3.0);
    }
    return m * g / cfg.contact.normalStiffness;
}

//- One sphere resting on the plane z = 0 (moving along x at beltSpeed)
//  with velocity v and spin w
System& restingSphere(System& s, const SimulationConfig& cfg, const Vec3& v, const Vec3& w)
{
    Snapshot st;
    st.particles = s.makeSpheres(0, {Vec3(0, 0, r - restingOverlap(cfg))}, {}, 0);
    st.particles.velocity[0] = v;
    st.particles.omega[0] = w;
    s.initialise(st);
    s.engine().enableEnergyFlows(true);
    return s;
}

SimulationConfig onPlane(ContactLaw law, double beltSpeed = 0)
{
    SimulationConfig cfg = test::sphereConfig(law, 0.5, 0.3, r, E, nu, rho);
    cfg.gravity = Vec3(0, 0, -g);
    cfg.timeStep = 2e-6;
    PlaneWall p = test::plane(Vec3(0, 0, 0), Vec3(0, 0, 1));
    if (beltSpeed != 0)
    {
        p.motion.kind = MotionKind::translation;
        p.motion.velocity = Vec3(beltSpeed, 0, 0);
    }
    cfg.planes.push_back(p);
    return cfg;
}

//- wallWork - dissipation - (E1 - E0), relative to scale
double imbalance(const EnergyFlows& f, const Energies& e0, const Energies& e1, double scale)
{
    return (f.wallWork - f.dissipation() - (e1.total() - e0.total())) / scale;
}

const char* lawName(ContactLaw law)
{
    return law == ContactLaw::hertzMindlin ? "hertzMindlin" : "linearSpringDashpot";
}

} // namespace


TEST(EnergyFlows, slidingToRolling)
{
    for (ContactLaw law : {ContactLaw::hertzMindlin, ContactLaw::linearSpringDashpot})
    {
        const double v0 = 0.5;
        const SimulationConfig cfg = onPlane(law);
        System s(cfg);
        restingSphere(s, cfg, Vec3(v0, 0, 0), Vec3());
        const Energies e0 = s.engine().energies();
        s.advance(37500);   // 0.075 s; sliding lasts 2 v0 / (7 mu g) = 0.049 s
        const EnergyFlows f = s.engine().energyFlows();
        const Energies e1 = s.engine().energies();
        const double lost = m * v0 * v0 / 7;
        std::printf("slidingToRolling %s: dissipated/(m v0^2/7) = %.6f, imbalance %.2e\n", lawName(law),
                    f.wallDissipation / lost, imbalance(f, e0, e1, lost));
        EXPECT_EQ(f.steps, 37500) << lawName(law);
        EXPECT_NEAR(f.wallDissipation / lost, 1.0, 0.005) << lawName(law);
        EXPECT_EQ(f.pairDissipation, 0.0) << lawName(law);
        EXPECT_EQ(f.wallWork, 0.0) << lawName(law) << ": a fixed wall does no work";
        EXPECT_NEAR(imbalance(f, e0, e1, lost), 0.0, 1e-3) << lawName(law);
    }
}

TEST(EnergyFlows, sphereOnBelt)
{
    for (ContactLaw law : {ContactLaw::hertzMindlin, ContactLaw::linearSpringDashpot})
    {
        const double U = 0.5;
        const SimulationConfig cfg = onPlane(law, U);
        System s(cfg);
        restingSphere(s, cfg, Vec3(), Vec3());
        const Energies e0 = s.engine().energies();
        s.advance(37500);   // the same 0.049 s of sliding as above
        const EnergyFlows f = s.engine().energyFlows();
        const Energies e1 = s.engine().energies();
        const auto p = s.engine().particles();
        std::printf("sphereOnBelt %s: v/U = %.6f, work/(2mU^2/7) = %.6f, dissipated/(mU^2/7) = %.6f,"
                    " imbalance %.2e\n", lawName(law), p.velocity[0].x / U, f.wallWork / (2 * m * U * U / 7),
                    f.wallDissipation / (m * U * U / 7), imbalance(f, e0, e1, f.wallWork));
        // Rolling on the belt: centre at 2U/7, bottom point at U
        EXPECT_NEAR(p.velocity[0].x / U, 2.0 / 7.0, 0.01 * 2.0 / 7.0) << lawName(law);
        EXPECT_NEAR(f.wallWork / (2 * m * U * U / 7), 1.0, 0.01) << lawName(law);
        EXPECT_NEAR(f.wallDissipation / (m * U * U / 7), 1.0, 0.01) << lawName(law);
        EXPECT_NEAR(imbalance(f, e0, e1, f.wallWork), 0.0, 1e-3) << lawName(law);
    }
}

TEST(EnergyFlows, rollingResistanceStops)
{
    for (RollingModel model : {RollingModel::constantTorque, RollingModel::elasticPlastic})
    {
        const double v0 = 0.2;
        SimulationConfig cfg = onPlane(ContactLaw::hertzMindlin);
        cfg.contact.rolling = model;
        cfg.pairs[0].rollingFriction = 0.3;
        System s(cfg);
        // Rolling without slip: omega_y = v / r
        restingSphere(s, cfg, Vec3(v0, 0, 0), Vec3(0, v0 / r, 0));
        const Energies e0 = s.engine().energies();
        // Deceleration of a rolling sphere under M = mu_r r m g:
        // (7/5) m a = mu_r m g -> stops after 7 v0 / (5 mu_r g) = 0.095 s
        s.advance(62500);   // 0.125 s
        const EnergyFlows f = s.engine().energyFlows();
        const Energies e1 = s.engine().energies();
        const double ke0 = 0.7 * m * v0 * v0;
        const char* name = model == RollingModel::constantTorque ? "constantTorque" : "elasticPlastic";
        std::printf("rollingResistanceStops %s: KE left %.2e of KE0, dissipated/KE0 = %.6f, imbalance %.2e\n",
                    name, e1.kinetic() / ke0, f.wallDissipation / ke0, imbalance(f, e0, e1, ke0));
        EXPECT_LT(e1.kinetic(), 1e-3 * ke0) << name << ": must have stopped";
        EXPECT_NEAR(f.wallDissipation / ke0, 1.0, 0.01) << name;
        EXPECT_NEAR(imbalance(f, e0, e1, ke0), 0.0, 1e-3) << name;
    }
}

TEST(EnergyFlows, headOnPair)
{
    for (ContactLaw law : {ContactLaw::hertzMindlin, ContactLaw::linearSpringDashpot})
    {
        const double v0 = 0.5;
        SimulationConfig cfg = test::sphereConfig(law, 0.5, 0.3, r, E, nu, rho);
        cfg.timeStep = 1e-6;
        System s(cfg);
        Snapshot st;
        // Slightly off-centre, so that friction acts too
        st.particles = s.makeSpheres(0, {Vec3(-r - 1e-5, 0, 0), Vec3(r + 1e-5, 0.2 * r, 0)}, {}, 0);
        st.particles.velocity[0] = Vec3(v0, 0, 0);
        st.particles.velocity[1] = Vec3(-v0, 0, 0);
        s.initialise(st);
        s.engine().enableEnergyFlows(true);
        const Energies e0 = s.engine().energies();
        double last = 0;
        bool decreased = false;
        for (int k = 0; k < 4000; ++k)
        {
            s.advance(1);
            const double d = s.engine().energyFlows().dissipation();
            decreased = decreased || d < last - 1e-15 * e0.kinetic();
            last = d;
        }
        const EnergyFlows f = s.engine().energyFlows();
        const Energies e1 = s.engine().energies();
        ASSERT_EQ(s.engine().statistics().contacts, 0u) << lawName(law) << ": still in contact";
        const double lost = e0.kinetic() - e1.kinetic();
        std::printf("headOnPair %s: KE lost %.4f of KE0, dissipated/lost = %.6f\n", lawName(law),
                    lost / e0.kinetic(), f.pairDissipation / lost);
        EXPECT_GT(lost, 0.1 * e0.kinetic()) << lawName(law);
        EXPECT_NEAR(f.pairDissipation / lost, 1.0, 2e-3) << lawName(law);
        EXPECT_EQ(f.wallDissipation, 0.0) << lawName(law);
        EXPECT_FALSE(decreased) << lawName(law) << ": the dissipation went down in a step";
    }
}

TEST(EnergyFlows, externalForceWork)
{
    {
        // A free sphere pushed by a constant force and torque: velocity
        // Verlet gives it exactly the work F . dx + T . w dt as kinetic energy
        SimulationConfig cfg = test::sphereConfig(ContactLaw::hertzMindlin, 0.5, 0.3, r, E, nu, rho);
        cfg.timeStep = 1e-5;
        System s(cfg);
        Snapshot st;
        st.particles = s.makeSpheres(0, {Vec3(0, 0, 0)}, {}, 0);
        st.particles.velocity[0] = Vec3(0.1, -0.2, 0.05);
        s.initialise(st);
        s.engine().enableEnergyFlows(true);
        s.engine().setExternalForces({Vec3(2 * m * g, 0.5 * m * g, -m * g)}, {Vec3()});
        const Energies e0 = s.engine().energies();
        s.advance(1000);
        const EnergyFlows f = s.engine().energyFlows();
        const double gained = s.engine().energies().kinetic() - e0.kinetic();
        std::printf("externalForceWork free: work/gained - 1 = %.3e\n", f.externalWork / gained - 1);
        EXPECT_NEAR(f.externalWork / gained, 1.0, 1e-12);
    }
    {
        // Pulled along a plane with friction: slides, then its work is
        // dissipated and stored as kinetic energy
        const SimulationConfig cfg = onPlane(ContactLaw::linearSpringDashpot);
        System s(cfg);
        restingSphere(s, cfg, Vec3(), Vec3());
        // Above 3.5 mu m g the contact slides (below it the sphere rolls)
        s.engine().setExternalForces({Vec3(2 * m * g, 0, 0)}, {Vec3()});
        const Energies e0 = s.engine().energies();
        s.advance(25000);   // 0.05 s
        const EnergyFlows f = s.engine().energyFlows();
        const Energies e1 = s.engine().energies();
        const double bal = (f.wallWork + f.externalWork - f.dissipation() - (e1.total() - e0.total()))
                           / f.externalWork;
        std::printf("externalForceWork pulled: dissipated/work = %.4f, imbalance %.2e\n",
                    f.dissipation() / f.externalWork, bal);
        // Sliding: the centre accelerates at (F - mu m g)/m, the contact
        // point at (F - 3.5 mu m g)/m (friction spins it up), so friction
        // dissipates mu (F/mg - 3.5 mu) / (F/mg (F/mg - mu)) of F's work
        const double mu = 0.3, Fg = 2.0;
        const double share = mu * (Fg - 3.5 * mu) / (Fg * (Fg - mu));
        EXPECT_NEAR(f.wallDissipation / f.externalWork / share, 1.0, 0.01);
        EXPECT_NEAR(bal, 0.0, 1e-3);
    }
}

TEST(EnergyFlows, trajectoriesUnchanged)
{
    // A sphere sliding on a belt beside a second one it hits: the same
    // positions, velocities and forces to the bit with energy flows on and off
    auto run = [](bool on) {
        SimulationConfig cfg = onPlane(ContactLaw::hertzMindlin, 0.3);
        cfg.contact.rolling = RollingModel::elasticPlastic;
        cfg.pairs[0].rollingFriction = 0.05;
        System s(cfg);
        Snapshot st;
        const double z = r - restingOverlap(cfg);
        st.particles = s.makeSpheres(0, {Vec3(0, 0, z), Vec3(2.5 * r, 0.3 * r, z)}, {}, 0);
        st.particles.velocity[0] = Vec3(0.5, 0, 0);
        s.initialise(st);
        s.engine().enableEnergyFlows(on);
        s.advance(20000);
        return s.engine().particles();
    };
    const ParticleState a = run(false), b = run(true);
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i)
    {
        EXPECT_EQ(a.position[i].x, b.position[i].x);
        EXPECT_EQ(a.position[i].y, b.position[i].y);
        EXPECT_EQ(a.position[i].z, b.position[i].z);
        EXPECT_EQ(a.velocity[i].x, b.velocity[i].x);
        EXPECT_EQ(a.omega[i].y, b.omega[i].y);
        EXPECT_EQ(a.force[i].x, b.force[i].x);
    }
}

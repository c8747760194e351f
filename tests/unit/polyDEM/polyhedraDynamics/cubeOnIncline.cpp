// A cube resting on a plane tilted by theta stays for tan(theta) < mu - 0.01
// and slides for tan(theta) > mu + 0.01 (Coulomb friction).
// The plane stays horizontal and gravity is tilted instead: the same statics.
#include "PolyhedraCase.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace polydem;

namespace
{

double slideDistance(double tanTheta, double mu)
{
    const double a = 0.01, g = 9.81;
    SimulationConfig cfg = test::polyhedronConfig(makeCube(a), 0.3, mu);
    const double th = std::atan(tanTheta);
    cfg.gravity = Vec3(g * std::sin(th), 0, -g * std::cos(th));
    cfg.timeStep = 2e-6;
    cfg.planes.push_back(test::plane(Vec3(0, 0, 0), Vec3(0, 0, 1)));
    System s(cfg);
    // Resting at its static overlap: m g cos = Kn A d
    const double m = 2500 * a * a * a;
    const double d = m * g * std::cos(th) / (cfg.contact.volumetricStiffness * a * a);
    Snapshot st = test::polyhedraAt(s, {Vec3(0, 0, 0.5 * a - d)}, {});
    s.initialise(st);
    s.advance(250000);  // 0.5 s
    return s.engine().particles().position[0].x;
}

} // namespace

TEST(PolyhedraFriction, cubeOnIncline)
{
    const double mu = 0.5;
    const double stay = slideDistance(mu - 0.01, mu);
    const double slide = slideDistance(mu + 0.01, mu);
    // sliding at tan - mu = 0.01: x = 1/2 g (sin - mu cos) t^2 ~ 5.5 mm in 0.5 s
    EXPECT_LT(std::fabs(stay), 1e-4) << "must stick below the friction angle";
    EXPECT_GT(slide, 3e-3) << "must slide above the friction angle";
}

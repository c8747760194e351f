// A block of height h and width b with high friction on a tilting plane tips
// over at tan(theta) = b/h: it stands 1 degree below that angle and topples
// 1 degree above it. The plane is tilted slowly (quasi-statically), as in
// the experiment: the down-slope part of gravity is ramped up as an external
// force at the centre of mass while the block stands on a horizontal plane.
#include "PolyhedraCase.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace polydem;

namespace
{

//- Tilt of the block's vertical axis after 0.6 s on a plane tilted by theta
double finalTilt(double theta)
{
    const double b = 0.01, h = 0.03, g = 9.81;
    SimulationConfig cfg = test::polyhedronConfig(makeBox(b, b, h), 0.3, 2.0);
    cfg.gravity = Vec3(0, 0, -g * std::cos(theta));
    cfg.timeStep = 2e-6;
    cfg.planes.push_back(test::plane(Vec3(0, 0, 0), Vec3(0, 0, 1)));
    System s(cfg);
    // The generator aligns the principal axes: find the body axis of the long side
    const ConvexShape& shape = cfg.shapes[0];
    const Vec3 ext = [&] {
        Vec3 e;
        for (const Vec3& v : shape.vertices)
            for (int k = 0; k < 3; ++k) e[k] = std::max(e[k], std::fabs(v[k]));
        return e;
    }();
    int longAxis = 0;
    for (int k = 1; k < 3; ++k) if (ext[k] > ext[longAxis]) longAxis = k;
    // Rotate the long body axis onto z
    Quaternion q;
    if (longAxis == 0) q = fromAxisAngle(Vec3(0, 1, 0), -M_PI / 2);
    if (longAxis == 1) q = fromAxisAngle(Vec3(1, 0, 0), M_PI / 2);
    const double m = 2500 * shape.volume;
    const double d = m * g * std::cos(theta) / (cfg.contact.volumetricStiffness * b * b);
    Snapshot st = test::polyhedraAt(s, {Vec3(0, 0, 0.5 * h - d)}, {q});
    s.initialise(st);
    const int ramp = 50;
    for (int k = 1; k <= ramp; ++k)
    {
        s.engine().setExternalForces({Vec3(m * g * std::sin(theta) * k / ramp, 0, 0)}, {});
        s.advance(4000);  // ramp over 0.4 s
    }
    s.advance(150000);
    const auto p = s.engine().particles();
    Vec3 axis;
    axis[longAxis] = 1;
    const Vec3 up = rotate(p.orientation[0], axis);
    return std::acos(std::fabs(up.z));
}

} // namespace

TEST(PolyhedraTipping, tipsAtWidthOverHeight)
{
    const double thetaTip = std::atan(0.01 / 0.03);
    const double oneDegree = M_PI / 180;
    EXPECT_LT(finalTilt(thetaTip - oneDegree), 0.01) << "stands below the tipping angle";
    EXPECT_GT(finalTilt(thetaTip + oneDegree), 0.3) << "topples above the tipping angle";
}

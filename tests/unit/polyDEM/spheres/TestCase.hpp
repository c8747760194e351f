// Helpers to set up small sphere systems in the unit tests.
#pragma once

#include "polyDEM/System.hpp"

#include <memory>

namespace polydem::test
{

//- One material, one sphere type, no walls, no gravity
inline SimulationConfig sphereConfig
(
    ContactLaw law, double e, double friction, double radius = 0.005,
    double E = 1e7, double nu = 0.3, double density = 2500
)
{
    SimulationConfig c;
    c.materials.push_back({"glass", E, nu, density});
    PairProperties pp;
    pp.restitution = e;
    pp.friction = friction;
    c.pairs = {pp};
    c.contact.law = law;
    if (law == ContactLaw::linearSpringDashpot)
    {
        c.contact.normalStiffness = 1e4;
    }
    ParticleType t;
    t.name = "sphere";
    t.radius = radius;
    c.types.push_back(t);
    c.gravity = Vec3(0, 0, 0);
    c.device = "cpu";
    c.source = "test";
    return c;
}

inline PlaneWall plane(const Vec3& point, const Vec3& normal, const std::string& name = "wall")
{
    PlaneWall w;
    w.name = name;
    w.point = point;
    w.normal = normal;
    return w;
}

} // namespace polydem::test

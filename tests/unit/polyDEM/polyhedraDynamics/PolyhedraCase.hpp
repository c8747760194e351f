// Helpers to set up small polyhedral systems in the unit tests.
#pragma once

#include "polyDEM/System.hpp"
#include "ShapeGenerators.hpp"

#include <cmath>

namespace polydem::test
{

//- One material, one polyhedral type (the given shape), overlapVolume law
inline SimulationConfig polyhedronConfig
(
    const ConvexShape& shape, double e, double friction, double Kn = 1e10, double density = 2500
)
{
    SimulationConfig c;
    c.materials.push_back({"rock", 1e9, 0.3, density});
    PairProperties pp;
    pp.restitution = e;
    pp.friction = friction;
    c.pairs = {pp};
    c.contact.law = ContactLaw::overlapVolume;
    c.contact.volumetricStiffness = Kn;
    c.shapes = {shape};
    ParticleType t;
    t.name = shape.name.empty() ? "shape" : shape.name;
    t.shape = ShapeKind::polyhedron;
    t.shapeIndex = 0;
    c.types.push_back(t);
    c.gravity = Vec3(0, 0, -9.81);
    c.device = "cpu";
    c.source = "test";
    return c;
}

inline PlaneWall plane(const Vec3& point, const Vec3& normal)
{
    PlaneWall w;
    w.name = "wall";
    w.point = point;
    w.normal = normal / norm(normal);
    return w;
}

//- n polyhedra of type 0 at the given poses, at rest
inline Snapshot polyhedraAt(const System& s, const std::vector<Vec3>& x, const std::vector<Quaternion>& q)
{
    Snapshot st;
    st.particles.resize(x.size());
    for (std::size_t i = 0; i < x.size(); ++i)
    {
        st.particles.id[i] = std::int64_t(i);
        st.particles.type[i] = 0;
        st.particles.position[i] = x[i];
        st.particles.orientation[i] = q.empty() ? Quaternion() : q[i];
    }
    s.completeMassProperties(st.particles);
    return st;
}

} // namespace polydem::test

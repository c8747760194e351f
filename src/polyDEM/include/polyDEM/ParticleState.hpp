// polyDEM: host copy of the particle state, structure of arrays.
// The engines keep the same fields on the device; this is what goes in and
// out of them (initial state, writing, restart, coupling).
#pragma once

#include "polyDEM/Quaternion.hpp"
#include "polyDEM/Vec3.hpp"

#include <cstdint>
#include <vector>

namespace polydem
{

struct ParticleState
{
    std::vector<std::int64_t> id;     //!< unique, stable over the run
    std::vector<int> type;            //!< index into SimulationConfig::types
    std::vector<double> radius;       //!< sphere radius / bounding-sphere radius [m]
    std::vector<double> mass;         //!< [kg]
    std::vector<Vec3> inertia;        //!< principal moments of inertia (body frame) [kg m2]
    std::vector<Vec3> position;       //!< centre of mass [m]
    std::vector<Quaternion> orientation; //!< body -> world
    std::vector<Vec3> velocity;       //!< [m/s]
    std::vector<Vec3> omega;          //!< angular velocity, world frame [rad/s]
    std::vector<Vec3> force;          //!< total force of the last step (contacts + body + external) [N]
    std::vector<Vec3> torque;         //!< total torque of the last step, world frame [N m]

    std::size_t size() const { return id.size(); }

    void resize(std::size_t n)
    {
        id.resize(n); type.resize(n); radius.resize(n); mass.resize(n); inertia.resize(n);
        position.resize(n); orientation.resize(n); velocity.resize(n); omega.resize(n);
        force.resize(n); torque.resize(n);
    }
};

} // namespace polydem

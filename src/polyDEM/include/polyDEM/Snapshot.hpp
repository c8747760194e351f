// polyDEM: complete engine state at one instant, enough for a bit-exact restart.
#pragma once

#include "polyDEM/ParticleState.hpp"

#include <cstdint>
#include <vector>

namespace polydem
{

//- Tangential (and rolling) spring of a particle-particle contact, idA < idB
struct PairHistory
{
    std::int64_t idA = 0, idB = 0;
    Vec3 tangential, rolling;
    //- Two polyhedra in contact: their last contact normal (from idA to idB).
    //  The next evaluation clips in a slab along it, so the overlap depends
    //  on it at round-off and a restart needs it to continue bit for bit.
    //  Zero for spheres (and in state files of versions 1-2).
    Vec3 normal;
};

//- Spring of a particle-wall contact. wall: plane index, or planes.size() + mesh index
struct WallHistory
{
    std::int64_t id = 0;
    int wall = 0;
    int triangle = -1;   //!< -1 for a plane
    Vec3 normal;         //!< last contact normal (lets a slide onto a neighbour triangle keep its spring)
    Vec3 tangential, rolling;
};

struct Snapshot
{
    double time = 0;
    std::int64_t step = 0;
    ParticleState particles;
    //- Positions at which the neighbour lists were last built: restarting from them
    //  rebuilds exactly the same lists, so a restart changes no bit of the result.
    std::vector<Vec3> referencePosition;
    std::vector<PairHistory> pairs;
    std::vector<WallHistory> walls;
    //- The particles' force and torque are those of this state (written by an
    //  engine), so a restart must not evaluate the contacts again: that would
    //  advance the springs a second time.
    bool forcesValid = false;
    //- External (fluid) force and torque per particle, part of force/torque
    //  above: kept so that a restarted run replaces them exactly. Empty: none.
    std::vector<Vec3> externalForce;
    std::vector<Vec3> externalTorque;
};

} // namespace polydem

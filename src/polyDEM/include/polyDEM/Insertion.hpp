// polyDEM: the particles of an insertion, ready for System::addParticles or
// an initial Snapshot.
//
// Random fill: spheres placed by randomFill (random sequential addition) in
// a region, clear of the particles present (their bounding spheres). For a
// polyhedral type every seed becomes the shape whose bounding sphere it is
// (a random one among shapes of equal bounding radius) with a uniformly
// random orientation (Shoemake 1992, "Uniform random rotations"), both drawn
// from the insertion's seed, or one given orientation for all.
// List: particles at given positions, orientations, velocities and angular
// velocities, without overlap check.
// Mass and inertia come from the type's material density and the sphere
// radius or the convex shape (System::makeSpheres). Deterministic for a seed.
#pragma once

#include "polyDEM/ParticleState.hpp"
#include "polyDEM/Quaternion.hpp"
#include "polyDEM/RandomFill.hpp"
#include "polyDEM/Vec3.hpp"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace polydem
{

class System;

//- The engine particle types one insertion draws from: a sphere type, or
//  the shapes of a polyhedral type, engine types [firstType, firstType + nTypes)
struct InsertionTypes
{
    int firstType = 0;
    int nTypes = 1;
    bool polyhedron = false;
};

//- A random fill of a region
struct RandomFillInsertion
{
    InsertionTypes types;
    FillRegion region;
    SizeDistribution sizes;
    std::size_t number = 0;
    std::uint64_t seed = 1;
    //- Minimum surface gap between inserted spheres [m]
    double gap = 0;
    Vec3 velocity;
    //- Polyhedra: all with orientation (instead of random ones)
    bool fixedOrientation = false;
    Quaternion orientation;
    //- Polyhedra: orientation, then a uniformly random turn about yawAxis
    //  (floating ice: flat, any heading); needs fixedOrientation
    bool randomYaw = false;
    Vec3 yawAxis{0, 0, 1};
    //- Tries per particle, and whether a fill that runs out of room keeps
    //  the particles placed so far (true) or throws (false)
    std::size_t maxAttempts = 20000;
    bool partial = false;
};

//- One particle of a list insertion
struct ListedParticle
{
    Vec3 position;
    //- Body to world rotation
    Quaternion orientation;
    Vec3 velocity;
    //- Angular velocity (world frame) [rad/s]
    Vec3 omega;
    //- Engine particle type (one shape of the insertion's types)
    int type = 0;
    //- Sphere radius; polyhedra: the shape's bounding radius
    double radius = 0;
};

//- A floating layer (an inflow with an approach region): polyhedra, or
//  spheres of one diameter per type, of the given engine types (all of one
//  kind; each drawn with equal probability), centres uniform
//  in the plan rectangle [min, max] at the height z = height, oriented as
//  orientation (and a uniform heading about yawAxis with randomYaw), placed
//  one by one clear of each other, of the particles present and of the
//  fixed plane walls with zero overlap volume (exact, PolyhedronOverlap),
//  and of the mesh walls to the insertion tolerance (InsertionChecks).
//  Deterministic for a seed.
struct LayerInsertion
{
    std::vector<int> types;
    Vec3 min, max;          //!< centres: x, y in [min, max]; min.z, max.z unused
    double height = 0;
    std::size_t number = 0;
    std::uint64_t seed = 1;
    Vec3 velocity;
    Quaternion orientation;
    //- Optional: one orientation per entry of types (instead of orientation)
    std::vector<Quaternion> typeOrientations;
    bool randomYaw = false;
    Vec3 yawAxis{0, 0, 1};
    //- Random tries per block; a block that finds no place ends the fill
    std::size_t maxAttempts = 200;
};

struct InsertedParticles
{
    ParticleState particles;
    //- Solid volume of the particles [m3]
    double volume = 0;
};

//- The particles of a random fill, ids from firstId, clear of obstacles.
//  Throws polydem::Error (from randomFill) when the region is too full.
InsertedParticles insertRandomFill
(
    const System& system,
    const RandomFillInsertion& insertion,
    const ParticleState& obstacles,
    std::int64_t firstId
);

//- The particles of a floating layer (LayerInsertion), ids from firstId:
//  as many as fit, up to insertion.number
InsertedParticles insertLayer
(
    const System& system,
    const LayerInsertion& insertion,
    const ParticleState& present,
    std::int64_t firstId
);

//- The particles of a list, ids from firstId
ParticleState insertList
(
    const System& system,
    const InsertionTypes& types,
    const std::vector<ListedParticle>& particles,
    std::int64_t firstId
);

//- One past the largest id of p (0 when empty)
std::int64_t nextParticleId(const ParticleState& p);

//- Append the particles of b to a
void appendParticles(ParticleState& a, const ParticleState& b);

} // namespace polydem

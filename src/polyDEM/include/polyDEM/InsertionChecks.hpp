// polyDEM: overlaps of listed particles at insertion, with each other, with
// the particles present and with the walls, measured with the contact
// geometry the engine uses (PolyhedronOverlap.hpp): spheres by depth,
// anything with a polyhedron by the exact overlap volume.
//
// A list insertion places particles where the user says; two spheres at one
// point never interact (no normal), and a deep overlap is released as
// stored elastic energy at metres per second. So an overlap beyond a small
// tolerance is refused, naming both partners, before the first step:
//   - depth beyond depthTolerance (1 %) of the smaller diameter for a sphere
//     with a sphere or a wall;
//   - a volume beyond volumeTolerance (1 %) of the smaller particle's
//     volume when a polyhedron is involved (face-to-face stacks that touch
//     exactly give zero);
//   - a centre on or behind a plane wall, whatever the overlap.
// Walls are those of the config; moving walls only when atStart (their
// geometry is that of t = 0). O(n) with a uniform grid of the bounding radii.
#pragma once

#include "polyDEM/Config.hpp"
#include "polyDEM/ParticleState.hpp"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace polydem
{

struct InsertionOverlap
{
    std::size_t particle = 0;     //!< index in the inserted particles
    //- The partner: another inserted particle (index), a present one (id),
    //  or a wall (name)
    enum class Partner { inserted, present, wall } partner = Partner::inserted;
    std::size_t otherIndex = 0;
    std::int64_t otherId = -1;
    std::string wall;
    //- depth / smaller diameter (spheres) or volume / smaller volume
    double measure = 0;
    bool byVolume = false;
    //- A centre on or behind a plane wall
    bool behindWall = false;
};

constexpr double kInsertionDepthTolerance = 0.01;
constexpr double kInsertionVolumeTolerance = 1e-2;

//- Every overlap beyond the tolerances (see top), in order of the inserted
//  particles; empty when the insertion is clear
std::vector<InsertionOverlap> insertionOverlaps
(
    const SimulationConfig& config,
    const ParticleState& inserted,
    const ParticleState& present,
    bool atStart
);

} // namespace polydem

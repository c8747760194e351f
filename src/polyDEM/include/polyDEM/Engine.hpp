// polyDEM: the interface a back end (cpu, cuda) implements.
// A back end lives in its own shared library (libpolyDEM_<name>.so) exporting
// `extern "C" polydem::Engine* polydemCreateEngine()`; System loads it by name.
#pragma once

#include "polyDEM/Config.hpp"
#include "polyDEM/Snapshot.hpp"

#include <string>
#include <vector>

namespace polydem
{

//- Energies of the system, for monitoring and conservation checks [J]
struct Energies
{
    double translational = 0;
    double rotational = 0;
    double gravitational = 0;   //!< -m g.x, relative to the origin
    double elastic = 0;         //!< stored in normal springs (contacts with particles and walls)

    double kinetic() const { return translational + rotational; }
    double total() const { return translational + rotational + gravitational + elastic; }
};

struct Statistics
{
    std::size_t particles = 0;
    std::size_t contacts = 0;            //!< particle-particle pairs in contact
    std::size_t wallContacts = 0;
    std::size_t particlesInContact = 0;
    std::size_t neighbourListBuilds = 0;
    double maxOverlapRatio = 0;          //!< largest overlap / smaller radius (0 under overlapVolume)
};

//- The load of the particles on one wall: the resultant of the contact
//  forces the particles exert on it (minus what the wall exerts on them) and
//  their moment about the wall's load point (the rolling and twisting
//  resistance moments included) [N, N m]
struct WallLoad
{
    Vec3 force;
    Vec3 torque;
    Vec3 point;    //!< where the torque is taken: the load point at that time (world)
    //- The part of force along the contact normals (each contact's force
    //  projected on its own normal, summed); force - normalForce is the
    //  frictional (tangential) part
    Vec3 normalForce;
    //- Particle-wall contacts (particle with a plane, or with one triangle
    //  of a mesh); in a WallLoadSum the sum over its steps
    double contacts = 0;

    Vec3 frictionForce() const { return force - normalForce; }
};

//- A particle the engine removed: it left the domain (region -1) or entered
//  outlet region k of SimulationConfig::outlets
struct RemovedParticle
{
    std::int64_t id = 0;
    int type = 0;
    double mass = 0;
    Vec3 position;      //!< where it was at the removal (a neighbour-list rebuild)
    Vec3 velocity;
    int region = -1;
    double time = 0;
};

//- Wall loads summed over the steps taken since the last reset: divide by
//  steps for the mean over that time (each step weighs the same, dt fixed)
struct WallLoadSum
{
    std::vector<WallLoad> sum;   //!< per wall (planes, then meshes); point: the last step's
    std::int64_t steps = 0;
};

//- Where the particles' mechanical energy went, summed over the steps since
//  the enabling or the last reset [J]: dissipated by the contacts (the
//  normal and tangential dashpots, Coulomb sliding, rolling and twisting
//  resistance), put in by the moving walls (the work of each wall contact's
//  force and moment at the wall's velocity there), and by the external
//  forces and torques (the fluid's: F . v(n+1/2) dt, exact for velocity
//  Verlet). Over a stretch of steps, wallWork + externalWork + work of
//  gravity = dissipation + change of kinetic and elastic energy, to the
//  step's discretisation error (the balance the tests check).
struct EnergyFlows
{
    double pairDissipation = 0;   //!< particle-particle contacts
    double wallDissipation = 0;   //!< particle-wall contacts
    double wallWork = 0;          //!< done by the walls on the particles
    double externalWork = 0;      //!< done by the external forces and torques
    std::int64_t steps = 0;

    double dissipation() const { return pairDissipation + wallDissipation; }
};

class Engine
{
public:
    virtual ~Engine() = default;

    virtual std::string name() const = 0;

    //- Set up from a checked config and a full state (initial, or read for a restart)
    virtual void initialise(const SimulationConfig& config, const Snapshot& state) = 0;

    //- Advance n time steps
    virtual void advance(std::int64_t nSteps) = 0;

    //- Copy the full state back to the host
    virtual Snapshot snapshot() const = 0;

    //- Copy only the particle state back to the host
    virtual ParticleState particles() const = 0;

    //- Add particles (ids must be new); contact history starts empty for them;
    //  the external forces of the particles present stay, the new ones get none
    virtual void addParticles(const ParticleState& added) = 0;

    //- Constant external force and torque per particle (fluid coupling), in the
    //  current particle order; empty vectors clear them
    virtual void setExternalForces(const std::vector<Vec3>& force, const std::vector<Vec3>& torque) = 0;

    //! includeElastic: also the energy stored in the contacts, a host-side
    //! diagnostic that costs as much as a contact pass (leave it out in
    //! per-step monitoring)
    virtual Energies energies(bool includeElastic = true) const = 0;
    virtual Statistics statistics() const = 0;

    //- Wall loads (planes, then meshes, in config order): off until enabled,
    //  as they cost a pass over particles x walls per step. Each particle
    //  keeps its share per wall; the shares are summed in blocks of a fixed
    //  size in particle order, then the blocks in order: the result is the
    //  same whatever the thread count, and a restart (same particle order)
    //  continues it to the bit. The particle dynamics do not change.
    virtual void enableWallLoads(bool on) = 0;
    virtual bool wallLoadsEnabled() const = 0;
    //- The loads of the last force evaluation (zero before one with loads on)
    virtual std::vector<WallLoad> wallLoads() const = 0;
    //- The loads summed over the steps since the last reset (or the enabling)
    virtual WallLoadSum wallLoadSum() const = 0;
    virtual void resetWallLoadSum() = 0;

    //- Energy flows (EnergyFlows): off until enabled, as they cost a few
    //  operations per contact and a sum over the particles per step. Summed
    //  in fixed blocks in particle order, as the wall loads. The particle
    //  dynamics do not change.
    virtual void enableEnergyFlows(bool on) = 0;
    virtual bool energyFlowsEnabled() const = 0;
    virtual EnergyFlows energyFlows() const = 0;
    virtual void resetEnergyFlows() = 0;

    //- The particles removed (domain, outlets) since the last call, in the
    //  order of the removal passes and, within one, of the particle order
    virtual std::vector<RemovedParticle> takeRemoved() = 0;

    virtual double time() const = 0;
    virtual std::int64_t step() const = 0;
};

} // namespace polydem

extern "C"
{
    typedef polydem::Engine* (*PolydemCreateEngineFn)();
}

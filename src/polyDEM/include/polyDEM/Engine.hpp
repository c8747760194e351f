// polyDEM: the interface a back end (cpu, cuda) implements.
// A back end lives in its own shared library (libpolyDEM_<name>.so) exporting
// `extern "C" polydem::Engine* polydemCreateEngine()`; System loads it by name.
#pragma once

#include "polyDEM/Config.hpp"
#include "polyDEM/Snapshot.hpp"

#include <string>

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

    //- Add particles (ids must be new); contact history starts empty for them
    virtual void addParticles(const ParticleState& added) = 0;

    //- Constant external force and torque per particle (fluid coupling), in the
    //  current particle order; empty vectors clear them
    virtual void setExternalForces(const std::vector<Vec3>& force, const std::vector<Vec3>& torque) = 0;

    //! includeElastic: also the energy stored in the contacts, a host-side
    //! diagnostic that costs as much as a contact pass (leave it out in
    //! per-step monitoring)
    virtual Energies energies(bool includeElastic = true) const = 0;
    virtual Statistics statistics() const = 0;

    virtual double time() const = 0;
    virtual std::int64_t step() const = 0;
};

} // namespace polydem

extern "C"
{
    typedef polydem::Engine* (*PolydemCreateEngineFn)();
}

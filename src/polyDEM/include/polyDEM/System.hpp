// polyDEM: the front object a program uses. It checks a SimulationConfig,
// completes particle properties (mass, inertia), checks the time step against
// the contact-stability limit, loads the back end named in the config
// (libpolyDEM_<device>.so) and drives it.
#pragma once

#include "polyDEM/Engine.hpp"

#include <memory>
#include <string>
#include <vector>

namespace polydem
{

class System
{
public:
    //- Check the config (throws polydem::Error naming the entry) and load the back end
    explicit System(SimulationConfig config);
    ~System();

    System(const System&) = delete;
    System& operator=(const System&) = delete;

    //- Start from a state (initial or restart). Particles with zero mass get
    //  mass and inertia from their type's material density and their radius.
    void initialise(Snapshot state);

    //- Add particles to the running engine (an insertion), after checking the
    //  time step against their contact-stability limit; what names them in
    //  the error (e.g. "the particles of insertion 'release'")
    void addParticles(const ParticleState& added, const std::string& what = "these particles");

    void advance(std::int64_t nSteps) { engine_->advance(nSteps); }

    const SimulationConfig& config() const { return config_; }
    Engine& engine() { return *engine_; }
    const Engine& engine() const { return *engine_; }

    //- Largest stable time step for the particles present: 20 % of the Rayleigh
    //  time (Hertz) or 1/10 of the undamped contact duration (linear)
    double criticalTimeStep(const ParticleState& particles) const;

    //- Fill mass and principal inertia of particles that have none, from their
    //  type's density and shape (solid spheres: the radius; polyhedra: the
    //  convex shape, which also sets the bounding radius)
    void completeMassProperties(ParticleState& particles) const;

    //- Make a particle state of spheres of one type
    ParticleState makeSpheres
    (
        int type,
        const std::vector<Vec3>& positions,
        const std::vector<double>& radii,
        std::int64_t firstId
    ) const;

    //- The material pair tables the back ends use (law coefficients)
    static void checkConfig(const SimulationConfig& config);

    //- The time step alone (positive and finite; part of checkConfig), for
    //  readers that use it before the System is made
    static void checkTimeStep(const SimulationConfig& config);

    //- Load a back end by name from the library path
    static std::unique_ptr<Engine> loadBackend(const std::string& device, const std::string& source);

private:
    //- Throw polydem::Error (entry timeStep) when the time step is above the
    //  contact-stability limit of particles
    void checkStability(const ParticleState& particles, const std::string& what) const;

    SimulationConfig config_;
    void* library_ = nullptr;
    std::unique_ptr<Engine> engine_;
};

} // namespace polydem

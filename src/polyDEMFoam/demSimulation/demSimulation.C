/*---------------------------------------------------------------------------*\
  Hedra: CFD-DEM for OpenFOAM
-------------------------------------------------------------------------------
Description
    demFoam's simulation driver: start or restart, DEM sub-steps per deltaT,
    wall removal, insertion, writing and monitoring (see demSimulation.H).

\*---------------------------------------------------------------------------*/

#include "demSimulation.H"
#include <sstream>
#include <cmath>
#include "OSspecific.H"
#include "IOmanip.H"
#include "mathematicalConstants.H"
#include "polyMesh.H"

#include "polyDEM/Insertion.hpp"
#include "polyDEM/InsertionChecks.hpp"
#include "polyDEM/MeshQueries.hpp"
#include "polyDEM/StateIO.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <unordered_map>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace Foam
{

//- Wall-clock duration as h:mm:ss
static std::string hms(double s)
{
    if (!(s >= 0) || s > 1e7)
    {
        return "-";
    }
    const long t = long(std::lround(s));
    char buf[32];
    std::snprintf(buf, sizeof(buf), "%ld:%02ld:%02ld", t/3600, (t/60)%60, t%60);
    return buf;
}

//- A checksum as the state file writes it
static std::string hex16(std::uint64_t x)
{
    char buf[24];
    std::snprintf(buf, sizeof(buf), "%016llx", static_cast<unsigned long long>(x));
    return buf;
}

} // End namespace Foam


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::label Foam::demSimulation::computeStepsPerDeltaT() const
{
    const scalar deltaT = runTime_.deltaTValue();
    const scalar dt = input_.config().timeStep;
    const dictionary& dict = input_.dict();
    const entry* e = dict.findEntry("timeStep", keyType::LITERAL);
    if (!(deltaT > 0) || !std::isfinite(deltaT))
    {
        FatalIOError
        (
            FUNCTION_NAME, __FILE__, __LINE__,
            runTime_.controlDict().name(), -1
        )
            << "Entry 'deltaT' of " << runTime_.controlDict().name()
            << " must be a positive time step [s], got " << deltaT << nl
            << exit(FatalIOError);
    }
    const scalar ratio = deltaT/dt;
    // A DEM step far below the fluid step is a units slip (1e-12 for
    // 1e-5), not a divisibility problem: say so before the rounding test
    const scalar maxStepsPerDeltaT = 1e8;
    if (ratio > maxStepsPerDeltaT)
    {
        FatalIOError
        (
            FUNCTION_NAME, __FILE__, __LINE__,
            dict.name(), e ? e->startLineNumber() : -1
        )
            << "The DEM time step (entry 'timeStep' " << dt << " s of "
            << dict.name() << ")" << nl
            << "    would take " << ratio << " DEM steps per controlDict"
            << " deltaT " << deltaT << " s (more than "
            << maxStepsPerDeltaT << ")" << nl
            << "    check the units; the largest stable step is a fraction"
            << " of the contact time (docs/demProperties.md)" << nl
            << exit(FatalIOError);
    }
    if (ratio < 1 - 1e-9)
    {
        FatalIOError
        (
            FUNCTION_NAME, __FILE__, __LINE__,
            dict.name(), e ? e->startLineNumber() : -1
        )
            << "The DEM time step (entry 'timeStep' " << dt << " s of "
            << dict.name() << ")" << nl
            << "    is larger than the controlDict deltaT " << deltaT
            << " s: the fluid step must hold a whole number (>= 1) of DEM"
            << " steps" << nl << exit(FatalIOError);
    }
    const label n = label(std::llround(ratio));
    if (n < 1 || mag(n*dt - deltaT) > 1e-9*deltaT)
    {
        FatalIOError
        (
            FUNCTION_NAME, __FILE__, __LINE__,
            dict.name(), e ? e->startLineNumber() : -1
        )
            << "The DEM time step (entry 'timeStep' " << dt << " s of "
            << dict.name() << ")" << nl
            << "    does not divide the controlDict deltaT " << deltaT
            << " s: deltaT/timeStep = " << setprecision(12) << ratio << nl
            << "    deltaT must be a whole multiple of timeStep (to 1e-9)"
            << nl << exit(FatalIOError);
    }
    return n;
}


Foam::fileName Foam::demSimulation::casePath() const
{
    // The case folder also in a parallel run: the DEM is not decomposed,
    // so its state stays where decomposePar and reconstructPar leave it
    return runTime_.globalPath();
}


Foam::fileName Foam::demSimulation::timePath() const
{
    return casePath()/runTime_.timeName();
}


void Foam::demSimulation::startSystem(polydem::Snapshot state)
{
    if (system_)
    {
        collectRemoved();
    }
    polydem::SimulationConfig config = input_.configWith(wallActive_, wallMap_);
    system_.reset(new polydem::System(std::move(config)));
    system_->initialise(std::move(state));
    collectRemoved();
    if (wallLoadsRequested_)
    {
        system_->engine().enableWallLoads(true);
    }
    if (energyFlowsRequested_)
    {
        system_->engine().enableEnergyFlows(true);
    }
}


void Foam::demSimulation::collectRemoved()
{
    const std::vector<polydem::RemovedParticle> r =
        system_->engine().takeRemoved();
    if (r.empty())
    {
        return;
    }
    balance_.addRemoved(r);
}


double Foam::demSimulation::meanParticleVolume(size_t k) const
{
    const auto& ins = input_.insertions()[k];
    const auto& ut = input_.userTypes()[ins.type];
    const auto& config = input_.config();
    if (ins.approach)
    {
        // A floating layer: every shape of the listed types equally likely
        // (spheres: the type's diameter)
        double v = 0;
        label n = 0;
        for (const int u : ins.types)
        {
            const auto& t = input_.userTypes()[u];
            for (int s = 0; s < t.nTypes; ++s, ++n)
            {
                const auto& type = config.types[t.firstType + s];
                v += t.polyhedron
                   ? config.shapes[type.shapeIndex].volume
                   : 4.0/3.0*constant::mathematical::pi*pow3(type.radius);
            }
        }
        return v/n;
    }
    if (ut.polyhedron)
    {
        // The shapes are drawn with equal probability (by bounding size)
        double v = 0;
        for (int t = 0; t < ut.nTypes; ++t)
        {
            const auto& type = config.types[ut.firstType + t];
            v += config.shapes[type.shapeIndex].volume;
        }
        return v/ut.nTypes;
    }
    // Spheres: the mean of pi d^3/6 over the distribution, from a fixed
    // sample (deterministic)
    std::mt19937_64 rng(12345u);
    const int n = 4096;
    double v = 0;
    for (int i = 0; i < n; ++i)
    {
        const double d = ins.sizes.sample(rng);
        v += constant::mathematical::pi/6*d*d*d;
    }
    return v/n;
}


bool Foam::demSimulation::inflowDue(size_t k, scalar t) const
{
    const auto& ins = input_.insertions()[k];
    const scalar eps = 1e-9*runTime_.deltaTValue();
    if (t + eps < ins.time || t > ins.endTime + eps)
    {
        return false;
    }
    // Every interval, counted in time steps from t = 0 (the same schedule
    // after a restart)
    const scalar deltaT = runTime_.deltaTValue();
    const label every = max(label(1), label(std::llround(ins.interval/deltaT)));
    const label index = label(std::llround(t/deltaT));
    return index % every == 0;
}


void Foam::demSimulation::checkApproachRegions() const
{
    // A coupled run: the fluid mesh is in the registry. An inflow with an
    // approach region must place its blocks outside the mesh (a block's
    // volume appearing inside it kicks the fluid: the d(eps)/dt of the
    // pressure equation) and must release them inside it (outside, a block
    // gets no fluid force and falls)
    if (!runTime_.foundObject<polyMesh>(polyMesh::defaultRegion))
    {
        return;
    }
    const polyMesh& mesh =
        runTime_.lookupObject<polyMesh>(polyMesh::defaultRegion);
    const boundBox& mb = mesh.bounds();
    const auto& config = input_.config();
    for (const auto& ins : input_.insertions())
    {
        if (!ins.approach)
        {
            continue;
        }
        double rMax = 0;
        for (const int u : ins.types)
        {
            const auto& t = input_.userTypes()[u];
            for (int s = 0; s < t.nTypes; ++s)
            {
                const auto& type = config.types[t.firstType + s];
                rMax = std::max
                (
                    rMax,
                    t.polyhedron
                  ? config.shapes[type.shapeIndex].boundingRadius
                  : type.radius
                );
            }
        }
        const polydem::Vec3& lo = ins.region.min;
        const polydem::Vec3& hi = ins.region.max;
        bool apart = false;
        for (int d = 0; d < 3; ++d)
        {
            apart = apart
                || hi[d] + rMax <= mb.min()[d] || lo[d] - rMax >= mb.max()[d];
        }
        if (!apart)
        {
            FatalIOError
            (
                FUNCTION_NAME, __FILE__, __LINE__, input_.dict().name(), -1
            )   << "Entry 'insertion/" << ins.name.c_str() << "/region' "
                << "(min " << vector(lo.x, lo.y, lo.z) << ", max "
                << vector(hi.x, hi.y, hi.z) << ") with an approach region "
                << "must lie outside the fluid mesh (bounds " << mb
                << ") by the blocks' largest bounding radius " << rMax
                << " m: a block inserted inside the mesh appears there in "
                << "one step and kicks the fluid" << nl << exit(FatalIOError);
        }
        bool reaches = true;
        for (int d = 0; d < 3; ++d)
        {
            reaches = reaches
                && ins.approachMax[d] > mb.min()[d]
                && ins.approachMin[d] < mb.max()[d];
        }
        if (!reaches)
        {
            FatalIOError
            (
                FUNCTION_NAME, __FILE__, __LINE__, input_.dict().name(), -1
            )   << "Entry 'insertion/" << ins.name.c_str() << "/approach' "
                << "must reach into the fluid mesh (bounds " << mb << "): "
                << "a block released outside it gets no fluid force and "
                << "falls; end the box a bounding radius (" << rMax
                << " m) inside the inlet" << nl << exit(FatalIOError);
        }
    }
}


polydem::ParticleState Foam::demSimulation::insertInflow
(
    size_t k,
    const polydem::ParticleState& present,
    int64_t step
) const
{
    const auto& ins = input_.insertions()[k];
    const auto& ut = input_.userTypes()[ins.type];
    const auto& config = input_.config();

    // The region's solid volume now (particles whose centre is in it)
    const auto bb = ins.region.bounds();
    double solid = 0;
    polydem::ParticleState near;
    double rMax = 0;
    for (size_t i = 0; i < present.size(); ++i)
    {
        rMax = std::max(rMax, present.radius[i]);
    }
    for (size_t i = 0; i < present.size(); ++i)
    {
        const polydem::Vec3& x = present.position[i];
        const double r = present.radius[i] + rMax + ins.gap;
        bool close = true;
        for (int d = 0; d < 3; ++d)
        {
            close = close && x[d] >= bb.first[d] - r && x[d] <= bb.second[d] + r;
        }
        if (!close)
        {
            continue;
        }
        // Obstacles: only the particles that can touch the region
        polydem::ParticleState one;
        one.resize(1);
        one.position[0] = x;
        one.radius[0] = present.radius[i];
        polydem::appendParticles(near, one);
        if (ins.region.contains(x, 0))
        {
            const auto& type = config.types[present.type[i]];
            solid += present.mass[i]/config.materials[type.material].density;
        }
    }
    const double target = ins.solidFraction*ins.region.volume();
    const double missing = target - solid;
    const label number = label(std::floor(missing/meanParticleVolume_[k]));
    if (number < 1)
    {
        return polydem::ParticleState();
    }

    // SplitMix64 of (seed, step): a new stream per check, known at restart
    uint64_t z = uint64_t(ins.seed)*0x9E3779B97F4A7C15ull + uint64_t(step);
    z = (z ^ (z >> 30))*0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27))*0x94D049BB133111EBull;
    const uint64_t checkSeed = z ^ (z >> 31);

    polydem::InsertedParticles added;
    if (ins.approach)
    {
        // A floating layer in the approach region: centres at the height,
        // each block one of the types' shapes, exactly clear of the rest
        polydem::LayerInsertion layer;
        for (size_t j = 0; j < ins.types.size(); ++j)
        {
            const auto& t = input_.userTypes()[ins.types[j]];
            // Every shape of the listed types equally likely (a type with
            // several shapes weighs as many)
            for (int s = 0; s < t.nTypes; ++s)
            {
                layer.types.push_back(t.firstType + s);
                if (!ins.typeOrientations.empty())
                {
                    layer.typeOrientations.push_back
                    (
                        ins.typeOrientations[j]
                    );
                }
            }
        }
        layer.min = bb.first;
        layer.max = bb.second;
        layer.height = ins.height;
        layer.number = size_t(number);
        layer.seed = checkSeed;
        layer.velocity = ins.velocity;
        layer.orientation =
            ins.fixedOrientation ? ins.orientation : polydem::Quaternion();
        layer.randomYaw = ins.randomYaw;
        layer.yawAxis = ins.yawAxis;
        layer.maxAttempts = size_t(ins.attempts);
        try
        {
            added = polydem::insertLayer
            (
                *system_, layer, present, polydem::nextParticleId(present)
            );
        }
        catch (const polydem::Error& err)
        {
            throw polydem::Error
            (
                err.message(), input_.dict().name(), "insertion/" + ins.name
            );
        }
    }
    else
    {
    polydem::RandomFillInsertion fill;
    fill.types = demInsertionsReader::insertionTypes(ut);
    fill.region = ins.region;
    fill.sizes = ins.sizes;
    fill.number = size_t(number);
    fill.seed = checkSeed;
    fill.gap = ins.gap;
    fill.velocity = ins.velocity;
    fill.fixedOrientation = ins.fixedOrientation;
    fill.orientation = ins.orientation;
    fill.randomYaw = ins.randomYaw;
    fill.yawAxis = ins.yawAxis;
    fill.maxAttempts = size_t(ins.attempts);
    fill.partial = true;

    try
    {
        added = polydem::insertRandomFill
        (
            *system_, fill, near, polydem::nextParticleId(present)
        );
    }
    catch (const polydem::Error& err)
    {
        throw polydem::Error
        (
            err.message(), input_.dict().name(), "insertion/" + ins.name
        );
    }
    }
    checkInsertedMotion
    (
        added.particles, "insertion/" + ins.name + "/velocity", false
    );
    if (input_.reportInterval() <= 0 || added.particles.size() > 0)
    {
        Info<< "DEM inflow '" << ins.name << "': +"
            << label(added.particles.size()) << " of " << number
            << " wanted, solid fraction " << solid/ins.region.volume()
            << " -> " << (solid + added.volume)/ins.region.volume()
            << " (target " << ins.solidFraction << ")" << endl;
    }
    return added.particles;
}


void Foam::demSimulation::collectWallLoads()
{
    polydem::Engine& engine = system_->engine();
    if (!engine.wallLoadsEnabled())
    {
        return;
    }
    const polydem::WallLoadSum s = engine.wallLoadSum();
    engine.resetWallLoadSum();
    const label before = wallLoadSteps_;
    wallLoadSteps_ += label(s.steps);
    if (wallLoadSteps_ == 0)
    {
        return;
    }
    // Running means over the steps so far: each chunk weighs by its steps
    const double a = double(before)/wallLoadSteps_;
    const double b = 1.0/wallLoadSteps_;
    for (size_t f = 0; f < wallMap_.size(); ++f)
    {
        polydem::WallLoad& m = wallLoadMean_[f];
        m.force = a*m.force;
        m.torque = a*m.torque;
        m.normalForce = a*m.normalForce;
        m.contacts = a*m.contacts;
        const int k = wallMap_[f];
        if (k >= 0 && size_t(k) < s.sum.size())
        {
            m.force += b*s.sum[k].force;
            m.torque += b*s.sum[k].torque;
            m.normalForce += b*s.sum[k].normalForce;
            m.contacts += b*s.sum[k].contacts;
            m.point = s.sum[k].point;
        }
    }
}


void Foam::demSimulation::collectEnergyFlows()
{
    polydem::Engine& engine = system_->engine();
    if (!engine.energyFlowsEnabled())
    {
        return;
    }
    const polydem::EnergyFlows f = engine.energyFlows();
    engine.resetEnergyFlows();
    energyFlowSum_.pairDissipation += f.pairDissipation;
    energyFlowSum_.wallDissipation += f.wallDissipation;
    energyFlowSum_.wallWork += f.wallWork;
    energyFlowSum_.externalWork += f.externalWork;
    energyFlowSum_.steps += f.steps;
}


void Foam::demSimulation::requestEnergyFlows() const
{
    if (!energyFlowsRequested_)
    {
        energyFlowsRequested_ = true;
        system_->engine().enableEnergyFlows(true);
    }
}


void Foam::demSimulation::requestWallLoads() const
{
    if (!wallLoadsRequested_)
    {
        wallLoadsRequested_ = true;
        system_->engine().enableWallLoads(true);
    }
}


bool Foam::demSimulation::removeDueWalls()
{
    const int64_t step = system_->engine().step();
    std::vector<bool> active(wallActive_);
    bool changed = false;
    for (size_t k = 0; k < active.size(); ++k)
    {
        if (active[k] && wallRemovalStep_[k] >= 0 && step >= wallRemovalStep_[k])
        {
            active[k] = false;
            changed = true;
            Info<< "DEM t = " << system_->engine().time() << " s: wall '"
                << input_.walls()[k].name << "' removed (activeUntil "
                << input_.walls()[k].activeUntil << ")" << endl;
        }
    }
    if (!changed)
    {
        return false;
    }

    polydem::Snapshot state = system_->engine().snapshot();

    // Wall springs: running-system index -> full index -> new index
    const std::vector<int> oldMap(wallMap_);
    wallActive_ = active;
    std::vector<int> newMap;
    input_.configWith(wallActive_, newMap);
    std::unordered_map<int, int> renumber;
    for (size_t f = 0; f < oldMap.size(); ++f)
    {
        if (oldMap[f] >= 0)
        {
            renumber[oldMap[f]] = newMap[f];
        }
    }
    std::vector<polydem::WallHistory> kept;
    for (const auto& w : state.walls)
    {
        const auto it = renumber.find(w.wall);
        if (it != renumber.end() && it->second >= 0)
        {
            kept.push_back(w);
            kept.back().wall = it->second;
        }
    }
    state.walls.swap(kept);
    startSystem(std::move(state));
    return true;
}


void Foam::demSimulation::checkInsertedMotion
(
    const polydem::ParticleState& p,
    const std::string& entry,
    const bool listed
) const
{
    // An inserted velocity that carries a particle further than its own
    // diameter in one DEM step, or a spin of more than 1 rad per step, cannot
    // be integrated (and its kinetic energy may overflow, tripping the
    // floating-point trap before the engine's blow-up guard): refused here,
    // where the entry is known
    const double dt = input_.config().timeStep;
    for (size_t i = 0; i < p.size(); ++i)
    {
        const polydem::Vec3& v = p.velocity[i];
        const polydem::Vec3& w = p.omega[i];
        const double d = 2*p.radius[i];
        const double vMax =
            std::max(std::abs(v.x), std::max(std::abs(v.y), std::abs(v.z)));
        const double wMax =
            std::max(std::abs(w.x), std::max(std::abs(w.y), std::abs(w.z)));
        const std::string at =
            listed ? entry + "[" + std::to_string(i) + "]" : entry;
        std::ostringstream msg;
        msg.precision(6);
        if (!(vMax*dt <= d))
        {
            msg << "an inserted velocity (" << v.x << ' ' << v.y << ' '
                << v.z << ") m/s moves particle " << p.id[i]
                << " further than its diameter (" << d << " m) in one DEM"
                << " step of " << dt << " s: lower the velocity or the time"
                << " step";
            throw polydem::Error
            (
                msg.str(), input_.dict().name(),
                listed ? at + "/velocity" : at
            );
        }
        if (!(wMax*dt <= 1))
        {
            msg << "an inserted angular velocity (" << w.x << ' ' << w.y
                << ' ' << w.z << ") rad/s turns particle " << p.id[i]
                << " by more than 1 rad in one DEM step of " << dt << " s";
            throw polydem::Error
            (
                msg.str(), input_.dict().name(), listed ? at + "/omega" : at
            );
        }
    }
}


void Foam::demSimulation::checkInsertedOverlaps
(
    const polydem::ParticleState& p,
    const polydem::ParticleState& present,
    const std::string& insertionName,
    const bool listed
) const
{
    const std::vector<polydem::InsertionOverlap> found =
        polydem::insertionOverlaps
        (
            system_->config(), p, present, system_->engine().step() == 0
        );
    if (found.empty())
    {
        return;
    }
    const std::string base = "insertion/" + insertionName;
    auto name = [&](size_t i)
    {
        return listed
            ? base + "/particles[" + std::to_string(i) + "]"
            : "particle " + std::to_string(p.id[i]) + " of " + base;
    };
    std::ostringstream msg;
    msg.precision(3);
    msg << found.size() << " overlap(s) of inserted particles beyond the"
        << " tolerance (depth " << 100*polydem::kInsertionDepthTolerance
        << " % of the smaller diameter for spheres, volume "
        << 100*polydem::kInsertionVolumeTolerance << " % of the smaller"
        << " particle with a polyhedron):";
    const size_t nShow = std::min<size_t>(found.size(), 5);
    for (size_t k = 0; k < nShow; ++k)
    {
        const polydem::InsertionOverlap& o = found[k];
        msg << "\n    " << name(o.particle);
        if (o.behindWall)
        {
            msg << ": centre on or behind plane wall '" << o.wall << "'";
            continue;
        }
        switch (o.partner)
        {
            case polydem::InsertionOverlap::Partner::inserted:
                msg << " and " << name(o.otherIndex);
                break;
            case polydem::InsertionOverlap::Partner::present:
                msg << " and particle " << o.otherId << " already present";
                break;
            case polydem::InsertionOverlap::Partner::wall:
                msg << " and wall '" << o.wall << "'";
                break;
        }
        msg << ": overlap " << (o.byVolume ? "volume " : "depth ")
            << 100*o.measure << " %";
    }
    if (found.size() > nShow)
    {
        msg << "\n    ... and " << found.size() - nShow << " more";
    }
    msg << "\n    (overlapping particles are pushed apart by their stored"
        << " elastic energy; two spheres at one point never interact)";
    const polydem::InsertionOverlap& first = found.front();
    throw polydem::Error
    (
        msg.str(), input_.dict().name(),
        listed
      ? base + "/particles[" + std::to_string(first.particle) + "]/position"
      : base + "/region"
    );
}


polydem::ParticleState Foam::demSimulation::insert
(
    size_t k,
    const polydem::ParticleState& obstacles,
    int64_t firstId
) const
{
    const auto& ins = input_.insertions()[k];
    const auto& ut = input_.userTypes()[ins.type];
    const polydem::InsertionTypes types =
        demInsertionsReader::insertionTypes(ut);
    if (ins.kind == demPropertiesReader::insertion::method::list)
    {
        polydem::ParticleState p =
            polydem::insertList(*system_, types, ins.particles, firstId);
        checkInsertedMotion(p, "insertion/" + ins.name + "/particles", true);
        checkInsertedOverlaps(p, obstacles, ins.name, true);
        Info<< "DEM insertion '" << ins.name << "': " << label(p.size())
            << (ut.polyhedron ? " polyhedra" : " spheres") << " (list)" << endl;
        return p;
    }

    polydem::RandomFillInsertion fill;
    fill.types = types;
    fill.region = ins.region;
    fill.sizes = ins.sizes;
    fill.number = size_t(ins.number);
    fill.seed = uint64_t(ins.seed);
    fill.gap = ins.gap;
    fill.velocity = ins.velocity;
    fill.fixedOrientation = ins.fixedOrientation;
    fill.orientation = ins.orientation;

    polydem::InsertedParticles added;
    try
    {
        added = polydem::insertRandomFill(*system_, fill, obstacles, firstId);
    }
    catch (const polydem::Error& err)
    {
        throw polydem::Error
        (
            err.message(), input_.dict().name(),
            "insertion/" + ins.name + "/number"
        );
    }
    checkInsertedMotion
    (
        added.particles, "insertion/" + ins.name + "/velocity", false
    );
    checkInsertedOverlaps(added.particles, obstacles, ins.name, false);
    Info<< "DEM insertion '" << ins.name << "': " << label(added.particles.size())
        << (ut.polyhedron ? " polyhedra" : " spheres")
        << ", solid fraction of the region "
        << added.volume/std::max(ins.region.volume(), VSMALL) << endl;
    return added.particles;
}


void Foam::demSimulation::insertDue()
{
    const scalar t = runTime_.value() - runTime_.deltaTValue();
    for (size_t k = 0; k < insertionDone_.size(); ++k)
    {
        const auto& ins = input_.insertions()[k];
        if (ins.kind == demPropertiesReader::insertion::method::inflow)
        {
            if (!inflowDue(k, t))
            {
                continue;
            }
            const polydem::ParticleState present = system_->engine().particles();
            const polydem::ParticleState added =
                insertInflow(k, present, system_->engine().step());
            if (added.size())
            {
                system_->addParticles
                (
                    added, "the particles of insertion '" + ins.name + "'"
                );
                balance_.addInserted(k, added);
                collectRemoved();
            }
            continue;
        }
        if (insertionDone_[k])
        {
            continue;
        }
        if (ins.time > t + 1e-9*runTime_.deltaTValue())
        {
            continue;
        }
        insertionDone_[k] = true;
        const polydem::ParticleState present = system_->engine().particles();
        const polydem::ParticleState added =
            insert(k, present, polydem::nextParticleId(present));
        system_->addParticles
        (
            added, "the particles of insertion '" + ins.name + "'"
        );
        balance_.addInserted(k, added);
        collectRemoved();
    }
}


bool Foam::demSimulation::wallMoves(size_t k) const
{
    const auto& w = input_.walls()[k];
    const auto& config = input_.config();
    const polydem::WallMotion& m =
        w.isPlane ? config.planes[w.index].motion : config.meshes[w.index].motion;
    return m.kind != polydem::MotionKind::fixed;
}


std::vector<double> Foam::demSimulation::volumeEquivalentDiameters
(
    const polydem::ParticleState& p
) const
{
    const auto& config = input_.config();
    std::vector<double> d(p.size());
    for (size_t i = 0; i < p.size(); ++i)
    {
        const auto& type = config.types[p.type[i]];
        const double V = p.mass[i]/config.materials[type.material].density;
        d[i] = std::cbrt(6*V/constant::mathematical::pi);
    }
    return d;
}


polydem::TriangleMesh Foam::demSimulation::wallSurface
(
    scalar t,
    std::vector<int>& ids,
    bool moving
) const
{
    polydem::TriangleMesh surface;
    ids.clear();
    const auto& config = input_.config();
    const auto& walls = input_.walls();

    auto place = [t](const polydem::WallMotion& m, const polydem::Vec3& y)
    {
        if (m.kind == polydem::MotionKind::translation)
        {
            return y + t*m.velocity;
        }
        if (m.kind == polydem::MotionKind::rotation)
        {
            const polydem::Vec3 a = m.axis/norm(m.axis);
            const polydem::Quaternion R = polydem::fromRotationVector((m.omega*t)*a);
            return m.origin + polydem::rotate(R, y - m.origin);
        }
        return y;
    };

    for (size_t k = 0; k < walls.size(); ++k)
    {
        if (!wallActive_[k] || wallMoves(k) != moving)
        {
            continue;
        }
        const int base = int(surface.points.size());
        if (walls[k].isPlane)
        {
            const auto& pl = config.planes[walls[k].index];
            const polydem::Vec3 n = pl.normal/norm(pl.normal);
            // A square centred at the scene centre's foot on the plane
            const scalar size =
                walls[k].displaySize > 0 ? walls[k].displaySize : input_.sceneSize();
            const polydem::Vec3 c =
                input_.sceneCentre() - dot(input_.sceneCentre() - pl.point, n)*n;
            polydem::Vec3 u = cross(n, polydem::Vec3(1, 0, 0));
            if (norm(u) < 0.1)
            {
                u = cross(n, polydem::Vec3(0, 1, 0));
            }
            u = (0.5*size/norm(u))*u;
            const polydem::Vec3 v = cross(n, u);
            surface.points.push_back(place(pl.motion, c - u - v));
            surface.points.push_back(place(pl.motion, c + u - v));
            surface.points.push_back(place(pl.motion, c + u + v));
            surface.points.push_back(place(pl.motion, c - u + v));
            surface.triangles.push_back({base, base + 1, base + 2});
            surface.triangles.push_back({base, base + 2, base + 3});
            ids.push_back(int(k));
            ids.push_back(int(k));
        }
        else
        {
            const auto& mw = config.meshes[walls[k].index];
            for (const auto& y : mw.mesh.points)
            {
                surface.points.push_back(place(mw.motion, y));
            }
            for (const auto& tri : mw.mesh.triangles)
            {
                surface.triangles.push_back
                (
                    {tri[0] + base, tri[1] + base, tri[2] + base}
                );
                ids.push_back(int(k));
            }
        }
    }
    return surface;
}


void Foam::demSimulation::writePolyhedra
(
    const fileName& path,
    const polydem::ParticleState& p
) const
{
    const auto& config = input_.config();
    std::vector<polydem::Vec3> points;
    std::vector<std::vector<int>> polygons;
    std::vector<size_t> owner;
    for (size_t i = 0; i < p.size(); ++i)
    {
        const auto& type = config.types[p.type[i]];
        if (type.shape != polydem::ShapeKind::polyhedron)
        {
            continue;
        }
        const polydem::ConvexShape& s = config.shapes[type.shapeIndex];
        const int base = int(points.size());
        for (const auto& v : s.vertices)
        {
            points.push_back(p.position[i] + polydem::rotate(p.orientation[i], v));
        }
        for (int f = 0; f < s.nFaces(); ++f)
        {
            std::vector<int> poly;
            for (int k = s.faceStart[f]; k < s.faceStart[f + 1]; ++k)
            {
                poly.push_back(base + s.faceVertex[k]);
            }
            polygons.push_back(std::move(poly));
            owner.push_back(i);
        }
    }
    polydem::writeParticleFacesVtp
    (
        path, points, polygons, owner, p, volumeEquivalentDiameters(p)
    );
}


void Foam::demSimulation::writeState()
{
    const fileName dir(timePath()/"polyDEM");
    mkDir(dir);
    const polydem::Snapshot state = system_->engine().snapshot();
    polydem::writeSnapshot
    (
        dir/"state", state, input_.stateFormat(),
        polydem::stateTypeRecords(input_.config())
    );
    balance_.check(int64_t(state.particles.size()), "at the write");
    balance_.write
    (
        dir/"particleBalance", state.step, int64_t(state.particles.size())
    );

    if (input_.writeVtk())
    {
        const fileName rel(runTime_.timeName()/"polyDEM");
        // The time as the folder shows it (no round-off digits)
        const scalar t = readScalar(runTime_.timeName());
        polydem::writeParticlesVtp
        (
            dir/"particles.vtp",
            state.particles,
            volumeEquivalentDiameters(state.particles)
        );
        particlesPvd_.add(t, rel/"particles.vtp");
        particlesPvd_.write(casePath()/"particles.pvd");

        if (input_.hasPolyhedra())
        {
            writePolyhedra(dir/"polyhedra.vtp", state.particles);
            polyhedraPvd_.add(t, rel/"polyhedra.vtp");
            polyhedraPvd_.write(casePath()/"polyhedra.pvd");
        }

        // Fixed walls (a large STL does not change) once, as part 0 of
        // walls.pvd at every time; moving walls at each write, part 1
        std::vector<bool> fixedNow(wallActive_.size(), false);
        bool anyFixed = false;
        for (size_t k = 0; k < wallActive_.size(); ++k)
        {
            fixedNow[k] = wallActive_[k] && !wallMoves(k);
            anyFixed = anyFixed || fixedNow[k];
        }
        bool indexChanged = false;
        if (anyFixed)
        {
            if
            (
                fixedWallsFile_.empty()
             || fixedNow != fixedWallsWritten_
             || !isFile(casePath()/fixedWallsFile_)
            )
            {
                std::vector<int> ids;
                const polydem::TriangleMesh fixed =
                    wallSurface(state.time, ids, false);
                polydem::writeSurfaceVtp
                (
                    dir/"fixedWalls.vtp", fixed, ids, "wall"
                );
                const std::string previous = fixedWallsFile_;
                fixedWallsFile_ = rel/"fixedWalls.vtp";
                if (fixedNow == fixedWallsWritten_ && !previous.empty())
                {
                    // The same walls, their file gone (purgeWrite): the
                    // earlier times name the new one
                    const auto entries = wallsPvd_.entries();
                    wallsPvd_.clear();
                    for (const auto& e : entries)
                    {
                        wallsPvd_.add
                        (
                            e.time,
                            e.file == previous
                          ? static_cast<const std::string&>(fixedWallsFile_)
                          : e.file,
                            e.part
                        );
                    }
                }
                fixedWallsWritten_ = fixedNow;
            }
            wallsPvd_.add(t, fixedWallsFile_, 0);
            indexChanged = true;
        }
        std::vector<int> ids;
        const polydem::TriangleMesh moving = wallSurface(state.time, ids, true);
        if (moving.size())
        {
            polydem::writeSurfaceVtp(dir/"walls.vtp", moving, ids, "wall");
            wallsPvd_.add(t, rel/"walls.vtp", 1);
            indexChanged = true;
        }
        if (indexChanged)
        {
            wallsPvd_.write(casePath()/"walls.pvd");
        }
    }
    Info<< "DEM t = " << state.time << " s: wrote " << dir << endl;
}


void Foam::demSimulation::restartWallsIndex()
{
    // The restart time's entries of walls.pvd (dropped by read) again, if
    // their files are there: its fixedWalls.vtp may be in an earlier folder
    polydem::PvdCollection previous;
    previous.read(casePath()/"walls.pvd");
    bool found = false;
    for (const auto& e : previous.entries())
    {
        if
        (
            mag(e.time - runTime_.value()) > 1e-6*runTime_.deltaTValue()
         || !isFile(casePath()/e.file)
        )
        {
            continue;
        }
        wallsPvd_.add(e.time, e.file, e.part);
        found = true;
        if (e.part == 0 && fileName(e.file).name() == "fixedWalls.vtp")
        {
            // Still the fixed walls of this time: written again only when
            // one is removed
            fixedWallsFile_ = e.file;
            fixedWallsWritten_.assign(wallActive_.size(), false);
            for (size_t k = 0; k < wallActive_.size(); ++k)
            {
                fixedWallsWritten_[k] = wallActive_[k] && !wallMoves(k);
            }
        }
    }
    const fileName rel(runTime_.timeName()/"polyDEM");
    if (!found && isFile(timePath()/"polyDEM"/"walls.vtp"))
    {
        wallsPvd_.add(runTime_.value(), rel/"walls.vtp");
    }
}


Foam::fileName Foam::demSimulation::restartEvidence() const
{
    // uniform/time is written by Time at every write time of a solver (and
    // carried by decomposePar and reconstructPar); a polyDEM folder by an
    // earlier DEM run
    const fileName candidates[3] =
    {
        runTime_.timePath()/"uniform"/"time",
        timePath()/"uniform"/"time",
        timePath()/"polyDEM"
    };
    for (const fileName& f : candidates)
    {
        if (isFile(f) || isDir(f))
        {
            return f;
        }
    }
    return fileName();
}


Foam::word Foam::demSimulation::userTypeOf(const label engineType) const
{
    for (const auto& u : input_.userTypes())
    {
        if (engineType >= u.firstType && engineType < u.firstType + u.nTypes)
        {
            return u.name;
        }
    }
    return word("?");
}


void Foam::demSimulation::checkState
(
    const fileName& statePath,
    const polydem::StateFileInfo& info,
    const polydem::Snapshot& state
) const
{
    const dictionary& dict = input_.dict();
    const auto& types = input_.config().types;
    const entry* typesEntry = dict.findEntry("particleTypes", keyType::LITERAL);
    const label line = typesEntry ? typesEntry->startLineNumber() : -1;

    if (!info.checksummed)
    {
        WarningInFunction
            << "The state " << statePath << " has no checksum line (written "
            << "by hand or by an earlier Hedra, file version " << info.version
            << "): its contents are read unchecked" << endl;
    }

    if (info.types.empty())
    {
        WarningInFunction
            << "The state " << statePath << " does not record its particle "
            << "types (file version " << info.version << "): its type "
            << "indices are taken to be those of entry 'particleTypes' of "
            << dict.name() << " as it is now, unchecked" << endl;
        for (size_t i = 0; i < state.particles.size(); ++i)
        {
            const int t = state.particles.type[i];
            if (t < 0 || size_t(t) >= types.size())
            {
                FatalIOError
                (
                    FUNCTION_NAME, __FILE__, __LINE__, dict.name(), line
                )
                    << "Particle id " << label(state.particles.id[i])
                    << " of the state " << statePath << " has type index "
                    << t << ", but entry 'particleTypes' of " << dict.name()
                    << " gives " << label(types.size()) << " types" << nl
                    << exit(FatalIOError);
            }
        }
        return;
    }

    // Names, by index: a reordered, renamed, added or removed type would
    // give the particles of one type the properties of another
    bool namesMatch = info.types.size() == types.size();
    for (size_t k = 0; namesMatch && k < types.size(); ++k)
    {
        namesMatch = info.types[k].name == types[k].name;
    }
    if (!namesMatch)
    {
        FatalIOError(FUNCTION_NAME, __FILE__, __LINE__, dict.name(), line)
            << "The particle types of the state " << statePath << nl
            << "    do not match entry 'particleTypes' of " << dict.name()
            << nl << "    state (by type index):";
        for (const auto& t : info.types)
        {
            FatalIOError<< ' ' << t.name.c_str();
        }
        FatalIOError<< nl << "    particleTypes now:      ";
        for (const auto& t : types)
        {
            FatalIOError<< ' ' << t.name.c_str();
        }
        FatalIOError
            << nl << "A restart would give the particles of one type the "
            << "shape and material of another. Give particleTypes the types "
            << "(names, order, number of shapes) the state was written "
            << "with, or start afresh from another time." << nl
            << exit(FatalIOError);
    }

    for (size_t k = 0; k < types.size(); ++k)
    {
        const std::uint64_t now = polydem::shapeChecksum(input_.config(), int(k));
        if (now != info.types[k].shapeChecksum)
        {
            const word userType(userTypeOf(label(k)));
            const entry* e = typesEntry && typesEntry->isDict()
                ? typesEntry->dict().findEntry(userType, keyType::LITERAL)
                : nullptr;
            FatalIOError
            (
                FUNCTION_NAME, __FILE__, __LINE__, dict.name(),
                e ? e->startLineNumber() : line
            )
                << "The shape of particle type '" << types[k].name.c_str()
                << "' (entry 'particleTypes/" << userType << "' of "
                << dict.name() << ")" << nl
                << "    differs from the one the state " << statePath
                << " was written with (shape checksum "
                << hex16(info.types[k].shapeChecksum).c_str()
                << " in the state, " << hex16(now).c_str() << " now)." << nl
                << "The particles' orientations, radii and masses belong to "
                << "the old shape: restore its geometry, or start afresh."
                << nl << exit(FatalIOError);
        }
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::demSimulation::demSimulation
(
    const Time& runTime,
    const IOdictionary& properties
)
:
    demParticleSource(runTime),
    runTime_(runTime),
    properties_(properties),
    input_(properties),
    system_(),
    wallActive_(input_.walls().size(), true),
    wallRemovalStep_(input_.walls().size(), -1),
    wallMap_(),
    insertionDone_(input_.insertions().size(), false),
    balance_
    (
        [this]()
        {
            std::vector<std::string> n;
            for (const auto& ins : input_.insertions()) n.push_back(ins.name);
            return n;
        }(),
        [this]()
        {
            std::vector<std::string> n;
            for (const auto& o : input_.config().outlets) n.push_back(o.name);
            return n;
        }()
    ),
    meanParticleVolume_(),
    stepsPerDeltaT_(computeStepsPerDeltaT()),
    lastEvolveTime_(runTime_.value()),
    stepCarry_(0),
    stateCache_(),
    stateCacheStep_(-1),
    wallLoadsRequested_(false),
    wallLoadMean_(),
    wallLoadSteps_(0),
    energyFlowsRequested_(false),
    energyFlowSum_(),
    summary_(),
    clock_(),
    wallStart_(0),
    lastReportWall_(0),
    lastReportStep_(0),
    startStep_(0),
    startTimeValue_(runTime.value())
{
    const scalar dt = input_.config().timeStep;
    for (size_t k = 0; k < wallRemovalStep_.size(); ++k)
    {
        const scalar until = input_.walls()[k].activeUntil;
        if (until < 0.5*GREAT)
        {
            wallRemovalStep_[k] = int64_t(std::llround(until/dt));
        }
    }

    for (size_t k = 0; k < input_.insertions().size(); ++k)
    {
        meanParticleVolume_.push_back(meanParticleVolume(k));
    }
    checkApproachRegions();

    const fileName statePath(timePath()/"polyDEM"/"state");
    const int64_t startStep = int64_t(std::llround(runTime_.value()/dt));

    // Walls already removed at the start time
    for (size_t k = 0; k < wallActive_.size(); ++k)
    {
        wallActive_[k] = wallRemovalStep_[k] < 0 || startStep < wallRemovalStep_[k];
    }

    const bool restart = isFile(statePath);
    if (restart)
    {
        Info<< "DEM: restarting from " << statePath << endl;
        polydem::StateFileInfo info;
        polydem::Snapshot state = polydem::readSnapshot(statePath, &info);
        checkState(statePath, info, state);
        // (an adjusted deltaT with no particles yet: within half a step)
        if
        (
            mag(state.time - runTime_.value())
          > 0.5*input_.config().timeStep + 1e-6*runTime_.deltaTValue()
        )
        {
            WarningInFunction
                << "The state in " << statePath << " is at t = " << state.time
                << " s, the time folder says " << runTime_.value() << " s"
                << endl;
        }
        // Insertions before the restart time are in the state already
        for (size_t k = 0; k < insertionDone_.size(); ++k)
        {
            insertionDone_[k] =
                input_.insertions()[k].time
              < runTime_.value() - 1e-9*runTime_.deltaTValue();
        }
        balance_.read
        (
            timePath()/"polyDEM"/"particleBalance", state.step,
            int64_t(state.particles.size())
        );
        startSystem(std::move(state));

        particlesPvd_.read(casePath()/"particles.pvd", runTime_.value());
        wallsPvd_.read(casePath()/"walls.pvd", runTime_.value());
        polyhedraPvd_.read(casePath()/"polyhedra.pvd", runTime_.value());
        const fileName rel(runTime_.timeName()/"polyDEM");
        if (isFile(timePath()/"polyDEM"/"particles.vtp"))
        {
            particlesPvd_.add(runTime_.value(), rel/"particles.vtp");
        }
        restartWallsIndex();
        if (isFile(timePath()/"polyDEM"/"polyhedra.vtp"))
        {
            polyhedraPvd_.add(runTime_.value(), rel/"polyhedra.vtp");
        }
    }
    else
    {
        // A time written by a run (fluid or DEM) without the DEM state: the
        // state was lost (deleted, not carried by a copy or a
        // decomposition); re-inserting would replace a settled bed by new
        // particles without a word
        const fileName evidence(restartEvidence());
        if (!evidence.empty() && !input_.freshStart())
        {
            const dictionary& dict = input_.dict();
            FatalIOError(FUNCTION_NAME, __FILE__, __LINE__, dict.name(), -1)
                << "The start time " << runTime_.timeName() << " is a restart "
                << "time (" << evidence << " exists)" << nl
                << "    but it has no DEM state: " << statePath
                << " is missing." << nl
                << "The DEM state lives in the case folder also for parallel "
                << "runs (<case>/<time>/polyDEM). Restore it, restart from "
                << "a time that has it, or, to insert new particles at this "
                << "time on purpose, set" << nl
                << "    freshStart true;" << nl
                << "in " << dict.name() << nl << exit(FatalIOError);
        }
        if (!evidence.empty())
        {
            Info<< "DEM: freshStart true: new particles at the restart time "
                << runTime_.timeName() << " (no " << statePath << ")" << endl;
        }
        Info<< "DEM: fresh start at t = " << runTime_.value()
            << " s (no " << statePath << ")" << endl;

        polydem::Snapshot state;
        state.time = runTime_.value();
        state.step = startStep;

        // The system first (it checks the config), then the particles
        startSystem(state);
        for (size_t k = 0; k < insertionDone_.size(); ++k)
        {
            const auto& ins = input_.insertions()[k];
            if (ins.kind == demPropertiesReader::insertion::method::inflow)
            {
                // Its first fill is at the start of the first time step
                // (evolve), on the schedule a restart keeps
                continue;
            }
            if (ins.time <= runTime_.value() + 1e-9*runTime_.deltaTValue())
            {
                insertionDone_[k] = true;
                const polydem::ParticleState p =
                    insert(k, state.particles, polydem::nextParticleId(state.particles));
                balance_.addInserted(k, p);
                polydem::appendParticles(state.particles, p);
            }
        }
        startSystem(std::move(state));
        removeDueWalls();
        writeState();
    }

    Info<< "DEM: " << label(system_->engine().particles().size())
        << " particles, back end '" << system_->engine().name().c_str()
        << "', time step " << dt << " s, " << stepsPerDeltaT_
        << " steps per deltaT" << endl;

    // The monitors of earlier versions are function objects now
    if (properties_.found("monitors"))
    {
        FatalIOErrorInFunction(properties_)
            << "Entry 'monitors' in " << input_.dict().name()
            << " is no longer read: the particle monitors are function "
            << "objects now. Move each of them into the 'functions' "
            << "dictionary of system/controlDict, adding "
            << "'libs (demFunctionObjects);', e.g." << nl << nl
            << "    functions" << nl
            << "    {" << nl
            << "        outlet { type planeFlux; libs (demFunctionObjects); "
            << "point (0 0 -0.01); normal (0 0 -1); }" << nl
            << "    }" << nl << nl
            << "(types planeFlux, reposeAngle, boundingBox; their entries "
            << "are unchanged; docs/demProperties.md)" << nl
            << exit(FatalIOError);
    }

    // Summary
    const fileName summaryDir
    (
        casePath()/"postProcessing"/"demFoam"/runTime_.timeName()
    );
    mkDir(summaryDir);
    balance_.openLog(summaryDir);
    summary_.reset(new OFstream(summaryDir/"summary.dat"));
    summary_().precision(10);
    summary_()
        << "# demFoam summary: energies [J]; maxOverlapRatio = largest "
        << "overlap/radius" << nl
        << "# time step particles contacts wallContacts particlesInContact "
        << "kineticEnergy translationalEnergy rotationalEnergy "
        << "gravitationalEnergy maxOverlapRatio" << endl;

    wallStart_ = clock_.elapsedTime();
    lastReportWall_ = wallStart_;
    lastReportStep_ = system_->engine().step();
    startStep_ = lastReportStep_;
    lastEvolveTime_ = runTime_.value();
    sample();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::demSimulation::evolve()
{
    insertDue();

    // The wall loads of this time step only
    wallLoadMean_.assign(wallMap_.size(), polydem::WallLoad());
    wallLoadSteps_ = 0;
    energyFlowSum_ = polydem::EnergyFlows();

    // DEM steps for this fluid step: stepsPerDeltaT_ with a fixed deltaT
    // (checked at the start); a solver that adjusts deltaT
    // (demBackend::compatibleDeltaT) keeps it a whole number of them
    // while there are particles, and with none the DEM follows the
    // OpenFOAM time to within half a step
    const scalar dt = input_.config().timeStep;
    const scalar increment = (runTime_.value() - lastEvolveTime_)/dt;
    lastEvolveTime_ = runTime_.value();
    int64_t nSteps = stepsPerDeltaT_;
    if (mag(increment - stepsPerDeltaT_) > 1e-6*stepsPerDeltaT_)
    {
        if
        (
            mag(increment - std::llround(increment)) > 1e-6
         && system_->engine().statistics().particles > 0
        )
        {
            FatalErrorInFunction
                << "The fluid time step to t = " << runTime_.value()
                << " s is " << increment << " DEM steps (timeStep " << dt
                << " s), not a whole number" << nl
                << "    deltaT was changed during the run (controlDict"
                << " edited, or a solver without DEM-aware time-step"
                << " control); keep it a multiple of timeStep"
                << exit(FatalError);
        }
        const scalar steps = increment + stepCarry_;
        nSteps = std::llround(steps);
        stepCarry_ = steps - nSteps;
    }
    if (nSteps < 0)
    {
        FatalErrorInFunction
            << "The OpenFOAM time " << runTime_.value() << " s went back"
            << " behind the DEM time " << system_->engine().time() << " s"
            << exit(FatalError);
    }
    const int64_t target = system_->engine().step() + nSteps;
    while (system_->engine().step() < target)
    {
        const int64_t step = system_->engine().step();
        int64_t next = target;
        for (size_t k = 0; k < wallActive_.size(); ++k)
        {
            if (wallActive_[k] && wallRemovalStep_[k] > step)
            {
                next = std::min(next, wallRemovalStep_[k]);
            }
        }
        system_->advance(next - step);
        collectRemoved();
        collectWallLoads();
        collectEnergyFlows();
        removeDueWalls();
    }
    report();
}


void Foam::demSimulation::sample()
{
    const polydem::Engine& engine = system_->engine();
    const polydem::Statistics s = engine.statistics();
    const polydem::Energies e = engine.energies(false);  // elastic part not written
    summary_()
        << engine.time() << ' ' << engine.step() << ' '
        << label(s.particles) << ' ' << label(s.contacts) << ' '
        << label(s.wallContacts) << ' ' << label(s.particlesInContact) << ' '
        << e.kinetic() << ' ' << e.translational << ' ' << e.rotational << ' '
        << e.gravitational << ' ' << s.maxOverlapRatio << endl;
    balance_.check(int64_t(s.particles), "at t = " + std::to_string(engine.time()));
    balance_.sample(engine.time(), engine.step(), int64_t(s.particles));
    checkOverlap(s);
}


void Foam::demSimulation::checkOverlap(const polydem::Statistics& s) const
{
    // Overlaps of sphere laws are a few per cent of the radius at most; one
    // of a third of the radius means particles are passing through each
    // other (time step or stiffness): name the pair (the host search runs
    // only then). The overlap-volume law reports no ratio: see write()
    const double limit = 1.0/3.0;
    if (!(s.maxOverlapRatio > limit) && std::isfinite(s.maxOverlapRatio))
    {
        return;
    }
    std::ostringstream what;
    what << "DEM overlap of " << s.maxOverlapRatio << " of a radius (more"
         << " than " << limit << ")";
    reportDeepestOverlap(what.str(), false);
}


void Foam::demSimulation::checkPolyhedronOverlap() const
{
    // The overlap-volume law: the exact overlaps of all pairs in contact,
    // once per write (the cost of one narrow phase on the host)
    const double limit = 0.1;
    const polydem::ParticleState p = system_->engine().particles();
    const std::vector<polydem::InsertionOverlap> found =
        polydem::insertionOverlaps
        (
            system_->config(), p, polydem::ParticleState(), false
        );
    for (const auto& o : found)
    {
        if (o.byVolume && o.measure > limit)
        {
            std::ostringstream what;
            what << "DEM overlap volume of more than " << 100*limit
                 << " % of a particle";
            reportDeepestOverlap(what.str(), true);
        }
    }
}


void Foam::demSimulation::reportDeepestOverlap
(
    const std::string& what,
    const bool byVolume
) const
{
    const polydem::ParticleState p = system_->engine().particles();
    const std::vector<polydem::InsertionOverlap> found =
        polydem::insertionOverlaps
        (
            system_->config(), p, polydem::ParticleState(), false
        );
    const polydem::InsertionOverlap* worst = nullptr;
    for (const auto& o : found)
    {
        if (!worst || o.measure > worst->measure)
        {
            worst = &o;
        }
    }
    FatalErrorInFunction
        << what.c_str() << " at t = " << system_->engine().time()
        << " s: particles are passing through each other" << nl;
    if (worst)
    {
        const size_t i = worst->particle;
        FatalError
            << "    particle " << label(p.id[i]) << " (type "
            << input_.config().types[p.type[i]].name.c_str() << ") at ("
            << p.position[i].x << ' ' << p.position[i].y << ' '
            << p.position[i].z << "), velocity (" << p.velocity[i].x << ' '
            << p.velocity[i].y << ' ' << p.velocity[i].z << ")";
        if (worst->partner == polydem::InsertionOverlap::Partner::wall)
        {
            FatalError<< " and wall '" << worst->wall.c_str() << "'";
        }
        else
        {
            const size_t j = worst->otherIndex;
            FatalError
                << " and particle " << label(p.id[j]) << " at ("
                << p.position[j].x << ' ' << p.position[j].y << ' '
                << p.position[j].z << "), velocity (" << p.velocity[j].x
                << ' ' << p.velocity[j].y << ' ' << p.velocity[j].z << ")";
        }
        if (byVolume || worst->byVolume)
        {
            FatalError<< ": overlap volume " << 100*worst->measure
                << " % of the smaller particle" << nl;
        }
        else
        {
            FatalError<< ": depth " << 2*worst->measure << " of the smaller"
                << " radius" << nl;
        }
    }
    FatalError
        << "    usual causes: a time step too large for the stiffness"
        << " (entry 'timeStep' of " << input_.dict().name() << "), a soft"
        << " material under a large load, or particles inserted overlapping"
        << exit(FatalError);
}


void Foam::demSimulation::write()
{
    if (runTime_.writeTime())
    {
        if (input_.config().contact.law == polydem::ContactLaw::overlapVolume)
        {
            checkPolyhedronOverlap();
        }
        writeState();
    }
}


void Foam::demSimulation::report(bool force)
{
    const scalar now = clock_.elapsedTime();
    if (!force && now - lastReportWall_ < input_.reportInterval())
    {
        return;
    }
    const polydem::Engine& engine = system_->engine();
    const polydem::Statistics s = engine.statistics();
    const polydem::Energies e = engine.energies(false);  // elastic part not written
    // Rates since the last report, or over the whole run for the last line
    const int64_t steps =
        engine.step() - (force ? startStep_ : lastReportStep_);
    const scalar span = max(now - (force ? wallStart_ : lastReportWall_), 1e-9);
    const scalar stepRate = steps/span;

    const scalar done = runTime_.value() - startTimeValue_;
    const scalar left = runTime_.endTime().value() - runTime_.value();
    const scalar eta = done > 0 ? left/done*(now - wallStart_) : -1;

    // One line of "name value" pairs: foamLog (docs/demProperties.md,
    // "Log") and grep pick each quantity by its name
    Info<< "DEM t = " << engine.time()
        << " step " << label(engine.step())
        << " particles " << label(s.particles)
        << " inContact " << label(s.particlesInContact)
        << " contacts " << label(s.contacts)
        << " wallContacts " << label(s.wallContacts)
        << " kineticEnergy " << e.kinetic()
        << " stepsPerSecond " << label(std::lround(stepRate))
        << " particleStepsPerSecond " << stepRate*s.particles
        << " wallTime " << hms(now - wallStart_).c_str()
        << " left " << hms(eta).c_str() << endl;

    lastReportWall_ = now;
    lastReportStep_ = engine.step();
}


// ************************************************************************* //


// * * * * * * * * * * * * * *  demParticleSource  * * * * * * * * * * * * * //

const polydem::ParticleState& Foam::demSimulation::particleState() const
{
    const polydem::Engine& engine = system_->engine();
    if (stateCacheStep_ != engine.step())
    {
        stateCache_ = engine.particles();
        stateCacheStep_ = engine.step();
    }
    return stateCache_;
}


const polydem::SimulationConfig& Foam::demSimulation::particleConfig() const
{
    return input_.config();
}


Foam::scalar Foam::demSimulation::particleTime() const
{
    return system_->engine().time();
}


// ************************************************************************* //

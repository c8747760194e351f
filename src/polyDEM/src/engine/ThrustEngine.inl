// polyDEM: the DEM engine, written once on Thrust and compiled twice:
// by nvcc for the CUDA back end (BackendCuda.cu) and by g++ with Thrust's
// OpenMP device system for the CPU back end (BackendCpu.cpp).
//
// Per step (velocity Verlet):
//   half kick (v, L) -> drift (x, q) -> [rebuild neighbour lists if some particle
//   moved more than half the skin] -> forces -> half kick.
// Contacts live in compact half neighbour lists (CSR, one entry per pair, the
// particle of smaller index in the cell-sorted order is body 1); each pair is
// evaluated once. Forces are gathered per particle without atomics in a fixed
// order (its pairs as body 1, then as body 2, then its walls), so the result
// does not depend on the thread count or schedule, and both back ends sum alike.
// Kernels are compiled per contact law and per particle kind (spheres only, or
// polyhedra among them): see dispatch().
//
// Sections: DeviceViews.hpp (state views), Integration.hpp, BroadPhase.hpp
// (grid, lists, history carried over rebuilds), ShapePairs.hpp (the shape-pair
// dispatch), PairKernels.hpp, WallKernels.hpp, Diagnostics.hpp.
//
// The including file defines PD_BACKEND_NAME ("cpu"/"cuda") and
// PD_BACKEND_NS (a namespace private to the back end).


#include "polyDEM/ContactLaws.hpp"
#include "polyDEM/Engine.hpp"
#include "polyDEM/Error.hpp"
#include "polyDEM/WallDepths.hpp"
#include "polyDEM/WallSidePlanes.hpp"
#include "polyDEM/PolyhedronOverlap.hpp"
#include "polyDEM/RestitutionCalibration.hpp"

#include "DeviceViews.hpp"
#include "Integration.hpp"
#include "BroadPhase.hpp"
#include "ShapePairs.hpp"
#include "PairKernels.hpp"
#include "WallKernels.hpp"
#include "Diagnostics.hpp"

#include <limits>
#include <sstream>
#include <cmath>

#include <thrust/copy.h>
#include <thrust/device_vector.h>
#include <thrust/execution_policy.h>
#include <thrust/fill.h>
#include <thrust/functional.h>
#include <thrust/transform.h>
#include <thrust/for_each.h>
#include <thrust/gather.h>
#include <thrust/host_vector.h>
#include <thrust/iterator/counting_iterator.h>
#include <thrust/reduce.h>
#include <thrust/sequence.h>
#include <thrust/sort.h>
#include <thrust/transform_reduce.h>
#include <thrust/binary_search.h>
#include <thrust/scan.h>
#include <thrust/iterator/transform_iterator.h>
#include <thrust/iterator/zip_iterator.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <type_traits>

#ifndef __CUDACC__
#include <omp.h>
#endif
#include <vector>

namespace polydem
{
namespace PD_BACKEND_NS
{

using detail::RigidMotion;
using std::int64_t;
// ---------------------------------------------------------------------------
// The engine
// ---------------------------------------------------------------------------

class ThrustEngine : public Engine
{
public:
    std::string name() const override { return PD_BACKEND_NAME; }

    void initialise(const SimulationConfig& config, const Snapshot& s) override
    {
        config_ = config;
        time_ = s.time;
        step_ = s.step;
        setupLaw();
        setupPlanes();
        setupWallLoadPoints();
        setupOutlets();
        uploadParticles(s.particles);
        if (s.referencePosition.size() == s.particles.size())
        {
            toDevice(ref_, s.referencePosition);
        }
        else
        {
            ref_ = pos_;
        }
        setupMeshes();
        const size_t np = s.particles.size();
        toDevice(extForce_, s.externalForce.size() == np ? s.externalForce : std::vector<Vec3>());
        toDevice(extTorque_, s.externalTorque.size() == np ? s.externalTorque : std::vector<Vec3>());
        rebuild(false);
        restoreHistory(s);
        if (!s.forcesValid)
        {
            computeForces();
        }
    }

    void advance(int64_t nSteps) override
    {
        dispatch([&](auto law, auto kind) { this->advanceWith<decltype(law), decltype(kind)>(nSteps); });
    }

    Snapshot snapshot() const override
    {
        Snapshot s;
        s.time = time_;
        s.step = step_;
        s.particles = particles();
        s.referencePosition = toHost(ref_);
        s.forcesValid = true;
        s.externalForce = toHost(extForce_);
        s.externalTorque = toHost(extTorque_);

        const int n = int(id_.size());
        const auto start = toHost(pairStart_);
        const auto partner = toHost(pairPartner_);
        const auto xi = toHost(pairXi_);
        const auto mr = toHost(pairMr_);
        const auto touching = toHost(pairTouching_);
        const auto axis = toHost(pairAxis_);
        const bool rolling = !mr.empty();
        const auto& ids = s.particles.id;
        for (int i = 0; i < n; ++i)
        {
            for (int k = start[i]; k < start[i + 1]; ++k)
            {
                const int j = partner[k];
                const Vec3 m = rolling ? mr[k] : Vec3();
                // A touching polyhedron pair keeps its contact normal even
                // without a spring (frictionless): the next overlap uses it
                const Vec3 nrm = touching[k] && !axis.empty() ? axis[k] : Vec3();
                if (normSqr(xi[k]) > 0 || normSqr(m) > 0 || normSqr(nrm) > 0)
                {
                    // Stored as seen from the particle of smaller id
                    if (ids[i] < ids[j]) s.pairs.push_back({ids[i], ids[j], xi[k], m, nrm});
                    else s.pairs.push_back({ids[j], ids[i], -xi[k], -m, -nrm});
                }
            }
        }
        const int nPl = int(config_.planes.size());
        if (nPl > 0)
        {
            const auto cs = toHost(planeStart_);
            const auto cp = toHost(planePlane_);
            const auto pxi = toHost(planeXi_);
            const auto pmr = toHost(planeMr_);
            for (int i = 0; i < n; ++i)
                for (int c = cs[i]; c < cs[i + 1]; ++c)
                {
                    const Vec3 m = pmr.empty() ? Vec3() : pmr[c];
                    if (normSqr(pxi[c]) > 0 || normSqr(m) > 0)
                    {
                        s.walls.push_back({ids[i], cp[c], -1, Vec3(), pxi[c], m});
                    }
                }
        }
        if (!config_.meshes.empty())
        {
            const auto slots = toHost(meshSlots_);
            for (int i = 0; i < n; ++i)
                for (int k = 0; k < maxMeshSlots; ++k)
                {
                    const MeshSlot& ms = slots[size_t(i) * maxMeshSlots + k];
                    if (ms.mesh >= 0)
                    {
                        s.walls.push_back({ids[i], nPl + ms.mesh, ms.triangle, ms.normal, ms.xi, ms.mr});
                    }
                }
        }
        return s;
    }

    ParticleState particles() const override
    {
        ParticleState p;
        p.id = toHost(id_);
        p.type = toHost(type_);
        p.radius = toHost(radius_);
        p.mass = toHost(mass_);
        p.inertia = toHost(inertia_);
        p.position = toHost(pos_);
        p.orientation = toHost(q_);
        p.velocity = toHost(vel_);
        p.omega = toHost(omega_);
        p.force = toHost(force_);
        p.torque = toHost(torque_);
        return p;
    }

    void addParticles(const ParticleState& added) override
    {
        ParticleState all = particles();
        std::vector<Vec3> ref = toHost(ref_);
        for (std::size_t i = 0; i < added.size(); ++i)
        {
            all.id.push_back(added.id[i]);
            all.type.push_back(added.type[i]);
            all.radius.push_back(added.radius[i]);
            all.mass.push_back(added.mass[i]);
            all.inertia.push_back(added.inertia[i]);
            all.position.push_back(added.position[i]);
            all.orientation.push_back(added.orientation[i]);
            all.velocity.push_back(added.velocity[i]);
            all.omega.push_back(added.omega[i]);
            all.force.push_back(Vec3());
            all.torque.push_back(Vec3());
            ref.push_back(added.position[i]);
        }
        // External (fluid) forces of the particles present stay (a coupled
        // run's inflow inserts between two coupling steps); the new ones
        // have none until the next coupling step sets them
        std::vector<Vec3> extF = toHost(extForce_), extT = toHost(extTorque_);
        if (!extF.empty()) extF.resize(all.size(), Vec3());
        if (!extT.empty()) extT.resize(all.size(), Vec3());
        // History of the existing particles survives: rebuild() matches it by id
        uploadParticles(all, false);
        toDevice(ref_, ref);
        toDevice(extForce_, extF);
        toDevice(extTorque_, extT);
        setupMeshes();
        rebuild(true);
        computeForces();
    }

    void setExternalForces(const std::vector<Vec3>& force, const std::vector<Vec3>& torque) override
    {
        const size_t n = id_.size();
        if ((!force.empty() && force.size() != n) || (!torque.empty() && torque.size() != n))
        {
            throw Error("external forces given for " + std::to_string(force.size())
                        + " particles, the engine holds " + std::to_string(n));
        }
        // The stored force and torque feed the next half kick: swap the old
        // external part for the new one there too, so that a force set between
        // steps acts from the very next step (not half a step late)
        dvec<Vec3> newForce, newTorque;
        toDevice(newForce, force);
        toDevice(newTorque, torque);
        const auto first = thrust::counting_iterator<int>(0);
        thrust::for_each(thrust::device, first, first + int(n),
                         ReplaceExternal{ptr(force_), extForce_.empty() ? nullptr : ptr(extForce_),
                                         newForce.empty() ? nullptr : ptr(newForce)});
        thrust::for_each(thrust::device, first, first + int(n),
                         ReplaceExternal{ptr(torque_), extTorque_.empty() ? nullptr : ptr(extTorque_),
                                         newTorque.empty() ? nullptr : ptr(newTorque)});
        extForce_.swap(newForce);
        extTorque_.swap(newTorque);
    }

    Energies energies(bool includeElastic = true) const override
    {
        const int n = int(id_.size());
        const auto first = thrust::counting_iterator<int>(0);
        ThrustEngine& self = const_cast<ThrustEngine&>(*this);
        Energies e = thrust::transform_reduce(thrust::device, first, first + n,
                                              KineticEnergy{self.view(), config_.gravity}, Energies(), AddEnergies());
        e.elastic = includeElastic ? elasticEnergy() : 0.0;
        return e;
    }

    Statistics statistics() const override
    {
        Statistics s;
        s.particles = id_.size();
        const auto cc = toHost(contactCount_);
        const auto wc = toHost(wallContactCount_);
        size_t sum = 0, inContact = 0, walls = 0;
        for (size_t i = 0; i < cc.size(); ++i)
        {
            sum += cc[i];
            walls += wc[i];
            if (cc[i] + wc[i] > 0) ++inContact;
        }
        s.contacts = sum / 2;
        const int n = int(id_.size());
        if (n > 0 && law_.law != ContactLaw::overlapVolume)
        {
            ThrustEngine& self = const_cast<ThrustEngine&>(*this);
            const auto first = thrust::counting_iterator<int>(0);
            s.maxOverlapRatio = thrust::transform_reduce(
                thrust::device, first, first + n,
                MaxOverlapRatio{self.view(), ptr(pairStart_), ptr(pairPartner_), ptr(pairTouching_)},
                0.0, thrust::maximum<double>());
        }
        s.wallContacts = walls;
        s.particlesInContact = inContact;
        s.neighbourListBuilds = builds_;
        return s;
    }

    void enableWallLoads(bool on) override
    {
        if (on == wallLoadsOn_) return;
        wallLoadsOn_ = on;
        const int nWalls = int(config_.planes.size() + config_.meshes.size());
        wallShare_.clear();
        wallLoadCurrent_.assign(on ? nWalls : 0, WallShare());
        wallLoadSum_.assign(on ? nWalls : 0, WallShare());
        wallLoadSteps_ = 0;
    }

    bool wallLoadsEnabled() const override { return wallLoadsOn_; }

    std::vector<WallLoad> wallLoads() const override
    {
        return loadsOf(toHost(wallLoadCurrent_));
    }

    WallLoadSum wallLoadSum() const override
    {
        WallLoadSum s;
        s.sum = loadsOf(toHost(wallLoadSum_));
        s.steps = wallLoadSteps_;
        return s;
    }

    void resetWallLoadSum() override
    {
        thrust::fill(thrust::device, wallLoadSum_.begin(), wallLoadSum_.end(), WallShare());
        wallLoadSteps_ = 0;
    }

    void enableEnergyFlows(bool on) override
    {
        if (on == energyOn_) return;
        energyOn_ = on;
        law_.accountEnergy = on;
        energyFlow_.clear();
        pairDissipation_.clear();
        ownDissipation_.clear();
        energySum_.assign(on ? 1 : 0, EnergyFlow());
        energySteps_ = 0;
    }

    bool energyFlowsEnabled() const override { return energyOn_; }

    EnergyFlows energyFlows() const override
    {
        EnergyFlows e;
        if (!energyOn_) return e;
        const EnergyFlow s = toHost(energySum_)[0];
        e.pairDissipation = s.pairDissipation;
        e.wallDissipation = s.wallDissipation;
        e.wallWork = s.wallWork;
        e.externalWork = s.externalWork;
        e.steps = energySteps_;
        return e;
    }

    void resetEnergyFlows() override
    {
        thrust::fill(thrust::device, energySum_.begin(), energySum_.end(), EnergyFlow());
        energySteps_ = 0;
    }

    std::vector<RemovedParticle> takeRemoved() override
    {
        std::vector<RemovedParticle> out;
        out.swap(removed_);
        return out;
    }

    double time() const override { return time_; }
    int64_t step() const override { return step_; }

private:
    //- The outlet boxes on the device
    void setupOutlets()
    {
        std::vector<Vec3> lo, hi;
        for (const auto& o : config_.outlets)
        {
            lo.push_back(o.min);
            hi.push_back(o.max);
        }
        toDevice(outletLo_, lo);
        toDevice(outletHi_, hi);
        std::vector<Vec3> alo, ahi, av;
        for (const auto& a : config_.approaches)
        {
            alo.push_back(a.min);
            ahi.push_back(a.max);
            av.push_back(a.velocity);
        }
        toDevice(approachLo_, alo);
        toDevice(approachHi_, ahi);
        toDevice(approachVel_, av);
    }

    //- Record the nRemoved particles that inside rejects (before the
    //  permutation drops them), with the region that removed each: the
    //  first outlet holding it, else the domain (-1)
    void logRemoved(const InsideDomain& inside, int nRemoved)
    {
        const int oldN = int(id_.size());
        const auto first = thrust::counting_iterator<int>(0);
        dvec<int> gone(nRemoved);
        thrust::copy_if(thrust::device, first, first + oldN, gone.begin(), OutsideDomain{inside});
        const std::vector<int> idx = toHost(gone);
        const std::vector<int64_t> id = toHost(id_);
        const std::vector<int> type = toHost(type_);
        const std::vector<double> mass = toHost(mass_);
        const std::vector<Vec3> pos = toHost(pos_);
        const std::vector<Vec3> ref = toHost(ref_);
        const std::vector<Vec3> vel = toHost(vel_);
        for (int i : idx)
        {
            RemovedParticle r;
            r.id = id[i];
            r.type = type[i];
            r.mass = mass[i];
            r.position = pos[i];
            r.velocity = vel[i];
            r.time = time_;
            const bool inDomain = InsideDomain::inBox(ref[i], config_.domainMin, config_.domainMax);
            r.region = -1;
            for (size_t k = 0; inDomain && k < config_.outlets.size(); ++k)
            {
                if (InsideDomain::inBox(ref[i], config_.outlets[k].min, config_.outlets[k].max))
                {
                    r.region = int(k);
                    break;
                }
            }
            removed_.push_back(r);
        }
    }

    // Time is step * dt relative to the step/time the run started from, so a
    // restart reproduces the same wall positions to the bit.
    double timeOffset() const { return time0_ - double(step0_) * config_.timeStep; }

    ParticleView view()
    {
        return ParticleView{int(id_.size()), ptr(id_), ptr(type_), ptr(radius_), ptr(mass_), ptr(inertia_),
                            ptr(pos_), ptr(q_), ptr(vel_), ptr(omega_), ptr(force_), ptr(torque_),
                            extForce_.empty() ? nullptr : ptr(extForce_),
                            extTorque_.empty() ? nullptr : ptr(extTorque_),
                            approachLo_.empty() ? nullptr : ptr(approachLo_),
                            approachHi_.empty() ? nullptr : ptr(approachHi_),
                            approachVel_.empty() ? nullptr : ptr(approachVel_),
                            int(approachLo_.size())};
    }

    LawView lawView() const
    {
        return LawView{law_, ptr(pairCoeffs_), int(config_.materials.size()), ptr(typeMaterial_),
                       ptr(typeShape_), shapeTable_};
    }

    //- The one run-time switch over contact law and particle kind: f(Law{}, Kind{})
    template<class F>
    void dispatch(F&& f)
    {
        if (law_.law == ContactLaw::overlapVolume)
        {
            if (anyPolyhedra_) f(OverlapVolume{}, MixedKind{});
            else f(OverlapVolume{}, SphereKind{});
        }
        else if (law_.law == ContactLaw::linearSpringDashpot)
        {
            f(LinearSpringDashpot{}, SphereKind{});
        }
        else
        {
            f(HertzMindlin{}, SphereKind{});
        }
    }

    template<class Law, class Kind>
    void advanceWith(int64_t nSteps)
    {
        const double dt = config_.timeStep;
        const auto first = thrust::counting_iterator<int>(0);
        for (int64_t k = 0; k < nSteps; ++k)
        {
            const int n = int(id_.size());
            const double maxSqr = n == 0 ? 0.0 : thrust::transform_reduce(
                thrust::device, first, first + n, KickDrift<Kind>{view(), ptr(typeShape_), ptr(ref_), dt},
                0.0, thrust::maximum<double>());
            ++step_;
            time_ = double(step_) * dt + timeOffset();
            const double half = 0.5 * skin();
            if (maxSqr > half * half)
            {
                // Every particle was within half the skin of its reference
                // before this step: one now beyond the whole skin moved more
                // than half of it in one step, and contacts may have been
                // missed (or it has blown up: guardedDisplacementSqr)
                if (maxSqr > skin() * skin())
                {
                    reportBlowUp(dt);
                }
                rebuild(true);
            }
            // Forces and the second half kick in the same pass
            forcesWith<Law, Kind, true>();
            reduceWallLoads(true);
            reduceEnergyFlows();
        }
    }

    //- Stop the run on the worst particle of a step that tripped the guard:
    //  its id, type, position, velocity, angular velocity, the distance it
    //  moved against the skin, its nearest plane wall, and what usually causes
    //  it. Runs only on failure, so it may copy the state to the host.
    [[noreturn]] void reportBlowUp(double dt) const
    {
        const auto id = toHost(id_);
        const auto type = toHost(type_);
        const auto radius = toHost(radius_);
        const auto pos = toHost(pos_);
        const auto vel = toHost(vel_);
        const auto omega = toHost(omega_);
        const auto ref = toHost(ref_);
        int worst = -1;
        double worstValue = -1;
        for (size_t i = 0; i < id.size(); ++i)
        {
            const double v = guardedDisplacementSqr(pos[i] - ref[i], omega[i], dt);
            if (v > worstValue)
            {
                worstValue = v;
                worst = int(i);
            }
        }
        std::ostringstream msg;
        msg.precision(6);
        auto vec = [&](const Vec3& a) { msg << '(' << a.x << ' ' << a.y << ' ' << a.z << ')'; };
        msg << "the run has become unstable at t = " << time_ << " s (step " << step_ << "): particle id "
            << id[worst] << " (type '" << config_.types[type[worst]].name << "', radius " << radius[worst]
            << " m) at ";
        vec(pos[worst]);
        msg << " m, velocity ";
        vec(vel[worst]);
        msg << " m/s, angular velocity ";
        vec(omega[worst]);
        msg << " rad/s";
        if (worstValue == HUGE_VAL)
        {
            msg << ": its position or angular velocity is not finite or beyond any domain, or it turns more than"
                << " 1 rad in one step (dt = " << dt << " s)";
        }
        else
        {
            msg << ": it moved " << std::sqrt(worstValue) << " m since the last neighbour search, more than the"
                << " neighbour skin " << skin() << " m, i.e. more than half the skin in one step (dt = " << dt
                << " s), so contacts may have been missed";
        }
        // The nearest plane wall (the usual partner of a particle driven hard)
        double nearest = HUGE_VAL;
        std::string wallName;
        for (const auto& w : config_.planes)
        {
            const double d = dot(pos[worst] - w.point, w.normal);
            if (std::isfinite(d) && std::abs(d) < std::abs(nearest))
            {
                nearest = d;
                wallName = w.name;
            }
        }
        if (!wallName.empty())
        {
            msg << "; nearest plane wall '" << wallName << "' at signed distance " << nearest << " m"
                << (nearest < 0 ? " (behind it)" : "");
        }
        msg << ". Usual causes: a time step too large for the contact stiffness (lower timeStep, or the"
               " Young's modulus), particles inserted overlapping each other or a wall, an initial velocity or"
               " an external (fluid) force far too large";
        throw Error(msg.str());
    }

    void setupLaw()
    {
        time0_ = time_;
        step0_ = step_;
        law_ = lawParameters(config_.contact, config_.timeStep);
        law_.accountEnergy = energyOn_;

        const int nm = int(config_.materials.size());
        std::vector<PairCoefficients> pc(nm * nm);
        std::map<double, double> dampingOf;
        for (int a = 0; a < nm; ++a)
        {
            for (int b = 0; b < nm; ++b)
            {
                const PairProperties& pp = config_.pair(a, b);
                auto it = dampingOf.find(pp.restitution);
                if (it == dampingOf.end())
                {
                    it = dampingOf.emplace(pp.restitution, dampingForRestitution(config_.contact.law, pp.restitution)).first;
                }
                PairCoefficients& c = pc[a * nm + b];
                c = withContactLaw(law_.law, [&](auto L) {
                    return decltype(L)::coefficients(config_.materials[a], config_.materials[b], law_, it->second);
                });
                c.friction = pp.friction;
                c.rollingFriction = pp.rollingFriction;
                c.rollingDamping = pp.rollingDamping;
                c.twistingFriction = pp.twistingFriction;
            }
        }
        toDevice(pairCoeffs_, pc);
        std::vector<int> tm, ts;
        for (const auto& t : config_.types)
        {
            tm.push_back(t.material);
            ts.push_back(t.shape == ShapeKind::polyhedron ? t.shapeIndex : -1);
        }
        toDevice(typeMaterial_, tm);
        toDevice(typeShape_, ts);
        anyPolyhedra_ = std::any_of(ts.begin(), ts.end(), [](int t) { return t >= 0; });
        uploadShapes();
    }

    //- The convex shapes live on the device once; particles only index them
    void uploadShapes()
    {
        const PackedPolyhedra packed = packPolyhedra(config_.shapes);
        toDevice(shapeVertexBegin_, packed.vertexBegin);
        toDevice(shapeFaceBegin_, packed.faceBegin);
        toDevice(shapeFaceStartBegin_, packed.faceStartBegin);
        toDevice(shapeFaceVertexBegin_, packed.faceVertexBegin);
        toDevice(shapeEdgeBegin_, packed.edgeBegin);
        toDevice(shapeBoundingRadius_, packed.boundingRadius);
        toDevice(shapeVolume_, packed.volume);
        toDevice(shapeInertia_, packed.inertiaPerDensity);
        toDevice(shapeVertices_, packed.vertices);
        toDevice(shapeFaceNormals_, packed.faceNormals);
        toDevice(shapeFaceOffsets_, packed.faceOffsets);
        toDevice(shapeFaceStart_, packed.faceStart);
        toDevice(shapeFaceVertex_, packed.faceVertex);
        toDevice(shapeEdges_, packed.edges);
        PolyhedronTable& t = shapeTable_;
        t.nShapes = packed.nShapes();
        auto p0 = [](auto& v) { return v.empty() ? nullptr : ptr(v); };
        t.vertexBegin = p0(shapeVertexBegin_);
        t.faceBegin = p0(shapeFaceBegin_);
        t.faceStartBegin = p0(shapeFaceStartBegin_);
        t.faceVertexBegin = p0(shapeFaceVertexBegin_);
        t.edgeBegin = p0(shapeEdgeBegin_);
        t.boundingRadius = p0(shapeBoundingRadius_);
        t.volume = p0(shapeVolume_);
        t.inertiaPerDensity = p0(shapeInertia_);
        t.vertices = p0(shapeVertices_);
        t.faceNormals = p0(shapeFaceNormals_);
        t.faceOffsets = p0(shapeFaceOffsets_);
        t.faceStart = p0(shapeFaceStart_);
        t.faceVertex = p0(shapeFaceVertex_);
        t.edges = p0(shapeEdges_);
    }

    static RigidMotion motionOf(const WallMotion& m)
    {
        RigidMotion r;
        r.kind = int(m.kind);
        r.velocity = m.velocity;
        r.origin = m.origin;
        r.axis = m.axis;
        r.omega = m.omega;
        return r;
    }

    void setupPlanes()
    {
        std::vector<PlaneDevice> pl;
        for (const auto& w : config_.planes)
        {
            pl.push_back(PlaneDevice{w.point, w.normal, w.material, motionOf(w.motion)});
        }
        toDevice(planes_, pl);
    }

    //- Bin every mesh's triangles (body frame) into a uniform grid whose cells
    //  list all triangles within the largest particle radius of the cell
    void setupMeshes()
    {
        if (config_.meshes.empty()) return;
        const auto radius = toHost(radius_);
        double rMax = 0;
        for (double r : radius) rMax = std::max(rMax, r);
        if (rMax <= 0) rMax = 1e-3;
        if (rMax <= meshBinnedRadius_) return;
        meshBinnedRadius_ = rMax * 1.25;  // room for later, larger inserts
        const double reach = meshBinnedRadius_;

        std::vector<MeshDevice> md;
        std::vector<Vec3> A, B, C;
        std::vector<double> depth;
        std::vector<int> sideStart{0};   // per triangle, its side planes (CSR)
        std::vector<Vec3> sideNormal;
        std::vector<double> sideOffset;
        std::vector<int> cellStart, cellTri;
        for (const auto& w : config_.meshes)
        {
            const TriangleMesh& mesh = w.mesh;
            // Floors no deeper than four particle reaches (WallDepths.hpp);
            // only polyhedra use them
            const bool polyhedra = std::any_of(config_.types.begin(), config_.types.end(),
                                               [](const ParticleType& t) { return t.shape == ShapeKind::polyhedron; });
            const std::vector<double> wd =
                w.wallDepth.size() == mesh.size() ? w.wallDepth
                : polyhedra ? wallDepths(mesh, 4 * reach)
                : std::vector<double>(mesh.size(), kUnboundedWallDepth);
            depth.insert(depth.end(), wd.begin(), wd.end());
            if (polyhedra)
            {
                const WallSidePlanes sp = wallSidePlanes(mesh);
                const int base = int(sideNormal.size());
                for (std::size_t t = 1; t < sp.start.size(); ++t) sideStart.push_back(base + sp.start[t]);
                sideNormal.insert(sideNormal.end(), sp.normal.begin(), sp.normal.end());
                sideOffset.insert(sideOffset.end(), sp.offset.begin(), sp.offset.end());
            }
            else
            {
                sideStart.resize(sideStart.size() + mesh.size(), int(sideNormal.size()));   // spheres: none
            }
            Vec3 lo(1e300, 1e300, 1e300), hi(-1e300, -1e300, -1e300);
            for (const auto& p : mesh.points)
            {
                for (int d = 0; d < 3; ++d)
                {
                    lo[d] = std::min(lo[d], p[d]);
                    hi[d] = std::max(hi[d], p[d]);
                }
            }
            for (int d = 0; d < 3; ++d)
            {
                lo[d] -= 2 * reach;
                hi[d] += 2 * reach;
            }
            const Vec3 ext = hi - lo;
            // Cells about a particle diameter, at most ~4M cells
            double h = 2 * reach;
            const double vol = ext.x * ext.y * ext.z;
            h = std::max(h, std::cbrt(vol / 4.0e6));
            MeshDevice m;
            m.material = w.material;
            m.motion = motionOf(w.motion);
            m.firstTriangle = int(A.size());
            m.gridOrigin = lo;
            m.cellSize = h;
            m.nx = std::max(1, int(std::ceil(ext.x / h)));
            m.ny = std::max(1, int(std::ceil(ext.y / h)));
            m.nz = std::max(1, int(std::ceil(ext.z / h)));
            m.firstCell = int(cellStart.size());

            const size_t nCells = size_t(m.nx) * m.ny * m.nz;
            std::vector<std::vector<int>> bins(nCells);
            for (size_t t = 0; t < mesh.triangles.size(); ++t)
            {
                const Vec3 a = mesh.points[mesh.triangles[t][0]];
                const Vec3 b = mesh.points[mesh.triangles[t][1]];
                const Vec3 c = mesh.points[mesh.triangles[t][2]];
                A.push_back(a);
                B.push_back(b);
                C.push_back(c);
                int i0[3], i1[3];
                for (int d = 0; d < 3; ++d)
                {
                    const double mn = std::min({a[d], b[d], c[d]}) - reach;
                    const double mx = std::max({a[d], b[d], c[d]}) + reach;
                    const int nd = d == 0 ? m.nx : (d == 1 ? m.ny : m.nz);
                    i0[d] = std::max(0, int(std::floor((mn - lo[d]) / h)));
                    i1[d] = std::min(nd - 1, int(std::floor((mx - lo[d]) / h)));
                }
                for (int z = i0[2]; z <= i1[2]; ++z)
                    for (int y = i0[1]; y <= i1[1]; ++y)
                        for (int x = i0[0]; x <= i1[0]; ++x)
                        {
                            // Only cells the triangle's reach really touches:
                            // distance from the cell centre <= reach + half diagonal
                            const Vec3 cc = lo + Vec3((x + 0.5) * h, (y + 0.5) * h, (z + 0.5) * h);
                            int f;
                            const Vec3 cp = detail::closestPointOnTriangle(cc, a, b, c, f);
                            if (norm(cp - cc) <= reach + 0.8660254037844387 * h)
                            {
                                bins[(size_t(z) * m.ny + y) * m.nx + x].push_back(int(t));
                            }
                        }
            }
            for (size_t c = 0; c < nCells; ++c)
            {
                cellStart.push_back(int(cellTri.size()));
                cellTri.insert(cellTri.end(), bins[c].begin(), bins[c].end());
            }
            cellStart.push_back(int(cellTri.size()));
            md.push_back(m);
        }
        toDevice(meshes_, md);
        toDevice(triA_, A);
        toDevice(triDepth_, depth);
        toDevice(triSideStart_, sideStart);
        toDevice(triSideNormal_, sideNormal);
        toDevice(triSideOffset_, sideOffset);
        toDevice(triB_, B);
        toDevice(triC_, C);
        toDevice(meshCellStart_, cellStart);
        toDevice(meshCellTri_, cellTri);
    }

    void uploadParticles(const ParticleState& p, bool resetWallHistory = true)
    {
        toDevice(id_, p.id);
        toDevice(type_, p.type);
        toDevice(radius_, p.radius);
        toDevice(mass_, p.mass);
        toDevice(inertia_, p.inertia);
        toDevice(pos_, p.position);
        toDevice(q_, p.orientation);
        toDevice(vel_, p.velocity);
        toDevice(omega_, p.omega);
        std::vector<Vec3> f = p.force, t = p.torque;
        f.resize(p.size());
        t.resize(p.size());
        toDevice(force_, f);
        toDevice(torque_, t);
        (void)resetWallHistory;
        double rMax = 0;
        for (double r : p.radius) rMax = std::max(rMax, r);
        rMax_ = std::max(rMax_, rMax);
    }

    double skin() const { return config_.skinFraction * 2 * rMax_; }

    template<class T>
    static void permute(dvec<T>& v, const dvec<int>& perm)
    {
        dvec<T> out(perm.size());
        thrust::gather(thrust::device, perm.begin(), perm.end(), v.begin(), out.begin());
        v.swap(out);
    }

    //- Remove particles that left the domain, sort by cell, rebuild the
    //  neighbour lists and carry the springs over. With moved = false the
    //  stored reference positions are used as they are (restart).
    void rebuild(bool moved)
    {
        ++builds_;
        const int oldN = int(id_.size());
        if (moved)
        {
            ref_ = pos_;
        }
        const auto first = thrust::counting_iterator<int>(0);

        // Keep the particles inside the domain and outside the outlets
        const InsideDomain inside{ptr(ref_), config_.domainMin, config_.domainMax,
                                  ptr(outletLo_), ptr(outletHi_), int(outletLo_.size())};
        dvec<int> perm(oldN);
        auto endIt = thrust::copy_if(thrust::device, first, first + oldN, perm.begin(), inside);
        const int n = int(endIt - perm.begin());
        perm.resize(n);
        if (n < oldN)
        {
            logRemoved(inside, oldN - n);
        }

        // Sort by cell (stable: ties keep their order, so a restart that starts
        // from a sorted state keeps it). Cells are keyed relative to the cell
        // of the kept particles' lower corner (min and max are exact, so the
        // box, and with it the order, does not depend on the thread count, and
        // a restart, which starts from the stored reference positions of the
        // same particles, finds the same box)
        Grid grid;
        grid.cellSize = 2 * rMax_ + skin();
        unsigned table = 1024;
        while (table < 2u * unsigned(std::max(n, 1))) table <<= 1;
        grid.tableMask = table - 1;
        if (n > 0)
        {
            const Vec3 r0 = ref_[int(perm[0])];
            const Box box = thrust::transform_reduce(thrust::device, perm.begin(), perm.end(),
                                                     BoxOf{ptr(ref_)}, Box{r0, r0}, MergeBoxes{});
            int64_t hx, hy, hz;
            grid.cellOf(box.lo, grid.ox, grid.oy, grid.oz);
            grid.cellOf(box.hi, hx, hy, hz);
            grid.nx = uint64_t(hx) - uint64_t(grid.ox) + 1;
            grid.ny = uint64_t(hy) - uint64_t(grid.oy) + 1;
        }
        dvec<unsigned> keys(n);
        thrust::transform(thrust::device, perm.begin(), perm.end(), keys.begin(), CellKey{grid, ptr(ref_)});
        thrust::stable_sort_by_key(thrust::device, keys.begin(), keys.end(), perm.begin());

        // Old pairs that hold a spring, keyed by id (old indices are valid in id_:
        // particles added since are appended)
        const bool rolling = law_.rolling != RollingModel::none;
        dvec<int64_t> oldLo, oldHi;
        dvec<Vec3> oldXi, oldMr, oldAxis;
        int nOld = 0;
        {
            const int nPairs = int(pairPartner_.size());
            const bool axes = nPairs > 0 && int(pairAxis_.size()) == nPairs;
            if (nPairs > 0)
            {
                dvec<int> live(nPairs);
                auto e = thrust::copy_if(thrust::device, first, first + nPairs, live.begin(),
                                         HasHistory{ptr(pairTouching_)});
                nOld = int(e - live.begin());
                live.resize(nOld);
                dvec<int> liveOwner(nOld), livePartner(nOld);
                dvec<Vec3> liveXi(nOld), liveMr(rolling ? nOld : 0), liveAxis(axes ? nOld : 0);
                thrust::gather(thrust::device, live.begin(), live.end(), pairOwner_.begin(), liveOwner.begin());
                thrust::gather(thrust::device, live.begin(), live.end(), pairPartner_.begin(), livePartner.begin());
                thrust::gather(thrust::device, live.begin(), live.end(), pairXi_.begin(), liveXi.begin());
                if (rolling) thrust::gather(thrust::device, live.begin(), live.end(), pairMr_.begin(), liveMr.begin());
                if (axes) thrust::gather(thrust::device, live.begin(), live.end(), pairAxis_.begin(), liveAxis.begin());
                oldLo.resize(nOld);
                oldHi.resize(nOld);
                oldXi.resize(nOld);
                oldMr.resize(nOld);
                oldAxis.resize(nOld);
                thrust::for_each(thrust::device, first, first + nOld,
                                 OldPairKeys{ptr(liveOwner), ptr(livePartner), ptr(id_), ptr(liveXi),
                                             rolling ? ptr(liveMr) : nullptr, axes ? ptr(liveAxis) : nullptr,
                                             ptr(oldLo), ptr(oldHi), ptr(oldXi), ptr(oldMr), ptr(oldAxis)});
                auto keys = thrust::make_zip_iterator(thrust::make_tuple(oldLo.begin(), oldHi.begin()));
                auto vals = thrust::make_zip_iterator(thrust::make_tuple(oldXi.begin(), oldMr.begin(), oldAxis.begin()));
                thrust::sort_by_key(thrust::device, keys, keys + nOld, vals);
            }
        }

        // Plane candidates (and their springs) of the old order
        const int nPl = int(config_.planes.size());
        dvec<int> oldPlaneStart, oldPlanePlane;
        dvec<Vec3> oldPlaneXi, oldPlaneMr;
        oldPlaneStart.swap(planeStart_);
        oldPlanePlane.swap(planePlane_);
        oldPlaneXi.swap(planeXi_);
        oldPlaneMr.swap(planeMr_);
        const int oldPlaneN = oldPlaneStart.empty() ? 0 : int(oldPlaneStart.size()) - 1;

        if (!config_.meshes.empty())
        {
            MeshSlot empty{};
            empty.mesh = -1;
            meshSlots_.resize(size_t(oldN) * maxMeshSlots, empty);
            dvec<MeshSlot> out(size_t(n) * maxMeshSlots);
            auto idx = thrust::make_transform_iterator(first, BlockPermutation{ptr(perm), maxMeshSlots});
            thrust::gather(thrust::device, idx, idx + n * maxMeshSlots, meshSlots_.begin(), out.begin());
            meshSlots_.swap(out);
        }

        permute(id_, perm);
        permute(type_, perm);
        permute(radius_, perm);
        permute(mass_, perm);
        permute(inertia_, perm);
        permute(pos_, perm);
        permute(q_, perm);
        permute(vel_, perm);
        permute(omega_, perm);
        permute(force_, perm);
        permute(torque_, perm);
        permute(ref_, perm);
        if (!extForce_.empty()) permute(extForce_, perm);
        if (!extTorque_.empty()) permute(extTorque_, perm);

        // Cell ranges
        dvec<int> cellStart(table, -1), cellEnd(table, -1);
        thrust::for_each(thrust::device, first, first + n,
                         MarkCellRanges{ptr(keys), n, ptr(cellStart), ptr(cellEnd)});

        // Half lists: count, scan, fill
        pairStart_.assign(n + 1, 0);
        BuildNeighbours build{grid, ptr(ref_), ptr(radius_), ptr(cellStart), ptr(cellEnd), skin(),
                              ptr(pairStart_), nullptr, nullptr, nullptr};
        thrust::for_each(thrust::device, first, first + n, build);
        const int64_t totalPairs = thrust::reduce(thrust::device, pairStart_.begin(), pairStart_.end(), int64_t(0));
        if (totalPairs > int64_t(std::numeric_limits<int>::max()))
        {
            throw Error("neighbour lists exceed 2^31 pairs: too many particles or neighbours per particle");
        }
        thrust::exclusive_scan(thrust::device, pairStart_.begin(), pairStart_.end(), pairStart_.begin());
        const int nPairs = pairStart_.back();
        pairPartner_.resize(nPairs);
        pairOwner_.resize(nPairs);
        build.start = ptr(pairStart_);
        build.out = ptr(pairPartner_);
        build.owner = ptr(pairOwner_);
        thrust::for_each(thrust::device, first, first + n, build);

        pairTouching_.resize(nPairs);
        pairXi_.resize(nPairs);
        pairMr_.resize(rolling ? nPairs : 0);
        // Polyhedra: a touching pair's contact normal goes with its springs (the
        // overlap's slab is taken along it); the separating axes of the pairs
        // apart start empty (they only decide early outs)
        pairAxis_.resize(anyPolyhedra_ ? nPairs : 0);
        thrust::for_each(thrust::device, first, first + nPairs,
                         TransferPairHistory{ptr(pairOwner_), ptr(pairPartner_), ptr(id_), ptr(oldLo), ptr(oldHi),
                                             ptr(oldXi), ptr(oldMr), anyPolyhedra_ ? ptr(oldAxis) : nullptr, nOld,
                                             ptr(pairXi_), rolling ? ptr(pairMr_) : nullptr,
                                             anyPolyhedra_ ? ptr(pairAxis_) : nullptr, ptr(pairTouching_)});
        pairForce_.resize(nPairs);
        pairTorqueB_.resize(nPairs);
#ifdef __CUDACC__
        pairTorqueA_.resize(nPairs);
#endif
        ownForce_.resize(n);
        ownTorque_.resize(n);

        // Incoming pairs of each particle, in pair order: a stable sort by body 2
        {
            dvec<int> key(pairPartner_);
            inPair_.resize(nPairs);
            thrust::sequence(thrust::device, inPair_.begin(), inPair_.end());
            thrust::stable_sort_by_key(thrust::device, key.begin(), key.end(), inPair_.begin());
            inStart_.resize(n + 1);
            thrust::lower_bound(thrust::device, key.begin(), key.end(), first, first + n + 1, inStart_.begin());
        }

        // Plane candidates, their springs carried over by plane index
        planeStart_.assign(n + 1, 0);
        BuildPlaneCandidates cand{ptr(ref_), ptr(radius_), nPl ? ptr(planes_) : nullptr, nPl, skin(),
                                  ptr(planeStart_), nullptr, nullptr};
        thrust::for_each(thrust::device, first, first + n, cand);
        thrust::exclusive_scan(thrust::device, planeStart_.begin(), planeStart_.end(), planeStart_.begin());
        const int nCand = planeStart_.back();
        planePlane_.resize(nCand);
        planeXi_.resize(nCand);
        planeMr_.resize(rolling ? nCand : 0);
        cand.start = ptr(planeStart_);
        cand.out = ptr(planePlane_);
        thrust::for_each(thrust::device, first, first + n, cand);
        thrust::for_each(thrust::device, first, first + n,
                         TransferPlaneHistory{ptr(perm), oldPlaneN,
                                              oldPlaneStart.empty() ? nullptr : ptr(oldPlaneStart),
                                              ptr(oldPlanePlane), ptr(oldPlaneXi),
                                              rolling && !oldPlaneMr.empty() ? ptr(oldPlaneMr) : nullptr,
                                              ptr(planeStart_), ptr(planePlane_), ptr(planeXi_),
                                              rolling ? ptr(planeMr_) : nullptr});

        contactCount_.assign(n, 0);
        wallContactCount_.assign(n, 0);
    }

    //- Put the springs of a snapshot into the freshly built lists
    void restoreHistory(const Snapshot& s)
    {
        const int n = int(id_.size());
        const auto ids = toHost(id_);
        std::map<int64_t, int> indexOf;
        for (int i = 0; i < n; ++i) indexOf[ids[i]] = i;
        const bool rolling = law_.rolling != RollingModel::none;

        if (!s.pairs.empty())
        {
            std::map<std::pair<int64_t, int64_t>, const PairHistory*> hist;
            for (const auto& h : s.pairs) hist[{h.idA, h.idB}] = &h;
            const auto start = toHost(pairStart_);
            const auto partner = toHost(pairPartner_);
            auto xi = toHost(pairXi_);
            auto mr = toHost(pairMr_);
            auto axis = toHost(pairAxis_);
            auto touching = toHost(pairTouching_);
            for (int i = 0; i < n; ++i)
                for (int k = start[i]; k < start[i + 1]; ++k)
                {
                    const int64_t a = ids[i], b = ids[partner[k]];
                    auto it = hist.find({std::min(a, b), std::max(a, b)});
                    if (it == hist.end()) continue;
                    // The snapshot holds the springs as seen from the smaller id
                    const double sign = a < b ? 1.0 : -1.0;
                    xi[k] = sign * it->second->tangential;
                    if (rolling) mr[k] = sign * it->second->rolling;
                    if (!axis.empty()) axis[k] = sign * it->second->normal;
                    touching[k] = 1;
                }
            toDevice(pairXi_, xi);
            toDevice(pairMr_, mr);
            toDevice(pairAxis_, axis);
            toDevice(pairTouching_, touching);
        }

        const int nPl = int(config_.planes.size());
        const auto cs = toHost(planeStart_);
        const auto cp = toHost(planePlane_);
        std::vector<Vec3> pxi(cp.size()), pmr(rolling ? cp.size() : 0);
        MeshSlot empty{};
        empty.mesh = -1;
        std::vector<MeshSlot> slots(config_.meshes.empty() ? 0 : size_t(n) * maxMeshSlots, empty);
        std::vector<int> used(n, 0);
        for (const auto& w : s.walls)
        {
            auto it = indexOf.find(w.id);
            if (it == indexOf.end()) continue;
            const int i = it->second;
            if (w.wall < nPl)
            {
                // A plane with a spring touches, so it is among the candidates
                for (int c = cs[i]; c < cs[i + 1]; ++c)
                {
                    if (cp[c] != w.wall) continue;
                    pxi[c] = w.tangential;
                    if (rolling) pmr[c] = w.rolling;
                }
            }
            else if (!slots.empty() && used[i] < maxMeshSlots)
            {
                MeshSlot& ms = slots[size_t(i) * maxMeshSlots + used[i]++];
                ms.mesh = w.wall - nPl;
                ms.triangle = w.triangle;
                ms.normal = w.normal;
                ms.xi = w.tangential;
                ms.mr = w.rolling;
            }
        }
        toDevice(planeXi_, pxi);
        toDevice(planeMr_, pmr);
        toDevice(meshSlots_, slots);
    }

    void computeForces()
    {
        dispatch([&](auto law, auto kind) { this->forcesWith<decltype(law), decltype(kind), false>(); });
        reduceWallLoads(false);
    }

    //- Every wall's load point and motion (planes, then meshes)
    void setupWallLoadPoints()
    {
        std::vector<WallLoadPoint> lp;
        for (const auto& w : config_.planes) lp.push_back(WallLoadPoint{motionOf(w.motion), w.loadPoint});
        for (const auto& w : config_.meshes) lp.push_back(WallLoadPoint{motionOf(w.motion), w.loadPoint});
        toDevice(wallLoadPoints_, lp);
        wallLoadPointsHost_ = lp;
    }

    //- Host loads from device sums, with the load points at the current time
    std::vector<WallLoad> loadsOf(const std::vector<WallShare>& s) const
    {
        std::vector<WallLoad> out(s.size());
        for (size_t w = 0; w < s.size(); ++w)
        {
            out[w].force = s[w].force;
            out[w].torque = s[w].torque;
            out[w].normalForce = s[w].normalForce;
            out[w].contacts = s[w].contacts;
            out[w].point = wallLoadPointsHost_[w].at(time_);
        }
        return out;
    }

    //- Shares of the last force pass -> each wall's load (WallLoadBlocks,
    //  WallLoadTotal: fixed order); accumulate: a step, add it to the sums
    void reduceWallLoads(bool accumulate)
    {
        if (!wallLoadsOn_) return;
        const int n = int(id_.size());
        const int nWalls = int(wallLoadCurrent_.size());
        if (nWalls == 0) return;
        if (accumulate) ++wallLoadSteps_;
        const auto first = thrust::counting_iterator<int>(0);
        if (n == 0 || wallShare_.size() != size_t(n) * nWalls)
        {
            // No particles (or no force pass with loads on yet): nothing on the walls
            thrust::fill(thrust::device, wallLoadCurrent_.begin(), wallLoadCurrent_.end(), WallShare());
            return;
        }
        const int nBlocks = (n + wallLoadBlock - 1) / wallLoadBlock;
        wallLoadBlocks_.resize(size_t(nBlocks) * nWalls);
        thrust::for_each(thrust::device, first, first + nBlocks * nWalls,
                         WallLoadBlocks{ptr(wallShare_), ptr(pos_), ptr(wallLoadPoints_), n, nWalls, time_,
                                        ptr(wallLoadBlocks_)});
        thrust::for_each(thrust::device, first, first + nWalls,
                         WallLoadTotal{ptr(wallLoadBlocks_), nBlocks, nWalls, accumulate,
                                       ptr(wallLoadCurrent_), ptr(wallLoadSum_)});
    }

    //- A step's energy flows (the particles' shares of the force pass, in
    //  fixed blocks in particle order) added to the running sum
    void reduceEnergyFlows()
    {
        if (!energyOn_) return;
        ++energySteps_;
        const int n = int(id_.size());
        if (n == 0 || energyFlow_.size() != size_t(n)) return;
        const auto first = thrust::counting_iterator<int>(0);
        const int nBlocks = (n + energyFlowBlock - 1) / energyFlowBlock;
        energyBlocks_.resize(nBlocks);
        thrust::for_each(thrust::device, first, first + nBlocks,
                         EnergyFlowBlocks{ptr(energyFlow_), n, ptr(energyBlocks_)});
        thrust::for_each(thrust::device, first, first + 1,
                         EnergyFlowTotal{ptr(energyBlocks_), nBlocks, ptr(energySum_)});
    }

    //- The shares of the force pass (null when wall loads are off)
    WallShares wallShares()
    {
        WallShares ws;
        const int nWalls = int(config_.planes.size() + config_.meshes.size());
        if (!wallLoadsOn_ || nWalls == 0) return ws;
        wallShare_.resize(id_.size() * size_t(nWalls));
        ws.share = ptr(wallShare_);
        ws.nWalls = nWalls;
        ws.nPlanes = int(config_.planes.size());
        return ws;
    }

    //- Pair pass, then the per-particle sums with the planes, then the meshes;
    //  with Kick the second half kick is done by the last of these kernels
    template<class Law, class Kind, bool Kick>
    void forcesWith()
    {
        const int n = int(id_.size());
        if (n == 0) return;
        contactCount_.resize(n);
        wallContactCount_.resize(n);
        const auto first = thrust::counting_iterator<int>(0);
        const ParticleView pv = view();
        const LawView lv = lawView();
        const bool rolling = law_.rolling != RollingModel::none;
        PairLists pl{ptr(pairStart_), ptr(pairPartner_), ptr(pairOwner_), ptr(pairXi_),
                     rolling ? ptr(pairMr_) : nullptr, ptr(pairTouching_), ptr(pairForce_),
                     nullptr, ptr(pairTorqueB_), pairAxis_.empty() ? nullptr : ptr(pairAxis_)};
        const int nPairs = int(pairPartner_.size());
        EnergyFlow* energy = nullptr;
        double* ownDissipation = nullptr;
        if (energyOn_)
        {
            energyFlow_.resize(n);
            energy = ptr(energyFlow_);
#ifdef __CUDACC__
            pairDissipation_.resize(nPairs);
            pl.dissipation = ptr(pairDissipation_);
#else
            ownDissipation_.resize(n);
            ownDissipation = ptr(ownDissipation_);
#endif
        }
#ifdef __CUDACC__
        constexpr bool ownFromPairs = true;
        pl.torqueA = ptr(pairTorqueA_);
        if (nPairs > 0)
        {
            thrust::for_each(thrust::device, first, first + nPairs,
                             PairPerPairKernel<Law, Kind>{PairContact<Law, Kind>{pv, lv, pl}});
        }
#else
        constexpr bool ownFromPairs = false;
        const bool serial = omp_get_max_threads() == 1 && config_.meshes.empty();
        if (!serial)
        {
            thrust::for_each(thrust::device, first, first + n,
                             PairKernel<Law, Kind>{PairContact<Law, Kind>{pv, lv, pl}, ptr(ownForce_), ptr(ownTorque_),
                                                   ownDissipation});
        }
#endif
        (void)nPairs;
        const int nMesh = int(config_.meshes.size());
        const WallContact<Law, Kind> wall{pv, lv};
        const WallShares shares = wallShares();
        auto particleForces = [&](auto kick) {
            constexpr bool kickHere = decltype(kick)::value;
            ParticleForces<Law, Kind, kickHere, ownFromPairs> k;
            k.wall = wall;
            k.gravity = config_.gravity;
            k.time = time_;
            k.dt = config_.timeStep;
            k.pairs = pl;
            k.ownForce = ptr(ownForce_);
            k.ownTorque = ptr(ownTorque_);
            k.inStart = ptr(inStart_);
            k.inPair = ptr(inPair_);
            k.contactCount = ptr(contactCount_);
            k.planes = planes_.empty() ? nullptr : ptr(planes_);
            k.planeStart = ptr(planeStart_);
            k.planePlane = ptr(planePlane_);
            k.planeXi = ptr(planeXi_);
            k.planeMr = rolling ? ptr(planeMr_) : nullptr;
            k.wallContactCount = ptr(wallContactCount_);
            k.shares = shares;
            k.energy = energy;
            k.ownDissipation = ownDissipation;
            thrust::for_each(thrust::device, first, first + n, k);
        };
        if (nMesh == 0)
        {
#ifndef __CUDACC__
            if (serial)
            {
                // One thread: pairs, planes and kick in a single loop
                ParticleForces<Law, Kind, Kick, false> k;
                k.wall = wall;
                k.gravity = config_.gravity;
                k.time = time_;
                k.dt = config_.timeStep;
                k.pairs = pl;
                k.contactCount = ptr(contactCount_);
                k.planes = planes_.empty() ? nullptr : ptr(planes_);
                k.planeStart = ptr(planeStart_);
                k.planePlane = ptr(planePlane_);
                k.planeXi = ptr(planeXi_);
                k.planeMr = rolling ? ptr(planeMr_) : nullptr;
                k.wallContactCount = ptr(wallContactCount_);
                k.shares = shares;
                k.energy = energy;
                serialSums_.resize(n);
                SerialStep<Law, Kind, Kick>{PairContact<Law, Kind>{pv, lv, pl}, k, ptr(serialSums_)}.run(n);
                return;
            }
#endif
            particleForces(std::integral_constant<bool, Kick>());
            return;
        }
        particleForces(std::false_type());
        MeshWallKernel<Law, Kind, Kick> m;
        m.wall = wall;
        m.time = time_;
        m.dt = config_.timeStep;
        m.meshes = ptr(meshes_);
        m.nMeshes = nMesh;
        m.triA = ptr(triA_);
        m.triDepth = ptr(triDepth_);
        m.triSideStart = ptr(triSideStart_);
        m.triSideNormal = triSideNormal_.empty() ? nullptr : ptr(triSideNormal_);
        m.triSideOffset = triSideOffset_.empty() ? nullptr : ptr(triSideOffset_);
        m.triB = ptr(triB_);
        m.triC = ptr(triC_);
        m.cellStart = ptr(meshCellStart_);
        m.cellTriangles = meshCellTri_.empty() ? nullptr : ptr(meshCellTri_);
        m.meshSlots = ptr(meshSlots_);
        m.wallContactCount = ptr(wallContactCount_);
        m.shares = shares;
        m.energy = energy;
        thrust::for_each(thrust::device, first, first + n, m);
    }

    //- Elastic energy of the normal springs (host side: a diagnostic, not hot)
    double elasticEnergy() const
    {
        const auto pos = toHost(pos_);
        const auto rad = toHost(radius_);
        const auto ids = toHost(id_);
        const auto start = toHost(pairStart_);
        const auto partner = toHost(pairPartner_);
        const auto type = toHost(type_);
        const auto q = toHost(q_);
        const auto pc = toHost(pairCoeffs_);
        const int nm = int(config_.materials.size());
        auto coeff = [&](int ma, int mb) { return pc[ma * nm + mb]; };
        const bool volumetric = law_.law == ContactLaw::overlapVolume;
        const PackedPolyhedra packed = packPolyhedra(config_.shapes);
        const PolyhedronTable table = packed.table();
        auto shapeOf = [&](int i) {
            const ParticleType& t = config_.types[type[i]];
            return t.shape == ShapeKind::polyhedron ? t.shapeIndex : -1;
        };
        double e = 0;
        const int n = int(ids.size());
        for (int i = 0; i < n; ++i)
        {
            const int mi = config_.types[type[i]].material;
            for (int k = start[i]; k < start[i + 1]; ++k)
            {
                const int j = partner[k];
                const int mj = config_.types[type[j]].material;
                if (volumetric)
                {
                    // Exact for flat (face-face) contacts, V = A d: W = Kn V^2 / (2 A)
                    const int si = shapeOf(i), sj = shapeOf(j);
                    OverlapResult ov;
                    if (si < 0 && sj < 0) ov = sphereSphereOverlap(pos[i], rad[i], pos[j], rad[j]);
                    else if (si >= 0 && sj >= 0)
                        ov = polyhedronOverlap(table.shape(si), pos[i], q[i], table.shape(sj), pos[j], q[j]);
                    else if (si >= 0) ov = polyhedronSphereOverlap(table.shape(si), pos[i], q[i], pos[j], rad[j]);
                    else ov = polyhedronSphereOverlap(table.shape(sj), pos[j], q[j], pos[i], rad[i]);
                    if (ov.touching)
                    {
                        e += OverlapVolume::elasticEnergyOfVolume(law_, ov.volume, ov.contactArea);
                    }
                    continue;
                }
                const double d = rad[i] + rad[j] - norm(pos[j] - pos[i]);
                if (d <= 0) continue;
                e += normalElasticEnergy(law_, coeff(mi, mj), rad[i] * rad[j] / (rad[i] + rad[j]), d);
            }
            for (const auto& w : config_.planes)
            {
                detail::RigidMotion m = motionOf(w.motion);
                const Quaternion R = m.rotationAt(time_);
                const Vec3 nrm = m.directionToWorld(w.normal, R);
                const Vec3 p0 = m.toWorld(w.point, time_, R);
                const double h = dot(pos[i] - p0, nrm);
                if (h >= rad[i]) continue;
                if (volumetric)
                {
                    // Exact: Kn times the first moment of the overlap about the plane
                    const int si = shapeOf(i);
                    const OverlapResult ov = si >= 0
                        ? polyhedronPlaneOverlap(table.shape(si), pos[i], q[i], p0, nrm)
                        : sphereHalfSpaceOverlap(pos[i], rad[i], pos[i] - h * nrm, nrm);
                    if (ov.touching)
                    {
                        e += OverlapVolume::elasticEnergyAgainstPlane(law_, ov.volume, dot(p0 - ov.centroid, nrm));
                    }
                    continue;
                }
                e += normalElasticEnergy(law_, coeff(mi, w.material), rad[i], rad[i] - h);
            }
        }
        return e;
    }

    SimulationConfig config_;
    double time_ = 0, time0_ = 0;
    int64_t step_ = 0, step0_ = 0;
    LawParameters law_;
    double rMax_ = 0;
    double meshBinnedRadius_ = 0;
    size_t builds_ = 0;

    dvec<int64_t> id_;
    dvec<int> type_;
    dvec<double> radius_, mass_;
    dvec<Vec3> inertia_, pos_, vel_, omega_, force_, torque_, ref_, extForce_, extTorque_;
    dvec<Quaternion> q_;

    dvec<PairCoefficients> pairCoeffs_;
    dvec<int> typeMaterial_, typeShape_;

    dvec<int> shapeVertexBegin_, shapeFaceBegin_, shapeFaceStartBegin_, shapeFaceVertexBegin_, shapeEdgeBegin_;
    dvec<double> shapeBoundingRadius_, shapeVolume_, shapeFaceOffsets_;
    dvec<Vec3> shapeInertia_, shapeVertices_, shapeFaceNormals_;
    dvec<int> shapeFaceStart_, shapeFaceVertex_;
    dvec<PolyhedronEdge> shapeEdges_;
    PolyhedronTable shapeTable_;

    bool anyPolyhedra_ = false;

    // Half lists (CSR) and the per-pair state
    dvec<int> pairStart_, pairPartner_, pairOwner_, inStart_, inPair_;
    dvec<Vec3> pairXi_, pairMr_;
    dvec<unsigned char> pairTouching_;
    dvec<Vec3> pairForce_, pairTorqueA_, pairTorqueB_, ownForce_, ownTorque_;
    dvec<Vec3> pairAxis_;   //!< polyhedra only: PairLists::separatingAxis
    dvec<int> contactCount_, wallContactCount_;
#ifndef __CUDACC__
    dvec<ForceSum> serialSums_;   //!< the one-thread force pass's accumulators
#endif

    // Plane candidates (CSR) and their springs
    dvec<int> planeStart_, planePlane_;
    dvec<PlaneDevice> planes_;
    dvec<Vec3> planeXi_, planeMr_;

    dvec<MeshDevice> meshes_;
    dvec<Vec3> triA_, triB_, triC_;
    dvec<double> triDepth_;     //!< per triangle, how deep its wall solid reaches
    dvec<int> triSideStart_;    //!< per triangle, its side planes (CSR; WallSidePlanes.hpp)
    dvec<Vec3> triSideNormal_;
    dvec<double> triSideOffset_;
    dvec<int> meshCellStart_, meshCellTri_;
    dvec<MeshSlot> meshSlots_;

    // Wall loads (off unless enabled): per-particle shares, block sums,
    // the last pass's loads and their running sums
    bool wallLoadsOn_ = false;
    dvec<WallShare> wallShare_, wallLoadBlocks_, wallLoadCurrent_, wallLoadSum_;
    dvec<WallLoadPoint> wallLoadPoints_;
    std::vector<WallLoadPoint> wallLoadPointsHost_;
    int64_t wallLoadSteps_ = 0;

    // Energy flows (off unless enabled): per-particle shares of a step
    // (pairs' dissipation: per pair on the GPU, per owner on the CPU),
    // block sums, and the running sum over steps
    bool energyOn_ = false;
    dvec<EnergyFlow> energyFlow_, energyBlocks_, energySum_;
    dvec<double> pairDissipation_, ownDissipation_;
    int64_t energySteps_ = 0;

    // Outlet boxes and the particles removed since the last takeRemoved()
    dvec<Vec3> outletLo_, outletHi_;
    // Kinematic approach boxes (SimulationConfig::approaches)
    dvec<Vec3> approachLo_, approachHi_, approachVel_;
    std::vector<RemovedParticle> removed_;
};

} // namespace PD_BACKEND_NS
} // namespace polydem

#include "polyDEM/System.hpp"

#include "polyDEM/ContactLaws.hpp"
#include "polyDEM/Error.hpp"

#include <dlfcn.h>

#include <cmath>
#include <cstdlib>
#include <sstream>

namespace polydem
{

namespace
{

std::string str(double x)
{
    std::ostringstream os;
    os.precision(4);
    os << x;
    return os.str();
}

// Folder of the shared library holding this code: back ends sit beside it
std::string thisLibraryFolder()
{
    Dl_info info;
    if (dladdr(reinterpret_cast<void*>(&thisLibraryFolder), &info) && info.dli_fname)
    {
        std::string path(info.dli_fname);
        const auto slash = path.rfind('/');
        if (slash != std::string::npos)
        {
            return path.substr(0, slash);
        }
    }
    return ".";
}

double largestFaceArea(const ConvexShape& s)
{
    double best = 0;
    for (int f = 0; f < s.nFaces(); ++f)
    {
        Vec3 a;
        const int b = s.faceStart[f], e = s.faceStart[f + 1];
        for (int k = b; k < e; ++k)
        {
            a += cross(s.vertices[s.faceVertex[k]], s.vertices[s.faceVertex[k + 1 < e ? k + 1 : b]]);
        }
        best = std::max(best, 0.5 * norm(a));
    }
    return best;
}

} // namespace


void System::checkTimeStep(const SimulationConfig& c)
{
    if (!(c.timeStep > 0) || !std::isfinite(c.timeStep))
    {
        throw Error("time step must be positive, got " + str(c.timeStep), c.source, "timeStep");
    }
}


void System::checkConfig(const SimulationConfig& c)
{
    const std::string& f = c.source;
    checkTimeStep(c);
    if (c.materials.empty())
    {
        throw Error("at least one material is needed", f, "materials");
    }
    for (const auto& m : c.materials)
    {
        const std::string e = "materials/" + m.name;
        if (!(m.youngsModulus > 0)) throw Error("Young's modulus must be positive", f, e + "/youngsModulus");
        if (!(m.poissonsRatio >= 0 && m.poissonsRatio < 0.5))
            throw Error("Poisson's ratio must be in [0, 0.5)", f, e + "/poissonsRatio");
        if (!(m.density > 0)) throw Error("density must be positive", f, e + "/density");
    }
    if (c.pairs.size() != c.materials.size() * c.materials.size())
    {
        throw Error("interaction table must have one entry per material pair", f, "interactions");
    }
    for (const auto& p : c.pairs)
    {
        if (!(p.restitution > 0 && p.restitution <= 1))
            throw Error("coefficient of restitution must be in (0, 1]", f, "interactions/restitution");
        if (!(p.friction >= 0)) throw Error("friction must be >= 0", f, "interactions/friction");
        if (!(p.rollingFriction >= 0))
            throw Error("rolling friction must be >= 0", f, "interactions/rollingFriction");
        if (!(p.twistingFriction >= 0))
            throw Error("twisting friction must be >= 0", f, "interactions/twistingFriction");
    }
    if (c.contact.law == ContactLaw::linearSpringDashpot && !(c.contact.normalStiffness > 0))
    {
        throw Error("linearSpringDashpot needs a positive normal stiffness [N/m]", f, "contactModel/normalStiffness");
    }
    if (c.contact.law == ContactLaw::overlapVolume && !(c.contact.volumetricStiffness > 0))
    {
        throw Error("overlapVolume needs a positive volumetric stiffness [N/m3]", f,
                    "contactModel/volumetricStiffness");
    }
    if (c.types.empty())
    {
        throw Error("at least one particle type is needed", f, "particleTypes");
    }
    for (const auto& t : c.types)
    {
        if (t.material < 0 || t.material >= int(c.materials.size()))
            throw Error("unknown material", f, "particleTypes/" + t.name + "/material");
        if (t.shape == ShapeKind::sphere && !(t.radius > 0))
            throw Error("sphere radius must be positive", f, "particleTypes/" + t.name + "/diameter");
        if (t.shape == ShapeKind::polyhedron)
        {
            if (t.shapeIndex < 0 || t.shapeIndex >= int(c.shapes.size()))
                throw Error("polyhedral type without a shape", f, "particleTypes/" + t.name + "/shape");
            if (c.contact.law != ContactLaw::overlapVolume)
                throw Error("polyhedral particles need the overlapVolume contact law", f, "contactModel/law");
            c.shapes[t.shapeIndex].check();
        }
    }
    for (const auto& w : c.planes)
    {
        if (!(norm(w.normal) > 0)) throw Error("plane normal must be non-zero", f, "walls/" + w.name + "/normal");
        if (w.material < 0 || w.material >= int(c.materials.size()))
            throw Error("unknown material", f, "walls/" + w.name + "/material");
    }
    for (const auto& w : c.meshes)
    {
        if (w.mesh.triangles.empty()) throw Error("wall mesh has no triangles", f, "walls/" + w.name + "/file");
        if (w.material < 0 || w.material >= int(c.materials.size()))
            throw Error("unknown material", f, "walls/" + w.name + "/material");
        if (w.motion.kind == MotionKind::rotation && !(norm(w.motion.axis) > 0))
            throw Error("rotation axis must be non-zero", f, "walls/" + w.name + "/motion/axis");
    }
    if (!(c.skinFraction > 0))
    {
        throw Error("neighbour skin must be positive", f, "skin");
    }
}


System::System(SimulationConfig config) : config_(std::move(config))
{
    checkConfig(config_);
    for (auto& w : config_.planes) w.normal = w.normal / norm(w.normal);
    for (auto& w : config_.planes)
        if (norm(w.motion.axis) > 0) w.motion.axis = w.motion.axis / norm(w.motion.axis);
    for (auto& w : config_.meshes)
        if (norm(w.motion.axis) > 0) w.motion.axis = w.motion.axis / norm(w.motion.axis);

    const std::string libName = "libpolyDEM_" + config_.device + ".so";
    std::vector<std::string> folders;
    if (const char* p = std::getenv("POLYDEM_BACKEND_PATH")) folders.push_back(p);
    folders.push_back(thisLibraryFolder());
    if (const char* p = std::getenv("FOAM_USER_LIBBIN")) folders.push_back(p);

    std::string tried;
    for (const auto& folder : folders)
    {
        const std::string path = folder + "/" + libName;
        library_ = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
        if (library_) break;
        tried += "\n    " + path + ": " + dlerror();
    }
    if (!library_)
    {
        throw Error
        (
            "cannot load the '" + config_.device + "' back end (valid: cpu, cuda; cuda needs a "
            "build with nvcc and a GPU). Tried:" + tried,
            config_.source, "device"
        );
    }
    auto create = reinterpret_cast<PolydemCreateEngineFn>(dlsym(library_, "polydemCreateEngine"));
    if (!create)
    {
        throw Error("back end library has no polydemCreateEngine", config_.source, "device");
    }
    engine_.reset(create());
}


System::~System()
{
    engine_.reset();
    // The library stays loaded: objects it made (exceptions in flight, statics)
    // may still refer to its code.
}


void System::completeMassProperties(ParticleState& p) const
{
    for (std::size_t i = 0; i < p.size(); ++i)
    {
        if (p.mass[i] > 0) continue;
        const auto& type = config_.types[p.type[i]];
        const double rho = config_.materials[type.material].density;
        if (type.shape == ShapeKind::polyhedron)
        {
            const ConvexShape& shape = config_.shapes[type.shapeIndex];
            p.mass[i] = rho * shape.volume;
            p.inertia[i] = rho * shape.inertiaPerDensity;
            p.radius[i] = shape.boundingRadius;
            continue;
        }
        const double r = p.radius[i];
        p.mass[i] = rho * 4.0 / 3.0 * M_PI * r * r * r;
        const double I = 0.4 * p.mass[i] * r * r;
        p.inertia[i] = Vec3(I, I, I);
    }
}


ParticleState System::makeSpheres
(
    int type,
    const std::vector<Vec3>& positions,
    const std::vector<double>& radii,
    std::int64_t firstId
) const
{
    ParticleState p;
    p.resize(positions.size());
    for (std::size_t i = 0; i < positions.size(); ++i)
    {
        p.id[i] = firstId + std::int64_t(i);
        p.type[i] = type;
        p.radius[i] = radii.empty() ? config_.types[type].radius : radii[i];
        p.mass[i] = 0;
        p.position[i] = positions[i];
    }
    completeMassProperties(p);
    return p;
}


double System::criticalTimeStep(const ParticleState& p) const
{
    const LawParameters law = lawParameters(config_.contact, config_.timeStep);
    double limit = 1e300;
    for (std::size_t i = 0; i < p.size(); ++i)
    {
        const auto& type = config_.types[p.type[i]];
        const auto& mat = config_.materials[type.material];
        const double r = p.radius[i];
        // Largest contact area the particle can make (volumetric law)
        const double area = type.shape == ShapeKind::polyhedron
                          ? largestFaceArea(config_.shapes[type.shapeIndex]) : M_PI * r * r;
        const double dtMax = withContactLaw(config_.contact.law, [&](auto L) {
            return decltype(L)::criticalTimeStep(law, mat, r, p.mass[i], area);
        });
        limit = std::min(limit, dtMax);
    }
    return limit;
}


void System::initialise(Snapshot state)
{
    completeMassProperties(state.particles);
    for (std::size_t i = 0; i < state.particles.size(); ++i)
    {
        if (state.particles.type[i] < 0 || state.particles.type[i] >= int(config_.types.size()))
        {
            throw Error("particle " + std::to_string(state.particles.id[i]) + " has an unknown type",
                        config_.source, "particleTypes");
        }
        if (!(state.particles.mass[i] > 0) || !(state.particles.radius[i] > 0))
        {
            throw Error("particle " + std::to_string(state.particles.id[i]) + " has no mass or radius",
                        config_.source, "particleTypes");
        }
    }
    checkStability(state.particles, "these particles");
    engine_->initialise(config_, state);
}


void System::checkStability(const ParticleState& particles, const std::string& what) const
{
    const double dtMax = criticalTimeStep(particles);
    if (config_.timeStep > dtMax)
    {
        throw Error
        (
            "time step " + str(config_.timeStep) + " s is above the contact-stability limit "
            + str(dtMax) + " s for " + what + " ("
            + withContactLaw(config_.contact.law, [](auto L) {
                   return std::string(decltype(L)::criticalTimeStepRule()); })
            + "): reduce timeStep, or soften the material",
            config_.source, "timeStep"
        );
    }
    // Far below the limit: a units slip (1e-11 for 1e-5), and a run that
    // would take forever, not a careful choice
    const double smallest = 1e-5;
    if (dtMax < 1e299 && config_.timeStep < smallest * dtMax)
    {
        throw Error
        (
            "time step " + str(config_.timeStep) + " s is below " + str(smallest)
            + " of the contact-stability limit " + str(dtMax) + " s for " + what
            + ": check the units (seconds); a step of 0.05 to 0.2 of the limit is usual",
            config_.source, "timeStep"
        );
    }
}


void System::addParticles(const ParticleState& added, const std::string& what)
{
    if (added.size() == 0)
    {
        return;
    }
    checkStability(added, what);
    engine_->addParticles(added);
}

} // namespace polydem

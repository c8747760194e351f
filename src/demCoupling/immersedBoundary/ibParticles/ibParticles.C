/*---------------------------------------------------------------------------*\
  Hedra: CFD-DEM for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "ibParticles.H"
#include "Time.H"
#include "mathematicalConstants.H"
#include "demSimulation.H"
#include "demPropertiesReader.H"
#include "polyDEM/System.hpp"
#include "polyDEM/Engine.hpp"
#include "polyDEM/Quaternion.hpp"
#include "polyDEM/Error.hpp"
#include "polyDEMConversions.H"

namespace
{
using Foam::polyDEMConversions::toVec3;
using Foam::polyDEMConversions::toVector;
}


void Foam::ibParticles::readFixed()
{
    const List<dictionary> list(dict_.lookup("bodies"));
    bodies_.setSize(list.size());
    forAll(list, i)
    {
        const dictionary& d = list[i];
        ibBody& b = bodies_[i];
        const word shape(d.get<word>("shape"));
        if (shape != "sphere")
        {
            FatalIOErrorInFunction(d)
                << "motion fixed supports shape sphere only (polyhedra come"
                << " from the DEM: motion polyDEM)" << exit(FatalIOError);
        }
        b.id = i;
        b.radius = d.get<scalar>("radius");
        b.volume = 4.0/3.0*constant::mathematical::pi*pow3(b.radius);
        b.position = d.get<vector>("position");
        b.velocity = d.getOrDefault<vector>("velocity", Zero);
        b.omega = d.getOrDefault<vector>("omega", Zero);
    }
}


void Foam::ibParticles::readDEM()
{
    const polydem::Engine& engine = dem_->system().engine();
    const polydem::SimulationConfig& cfg = dem_->input().config();
    const polydem::ParticleState s = engine.particles();

    bodies_.setSize(s.size());
    forAll(bodies_, i)
    {
        ibBody& b = bodies_[i];
        b.id = label(s.id[i]);
        b.position = toVector(s.position[i]);
        b.velocity = toVector(s.velocity[i]);
        b.omega = toVector(s.omega[i]);
        b.radius = s.radius[i];
        b.mass = s.mass[i];
        // The orientation (spheres too: written to forces.dat)
        b.orientation = polyDEMConversions::orientationTensor(s.orientation[i]);
        const polydem::ParticleType& type = cfg.types[s.type[i]];
        if (type.shape == polydem::ShapeKind::polyhedron)
        {
            const polydem::ConvexShape& shape = cfg.shapes[type.shapeIndex];
            b.polyhedron = true;
            b.volume = shape.volume;
            const label nf = shape.faceNormals.size();
            b.faceNormals.setSize(nf);
            b.faceOffsets.setSize(nf);
            for (label f = 0; f < nf; ++f)
            {
                b.faceNormals[f] = toVector(shape.faceNormals[f]);
                b.faceOffsets[f] = shape.faceOffsets[f];
            }
        }
        else
        {
            b.polyhedron = false;
            b.volume = 4.0/3.0*constant::mathematical::pi*pow3(b.radius);
        }
    }
}


Foam::ibParticles::ibParticles(const fvMesh& mesh)
:
    mesh_(mesh),
    dict_
    (
        IOobject
        (
            "ibProperties",
            mesh.time().constant(),
            mesh,
            IOobject::MUST_READ,
            IOobject::NO_WRITE
        )
    ),
    motion_(dict_.get<word>("motion")),
    internalFluid_
    (
        dict_.getOrDefault<bool>("internalInertia", true)
      ? dict_.getOrDefault<word>("internalFluid", "integrated")
      : word("none")
    ),
    g_(dict_.getOrDefault<vector>("g", vector(0, 0, -9.81)))
{
    if
    (
        internalFluid_ != "integrated"
     && internalFluid_ != "rigid"
     && internalFluid_ != "none"
    )
    {
        FatalIOErrorInFunction(dict_)
            << "Unknown internalFluid " << internalFluid_
            << " (integrated | rigid | none)" << exit(FatalIOError);
    }

    if (motion_ == "fixed")
    {
        readFixed();
    }
    else if (motion_ == "polyDEM")
    {
        demProperties_.reset
        (
            new IOdictionary
            (
                IOobject
                (
                    "demProperties",
                    mesh.time().constant(),
                    mesh,
                    IOobject::MUST_READ,
                    IOobject::NO_WRITE
                )
            )
        );
        // The DEM runs once, on the master, writing to the case folder;
        // the other ranks get the bodies (scatterBodies)
        if (Pstream::master())
        {
            try
            {
                dem_.reset
                (
                    new demSimulation(mesh.time(), *demProperties_, true)
                );
                g_ = toVector(dem_->input().config().gravity);
            }
            catch (const polydem::Error& err)
            {
                demPropertiesReader::reportError(err, *demProperties_);
            }
            readDEM();
        }
        Pstream::scatter(g_);
        scatterBodies(bodies_);
    }
    else
    {
        FatalIOErrorInFunction(dict_)
            << "Unknown motion " << motion_ << " (fixed | polyDEM)"
            << exit(FatalIOError);
    }

    previousVelocity_.setSize(bodies_.size());
    forAll(bodies_, i)
    {
        previousVelocity_[i] = bodies_[i].velocity;
    }
    readState();
    readLubrication();

    if (Pstream::master())
    {
        const fileName dir
        (
            mesh.time().globalPath()/"postProcessing"/"ibForces"
           /mesh.time().timeName()
        );
        mkDir(dir);
        out_.reset(new OFstream(dir/"forces.dat"));
        *out_ << "# time id x y z Ux Uy Uz Fx Fy Fz Tx Ty Tz FLx FLy FLz"
              << " omegax omegay omegaz qw qx qy qz" << nl;
    }
}


Foam::ibParticles::~ibParticles()
{}


void Foam::ibParticles::evolve
(
    const List<vector>& F,
    const List<vector>& T,
    scalar rhoFluid,
    const List<vector>& P,
    const List<vector>& L
)
{
    if (motion_ == "fixed")
    {
        return;
    }

    const scalar dt = mesh_.time().deltaTValue();
    std::vector<polydem::Vec3> force(F.size()), torque(T.size());
    forAll(F, i)
    {
        const ibBody& b = bodies_[i];
        vector Fi = F[i] - rhoFluid*b.volume*g_;
        vector Ti = T[i];
        if (internalFluid_ == "rigid")
        {
            Fi += rhoFluid*b.volume*(b.velocity - previousVelocity_[i])/dt;
        }
        else if (internalFluid_ == "integrated")
        {
            // Internal-fluid inertia from the fluid itself (Kempe &
            // Froehlich 2012); first step: rigid, L = 0
            const vector P0 =
                previousP_.lookup(b.id, b.volume*previousVelocity_[i]);
            const vector L0 = previousL_.lookup(b.id, Zero);
            Fi += rhoFluid*(P[i] - P0)/dt;
            Ti += rhoFluid*(L[i] - L0)/dt;
            previousP_.set(b.id, P[i]);
            previousL_.set(b.id, L[i]);
        }
        if (lubForce_.size() == bodies_.size())
        {
            Fi += lubForce_[i];
        }
        force[i] = toVec3(Fi);
        torque[i] = toVec3(Ti);
        previousVelocity_[i] = b.velocity;
    }

    if (dem_)
    {
        try
        {
            dem_->system().engine().setExternalForces(force, torque);
            dem_->evolve();
        }
        catch (const polydem::Error& err)
        {
            demPropertiesReader::reportError(err, *demProperties_);
        }
    }

    // The engine's order may change (re-sorting): match by id
    Map<vector> oldU;
    forAll(bodies_, i)
    {
        oldU.set(bodies_[i].id, previousVelocity_[i]);
    }
    if (Pstream::master())
    {
        readDEM();
    }
    scatterBodies(bodies_);
    previousVelocity_.setSize(bodies_.size());
    forAll(bodies_, i)
    {
        previousVelocity_[i] =
            oldU.lookup(bodies_[i].id, bodies_[i].velocity);
    }
    updateLubrication();
}


void Foam::ibParticles::writeForces
(
    const List<vector>& F,
    const List<vector>& T
) const
{
    if (!out_)
    {
        return;
    }
    OFstream& os = *out_;
    forAll(bodies_, i)
    {
        const ibBody& b = bodies_[i];
        os  << mesh_.time().timeOutputValue() << ' ' << b.id << ' '
            << b.position.x() << ' ' << b.position.y() << ' '
            << b.position.z() << ' '
            << b.velocity.x() << ' ' << b.velocity.y() << ' '
            << b.velocity.z() << ' '
            << F[i].x() << ' ' << F[i].y() << ' ' << F[i].z() << ' '
            << T[i].x() << ' ' << T[i].y() << ' ' << T[i].z() << ' '
            << lubForce_[i].x() << ' ' << lubForce_[i].y() << ' '
            << lubForce_[i].z() << ' '
            << b.omega.x() << ' ' << b.omega.y() << ' ' << b.omega.z();
        // Orientation: body-to-world rotation as a unit quaternion, w >= 0
        const polydem::Quaternion q =
            polyDEMConversions::quaternionOf(b.orientation);
        os  << ' ' << q.w << ' ' << q.x << ' ' << q.y << ' ' << q.z << nl;
    }
    os.flush();
}


void Foam::ibParticles::write()
{
    if (dem_ && mesh_.time().writeTime())
    {
        dem_->write();
    }
    writeState();
}


// ************************************************************************* //

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
#include "FixedList.H"

namespace
{
Foam::vector toV(const polydem::Vec3& v)
{
    return Foam::vector(v.x, v.y, v.z);
}
polydem::Vec3 toP(const Foam::vector& v)
{
    return polydem::Vec3{v.x(), v.y(), v.z()};
}

//- Unit quaternion (w x y z), w >= 0, of the body-to-world rotation whose
//  transpose is worldToBody (rows: the body axes in world coordinates);
//  Shepperd's method (the largest of 4w^2, 4x^2, 4y^2, 4z^2 first)
Foam::FixedList<Foam::scalar, 4> orientationQuaternion
(
    const Foam::tensor& worldToBody
)
{
    using namespace Foam;
    const tensor R(worldToBody.T());
    const scalar tr = R.xx() + R.yy() + R.zz();
    scalar w, x, y, z;
    if (tr >= R.xx() && tr >= R.yy() && tr >= R.zz())
    {
        const scalar s = 2*std::sqrt(max(1 + tr, scalar(0)));
        w = 0.25*s;
        x = (R.zy() - R.yz())/s;
        y = (R.xz() - R.zx())/s;
        z = (R.yx() - R.xy())/s;
    }
    else if (R.xx() >= R.yy() && R.xx() >= R.zz())
    {
        const scalar s = 2*std::sqrt(max(1 + R.xx() - R.yy() - R.zz(), scalar(0)));
        w = (R.zy() - R.yz())/s;
        x = 0.25*s;
        y = (R.xy() + R.yx())/s;
        z = (R.xz() + R.zx())/s;
    }
    else if (R.yy() >= R.zz())
    {
        const scalar s = 2*std::sqrt(max(1 + R.yy() - R.xx() - R.zz(), scalar(0)));
        w = (R.xz() - R.zx())/s;
        x = (R.xy() + R.yx())/s;
        y = 0.25*s;
        z = (R.yz() + R.zy())/s;
    }
    else
    {
        const scalar s = 2*std::sqrt(max(1 + R.zz() - R.xx() - R.yy(), scalar(0)));
        w = (R.yx() - R.xy())/s;
        x = (R.xz() + R.zx())/s;
        y = (R.yz() + R.zy())/s;
        z = 0.25*s;
    }
    const scalar n = std::sqrt(w*w + x*x + y*y + z*z);
    const scalar sign = w < 0 ? -1 : 1;
    FixedList<scalar, 4> q;
    q[0] = sign*w/n;
    q[1] = sign*x/n;
    q[2] = sign*y/n;
    q[3] = sign*z/n;
    return q;
}
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
        b.position = toV(s.position[i]);
        b.velocity = toV(s.velocity[i]);
        b.omega = toV(s.omega[i]);
        b.radius = s.radius[i];
        b.mass = s.mass[i];
        // The orientation (spheres too: written to forces.dat)
        const polydem::Quaternion& q = s.orientation[i];
        const vector e0 = toV(polydem::rotate(q, polydem::Vec3{1, 0, 0}));
        const vector e1 = toV(polydem::rotate(q, polydem::Vec3{0, 1, 0}));
        const vector e2 = toV(polydem::rotate(q, polydem::Vec3{0, 0, 1}));
        b.worldToBody = tensor(e0, e1, e2);
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
                b.faceNormals[f] = toV(shape.faceNormals[f]);
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
                g_ = toV(dem_->input().config().gravity);
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
        force[i] = toP(Fi);
        torque[i] = toP(Ti);
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
        const FixedList<scalar, 4> q = orientationQuaternion(b.worldToBody);
        os  << ' ' << q[0] << ' ' << q[1] << ' ' << q[2] << ' ' << q[3] << nl;
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

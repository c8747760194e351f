/*---------------------------------------------------------------------------*\
  Hedra: CFD-DEM for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "ibParticles.H"
#include "Time.H"
#include "mathematicalConstants.H"
#include "polyDEMConversions.H"
#include "directForcingIB.H"
#include "ibRefinementIndicator.H"
#include "ibLubrication.H"
#include "boundBox.H"
#include <cmath>
#include "demPropertiesErrors.H"


Foam::dictionary Foam::ibParticles::backendSelection() const
{
    dictionary selection(dict_);
    // No DEM summary rows unless asked for (as demIbFoam has
    // always run: postProcessing/demFoam holds the header only)
    if (!selection.found("demSummary"))
    {
        selection.add("demSummary", false);
    }
    if (!dict_.found("demBackend") && dict_.found("motion"))
    {
        selection.set("demBackend", dict_.get<word>("motion"));
    }
    else if
    (
        dict_.found("motion")
     && dict_.get<word>("motion") != dict_.get<word>("demBackend")
    )
    {
        FatalIOErrorInFunction(dict_)
            << "motion " << dict_.get<word>("motion") << " and demBackend "
            << dict_.get<word>("demBackend") << " disagree in "
            << dict_.name() << " (give demBackend only)"
            << exit(FatalIOError);
    }
    return selection;
}


void Foam::ibParticles::readBodies()
{
    demParticleArrays p;
    backend_->particles(p);

    bodies_.setSize(p.size());
    forAll(bodies_, i)
    {
        ibBody& b = bodies_[i];
        b.id = p.id[i];
        b.position = p.position[i];
        b.velocity = p.velocity[i];
        b.omega = p.omega[i];
        b.radius = p.radius[i];
        b.mass = p.mass[i];
        // The orientation (spheres too: written to forces.dat)
        b.orientation = p.orientation[i];
        const demShape& shape = shapes_[p.type[i]];
        if (shape.polyhedron())
        {
            b.polyhedron = true;
            b.volume = shape.volume;
            b.faceNormals = shape.normals;
            b.faceOffsets = shape.offsets;
        }
        else
        {
            b.polyhedron = false;
            b.volume = 4.0/3.0*constant::mathematical::pi*pow3(b.radius);
            b.faceNormals.clear();
            b.faceOffsets.clear();
        }
    }
}


Foam::wordList Foam::ibParticles::dictKeys()
{
    return wordList
    ({
        "demBackend", "motion", "internalInertia", "internalFluid",
        "directForcing", "lubrication", "refinement"
    });
}


void Foam::ibParticles::checkEntries(const wordList& solverKeys) const
{
    DynamicList<word> valid(dictKeys());
    valid.append(solverKeys);
    if (backend_)
    {
        valid.append(backend_->dictKeys());
    }
    demPropertiesErrors::checkKeys(dict_, dict_, "", valid);

    auto checkSub = [&](const word& key, const wordList& keys)
    {
        const entry* e = dict_.findEntry(key, keyType::LITERAL);
        if (!e)
        {
            return;
        }
        if (!e->isDict())
        {
            FatalIOErrorInFunction(dict_)
                << "Entry '" << key << "' of " << dict_.name()
                << " must be a dictionary; valid entries: " << keys
                << exit(FatalIOError);
        }
        demPropertiesErrors::checkKeys(dict_, e->dict(), key, keys);
    };
    checkSub("directForcing", directForcingIB::dictKeys());
    checkSub("lubrication", ibLubrication::dictKeys());
    checkSub("refinement", ibRefinementIndicator::dictKeys());
}


Foam::ibParticles::ibParticles
(
    const fvMesh& mesh,
    const word& dictName,
    const wordList& solverKeys
)
:
    mesh_(mesh),
    dict_
    (
        IOobject
        (
            dictName,
            mesh.time().constant(),
            mesh,
            IOobject::MUST_READ,
            IOobject::NO_WRITE
        )
    ),
    internalFluid_
    (
        dict_.getOrDefault<bool>("internalInertia", true)
      ? dict_.getOrDefault<word>("internalFluid", "integrated")
      : word("none")
    ),
    g_(Zero),
    demTimeStep_(0),
    started_(false)
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

    // The DEM runs once, on the master, writing to the case folder; the
    // other ranks get the bodies (scatterBodies). A distributed back end
    // (demBackend::onAllRanks) runs on every rank, every call to it made on
    // every rank; the master's bodies are scattered.
    const dictionary selection(backendSelection());
    if (Pstream::master() || demBackend::onAllRanks(selection))
    {
        backend_ = demBackend::New(mesh.time(), selection);
        g_ = backend_->gravity();
        demTimeStep_ = backend_->timeStep();
        shapes_.setSize(backend_->typeNames().size());
        forAll(shapes_, t)
        {
            backend_->typePolyhedron(t, shapes_[t]);
        }
        readBodies();
        checkEntries(solverKeys);
    }
    Pstream::scatter(g_);
    Pstream::scatter(demTimeStep_);
    scatterBodies(bodies_);
    checkInsideMesh();

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
              << " omegax omegay omegaz qw qx qy qz"
              << " FDx FDy FDz TDx TDy TDz" << nl;
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
    checkForcesFinite(F, T);
    const scalar dt = mesh_.time().deltaTValue();
    List<vector> force(F.size()), torque(T.size());
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
        force[i] = Fi;
        torque[i] = Ti;
        previousVelocity_[i] = b.velocity;
    }

    writeForces(F, T, force, torque);
    advance(force, torque);
}


void Foam::ibParticles::evolve
(
    const List<vector>& F,
    const List<vector>& T,
    const List<scalar>& M,
    const List<vector>& S,
    const vector& g,
    const List<vector>& P,
    const List<vector>& L,
    const List<vector>& Pnext,
    const List<vector>& Lnext
)
{
    checkForcesFinite(F, T);
    const scalar dt = mesh_.time().deltaTValue();
    List<vector> force(F.size()), torque(T.size());
    forAll(F, i)
    {
        const ibBody& b = bodies_[i];
        // No Archimedes term: the weight of the fluid inside that the
        // fluid equations carried is taken out, buoyancy is in F_IB; so is
        // that weight's moment about the centre, which is not zero where a
        // free surface runs through the body (water below, air above): the
        // hydrostatic righting moment is then in T_IB
        vector Fi = F[i] - M[i]*g;
        vector Ti = T[i] - (S[i] ^ g);
        if (internalFluid_ == "rigid")
        {
            Fi += M[i]*(b.velocity - previousVelocity_[i])/dt;
        }
        else if (internalFluid_ == "integrated")
        {
            const vector P0 =
                previousP_.lookup(b.id, M[i]*previousVelocity_[i]);
            const vector L0 = previousL_.lookup(b.id, Zero);
            Fi += (P[i] - P0)/dt;
            Ti += (L[i] - L0)/dt;
            previousP_.set(b.id, Pnext[i]);
            previousL_.set(b.id, Lnext[i]);
        }
        if (lubForce_.size() == bodies_.size())
        {
            Fi += lubForce_[i];
        }
        force[i] = Fi;
        torque[i] = Ti;
        previousVelocity_[i] = b.velocity;
    }

    writeForces(F, T, force, torque);
    advance(force, torque);
}


void Foam::ibParticles::advance
(
    List<vector>& force,
    List<vector>& torque
)
{
    if (backend_.valid())
    {
        // The first handover goes through start() (the back end's restart
        // order), the later ones through setForces()
        if (started_)
        {
            backend_->setForces(force, torque);
        }
        else
        {
            backend_->start(force, torque);
        }
        backend_->evolve();
    }
    started_ = true;

    // The engine's order may change (re-sorting): match by id
    Map<vector> oldU;
    forAll(bodies_, i)
    {
        oldU.set(bodies_[i].id, previousVelocity_[i]);
    }
    if (backend_.valid())
    {
        readBodies();
    }
    scatterBodies(bodies_);
    checkInsideMesh();
    previousVelocity_.setSize(bodies_.size());
    forAll(bodies_, i)
    {
        previousVelocity_[i] =
            oldU.lookup(bodies_[i].id, bodies_[i].velocity);
    }
    updateLubrication();
}


void Foam::ibParticles::checkInsideMesh() const
{
    // A body whose centre has left the fluid mesh feels no fluid at all:
    // stop, naming it (every rank holds every body; reduce the search)
    // One reduction for all bodies: a body is inside if some rank finds it
    labelList found(bodies_.size(), 0);
    forAll(bodies_, i)
    {
        found[i] = (mesh_.findCell(bodies_[i].position) >= 0) ? 1 : 0;
    }
    Pstream::listCombineGather(found, maxEqOp<label>());
    Pstream::listCombineScatter(found);
    forAll(bodies_, i)
    {
        const ibBody& b = bodies_[i];
        if (!found[i])
        {
            const boundBox bb(mesh_.points(), true);
            FatalErrorInFunction
                << "Body " << b.id << " has left the fluid mesh at t = "
                << mesh_.time().value() << " s: centre " << b.position
                << ", velocity " << b.velocity << ", angular velocity "
                << b.omega << nl
                << "    mesh bounds " << bb << nl
                << "    (bodies must stay inside the fluid domain: a DEM wall"
                << " at the mesh boundary keeps them in; or the time step"
                << " is too large)" << exit(FatalError);
        }
    }
}


void Foam::ibParticles::checkForcesFinite
(
    const List<vector>& F,
    const List<vector>& T
) const
{
    auto finite = [](const vector& v)
    {
        return std::isfinite(v.x()) && std::isfinite(v.y())
            && std::isfinite(v.z());
    };
    forAll(F, i)
    {
        if (finite(F[i]) && finite(T[i]))
        {
            continue;
        }
        const ibBody& b = bodies_[i];
        FatalErrorInFunction
            << "Non-finite fluid force on body " << b.id << " at t = "
            << mesh_.time().value() << " s: force " << F[i]
            << " N, torque " << T[i] << " N m" << nl
            << "    centre " << b.position << ", velocity " << b.velocity
            << ", angular velocity " << b.omega << nl
            << "    (the fluid has blown up: check the Courant number and"
            << " the body's velocity)" << exit(FatalError);
    }
}


void Foam::ibParticles::writeForces
(
    const List<vector>& F,
    const List<vector>& T,
    const List<vector>& force,
    const List<vector>& torque
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
        os  << ' ' << q.w << ' ' << q.x << ' ' << q.y << ' ' << q.z;
        // What the DEM gets: the whole fluid force and torque on the body
        os  << ' ' << force[i].x() << ' ' << force[i].y() << ' '
            << force[i].z() << ' ' << torque[i].x() << ' ' << torque[i].y()
            << ' ' << torque[i].z() << nl;
    }
    os.flush();
}


void Foam::ibParticles::write()
{
    if (backend_.valid())
    {
        backend_->write();
    }
    writeState();
}


// ************************************************************************* //

// Built only where LIGGGHTS is installed (Debian's libliggghts-dev)
#if __has_include(<liggghts/library_cfd_coupling.h>)

#include "liggghtsBackend.H"
#include "liggghtsLibrary.H"
#include "addToRunTimeSelectionTable.H"
#include "OSspecific.H"
#include "Pstream.H"
#include "IOmanip.H"
#include "DynamicList.H"
#include "demPropertiesErrors.H"
#include <cmath>

namespace Foam
{
    defineTypeNameAndDebug(liggghtsBackend, 0);
    addToRunTimeSelectionTable(demBackend, liggghtsBackend, dictionary);
    addDemBackendOnAllRanks(liggghtsBackend);
}


namespace
{
//- The master's value on every rank
template<class T>
T fromMaster(const T& value)
{
    T v(value);
    if (Foam::Pstream::parRun())
    {
        Foam::Pstream::scatter(v);
    }
    return v;
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::fileName Foam::liggghtsBackend::scriptPath(const word& entry) const
{
    fileName f(coeffs_.get<fileName>(entry));
    f.expand();
    if (!f.isAbsolute())
    {
        f = runTime_.globalPath()/f;
    }
    if (!isFile(f))
    {
        FatalIOErrorInFunction(coeffs_)
            << "The LIGGGHTS input script " << f << " (entry " << entry
            << " of " << coeffs_.name() << ") does not exist" << nl
            << "    expected a LIGGGHTS script, by convention"
            << " constant/liggghts/in.liggghts" << exit(FatalIOError);
    }
    return f;
}


void Foam::liggghtsBackend::checkScript() const
{
    // Every rank holds the same fixes and settings: all stop together
    DynamicList<string> missing;
    if (!lib_->hasFixStyle("couple/cfd") || !lib_->mpiCoupling())
    {
        missing.append("fix cfd all couple/cfd couple_every 1 mpi");
    }
    if (!lib_->hasFixStyle("couple/cfd/force") || !lib_->hasAtomVector("dragforce"))
    {
        missing.append("fix cfd2 all couple/cfd/force");
    }
    if (!lib_->atomMap())
    {
        missing.append("atom_modify map array");
    }
    if (missing.size())
    {
        FatalIOErrorInFunction(coeffs_)
            << "The LIGGGHTS script " << script_ << " (from "
            << coeffs_.name() << ") lacks what the coupling needs;"
            << " add to it:" << nl;
        for (const string& line : missing)
        {
            FatalIOError << "        " << line.c_str() << nl;
        }
        FatalIOError
            << "    (fix couple/cfd with the mpi data coupling and fix"
            << " couple/cfd/force, before the run; atom_modify before"
            << " create_box)" << exit(FatalIOError);
    }
    if (!lib_->granularAtoms())
    {
        FatalIOErrorInFunction(coeffs_)
            << "The LIGGGHTS script " << script_ << " does not set up"
            << " granular atoms (radius, rmass, omega): use"
            << " atom_style granular (spheres)" << exit(FatalIOError);
    }
    if (lib_->timeStep() <= 0)
    {
        FatalIOErrorInFunction(coeffs_)
            << "The LIGGGHTS script " << script_ << " sets no positive"
            << " timestep" << exit(FatalIOError);
    }
}


Foam::fileName Foam::liggghtsBackend::restartDir() const
{
    return fromMaster(fileName(casePath()/runTime_.timeName()/"liggghts"));
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::liggghtsBackend::liggghtsBackend
(
    const word& modelType,
    const Time& runTime,
    const dictionary& dict
)
:
    demBackend(runTime),
    coeffs_(dict.subDict(modelType + "Coeffs")),
    script_(),
    lib_(),
    restartForces_(false),
    typeDensity_(),
    gravity_(Zero),
    ids_(),
    heldForce_(),
    heldTorque_(),
    holding_(false)
{
    // A misspelled script entry would otherwise fall back silently (the
    // restart script is optional)
    demPropertiesErrors::checkKeys
    (
        dict, coeffs_, modelType + "Coeffs", {"inputScript", "restartScript"}
    );

    // A start time with a LIGGGHTS restart file (the master's folder)
    const fileName restartFile(restartDir()/"liggghts.restart");
    const bool restart = fromMaster(isFile(restartFile));
    restartForces_ =
        Pstream::master() && isFile(stateDir()/"fluidForces");

    const fileName input(scriptPath("inputScript"));
    if (restart)
    {
        if (!coeffs_.found("restartScript"))
        {
            FatalIOErrorInFunction(coeffs_)
                << "The start time holds the LIGGGHTS restart file "
                << restartFile << nl << "    but " << coeffs_.name()
                << " gives no restartScript: a LIGGGHTS script that reads"
                << " it (read_restart ${restartFile}) and sets up the fixes,"
                << " as inputScript " << input << " does"
                << exit(FatalIOError);
        }
        script_ = scriptPath("restartScript");
    }
    else
    {
        script_ = input;
    }

    const fileName screen(runTime.globalPath()/"log.liggghts");
    Info<< "liggghtsBackend: LIGGGHTS on "
        << (Pstream::parRun() ? Pstream::nProcs() : 1) << " rank(s), "
        << "script " << script_ << ", screen output " << screen << endl;

    lib_.reset(new liggghtsLibrary(Pstream::parRun(), screen));
    if (restart)
    {
        Info<< "liggghtsBackend: restart from " << restartFile << endl;
        lib_->command("variable restartFile string " + restartFile);
    }
    lib_->file(script_);
    checkScript();
    // Set up (fixes initialised, data coupling established): advances
    // nothing
    lib_->command("run 0 post no");

    // Types and gravity (collective)
    const std::vector<double> rho(lib_->typeDensities());
    typeDensity_.setSize(label(rho.size()));
    forAll(typeDensity_, t)
    {
        if (rho[t] < 0)
        {
            FatalIOErrorInFunction(coeffs_)
                << "The atoms of LIGGGHTS type " << t + 1 << " (script "
                << script_ << ") have different densities: the coupling"
                << " needs one density per type (give each density its own"
                << " type)" << exit(FatalIOError);
        }
        typeDensity_[t] = rho[t];
    }
    const std::array<double, 3> g(lib_->gravity());
    gravity_ = vector(g[0], g[1], g[2]);

    const label nSteps = stepsPerFluidStep();
    Info<< "liggghtsBackend: " << typeDensity_.size() << " atom type(s),"
        << " densities " << typeDensity_ << " kg/m3, gravity " << gravity_
        << " m/s2, timestep " << lib_->timeStep() << " s, "
        << nSteps << " DEM steps per fluid step, time "
        << lib_->time() << " s" << endl;
}


Foam::liggghtsBackend::~liggghtsBackend()
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::liggghtsBackend::timeStep() const
{
    return lib_->timeStep();
}


Foam::label Foam::liggghtsBackend::stepsPerFluidStep() const
{
    const scalar deltaT = runTime_.deltaTValue();
    const scalar dt = lib_->timeStep();
    const scalar ratio = deltaT/dt;
    const label n = label(std::llround(ratio));
    if (n < 1 || mag(n*dt - deltaT) > 1e-9*deltaT)
    {
        FatalIOErrorInFunction(coeffs_)
            << "The LIGGGHTS timestep " << dt << " s (script " << script_
            << ")" << nl << "    does not divide the controlDict deltaT "
            << deltaT << " s: deltaT/timestep = " << setprecision(12)
            << ratio << nl
            << "    deltaT must be a whole multiple of the timestep (to 1e-9)"
            << exit(FatalIOError);
    }
    return n;
}


Foam::wordList Foam::liggghtsBackend::typeNames() const
{
    wordList names(typeDensity_.size());
    forAll(names, t)
    {
        names[t] = word("type" + Foam::name(t + 1));
    }
    return names;
}


Foam::scalar Foam::liggghtsBackend::typeDensity(label type) const
{
    return typeDensity_[type];
}


Foam::vector Foam::liggghtsBackend::gravity() const
{
    return gravity_;
}


void Foam::liggghtsBackend::particles(demParticleArrays& p) const
{
    liggghtsLibrary::atoms a;
    lib_->gather(a);
    const label n = label(a.size());
    p.setSize(n);
    ids_.setSize(n);
    for (label i = 0; i < n; ++i)
    {
        const label t = a.type[i] - 1;
        // The volume demCloud takes from mass/typeDensity must be the
        // atom's: one density per type (a type seen first now takes it)
        if (t >= 0 && t < typeDensity_.size() && typeDensity_[t] > 0)
        {
            if (mag(a.density[i] - typeDensity_[t]) > 1e-12*typeDensity_[t])
            {
                FatalIOErrorInFunction(coeffs_)
                    << "LIGGGHTS atom " << a.id[i] << " of type " << t + 1
                    << " has density " << a.density[i] << ", its type "
                    << typeDensity_[t] << " (script " << script_ << "):"
                    << " the coupling needs one density per type"
                    << exit(FatalIOError);
            }
        }
        p.id[i] = a.id[i];
        p.type[i] = t;
        p.radius[i] = a.radius[i];
        p.mass[i] = a.mass[i];
        p.position[i] = vector(a.x[3*i], a.x[3*i + 1], a.x[3*i + 2]);
        p.velocity[i] = vector(a.v[3*i], a.v[3*i + 1], a.v[3*i + 2]);
        p.omega[i] = vector(a.omega[3*i], a.omega[3*i + 1], a.omega[3*i + 2]);
        p.orientation[i] = tensor::I;
        ids_[i] = a.id[i];
    }
}


bool Foam::liggghtsBackend::restartForcesFound() const
{
    return restartForces_;
}


void Foam::liggghtsBackend::start(List<vector>& F, List<vector>& T)
{
    if (restartForces_)
    {
        readHeldForces(ids_, F, T);
    }
    setForces(F, T);
}


void Foam::liggghtsBackend::setForces
(
    const List<vector>& F,
    const List<vector>& T
)
{
    if (F.size() != ids_.size() || (T.size() && T.size() != ids_.size()))
    {
        FatalErrorInFunction
            << "Forces for " << F.size() << " particles and torques for "
            << T.size() << " handed over; the last particles() gave "
            << ids_.size() << exit(FatalError);
    }
    if (T.size() && !lib_->hasAtomVector("hdtorque"))
    {
        FatalIOErrorInFunction(coeffs_)
            << "Torques handed over, but fix couple/cfd/force of the LIGGGHTS"
            << " script " << script_ << " holds no hdtorque (torque transfer"
            << " off): the torques would be lost" << exit(FatalIOError);
    }
    std::vector<int> ids(ids_.begin(), ids_.end());
    std::vector<double> f(3*F.size()), t(3*T.size());
    forAll(F, i)
    {
        for (direction c = 0; c < 3; ++c)
        {
            f[3*i + c] = F[i][c];
        }
    }
    forAll(T, i)
    {
        for (direction c = 0; c < 3; ++c)
        {
            t[3*i + c] = T[i][c];
        }
    }
    // The master's forces (every rank's are the same): summed over the
    // ranks by the data coupling, the others give zero
    lib_->scatterForces(ids, f, t, Pstream::master());
    heldForce_ = F;
    heldTorque_ = T;
    holding_ = true;
}


void Foam::liggghtsBackend::evolve()
{
    const label n = stepsPerFluidStep();
    holding_ = false;
    lib_->command("run " + std::to_string(n) + " pre yes post no");
}


void Foam::liggghtsBackend::write()
{
    if (!runTime_.writeTime())
    {
        return;
    }
    // Collective: LIGGGHTS's rank 0 (the master) writes the file
    const fileName dir(restartDir());
    if (Pstream::master())
    {
        mkDir(dir);
    }
    lib_->command("write_restart " + dir/"liggghts.restart");
    if (holding_ && Pstream::master())
    {
        // Forces for the next advance: start() hands them over again at a
        // restart, so that the restarted run continues as if unbroken
        writeHeldForces(ids_, heldForce_, heldTorque_);
    }
}


Foam::scalar Foam::liggghtsBackend::time() const
{
    return lib_->time();
}

#endif

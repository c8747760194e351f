/*---------------------------------------------------------------------------*\
  Hedra: CFD-DEM for OpenFOAM
-------------------------------------------------------------------------------
Description
    ibParticles: restart state and lubrication (kept apart from the motion
    in ibParticles.C).

    <time>/polyDEM/ibState (case folder, written by the master with the DEM
    state at write times, read back on restart) holds what the particles'
    equation carries from one fluid step to the next, by body id:
        previousVelocity   U_p of the last step (internalFluid rigid)
        previousP          sum lambda U V of the last step (integrated)
        previousL          sum lambda r x U V of the last step (integrated)
    written with 17 digits, so that a restarted run continues bit for bit
    (with the fields written in binary or with writePrecision 17). A start
    time written by demIbFoam (it holds fIB) without ibState is an error.

\*---------------------------------------------------------------------------*/

#include "ibParticles.H"
#include "Time.H"
#include "IFstream.H"
#include "OFstream.H"
#include "OSspecific.H"
#include "dimensionedScalar.H"

Foam::fileName Foam::ibParticles::statePath() const
{
    return
        mesh_.time().globalPath()/mesh_.time().timeName()/"polyDEM"/"ibState";
}


void Foam::ibParticles::readState()
{
    bool found = false;
    if (Pstream::master() && backend_->movesParticles())
    {
        const fileName f(statePath());
        if (isFile(f))
        {
            IFstream is(f);
            const dictionary d(is);
            const labelList ids(d.get<labelList>("id"));
            const List<vector> U0(d.get<List<vector>>("previousVelocity"));
            if (ids.size() != U0.size())
            {
                FatalIOErrorInFunction(d)
                    << "id and previousVelocity differ in size in " << f
                    << exit(FatalIOError);
            }
            Map<vector> byId;
            forAll(ids, k)
            {
                byId.set(ids[k], U0[k]);
            }
            forAll(bodies_, i)
            {
                previousVelocity_[i] =
                    byId.lookup(bodies_[i].id, previousVelocity_[i]);
            }
            previousP_ = d.get<Map<vector>>("previousP");
            previousL_ = d.get<Map<vector>>("previousL");
            Info<< "ibParticles: restart state read from " << f << endl;
            found = true;
        }
        else
        {
            // fIB is written by demIbFoam at its write times (and carried by
            // decomposePar and reconstructPar): such a time also carries
            // ibState, without which the first step would not continue the
            // run that wrote it
            const Time& runTime = mesh_.time();
            const fileName written[2] =
            {
                runTime.timePath()/"fIB",
                runTime.globalPath()/runTime.timeName()/"fIB"
            };
            for (const fileName& w : written)
            {
                if (isFile(w) || isFile(w + ".gz"))
                {
                    FatalErrorInFunction
                        << "The start time " << runTime.timeName()
                        << " was written by demIbFoam (" << w << " exists)"
                        << nl << "    but " << f << " is missing: the "
                        << "bodies' previous velocity and internal-fluid "
                        << "momentum, written with the DEM state." << nl
                        << "Restore it, or restart from a time that has it."
                        << exit(FatalError);
                }
            }
        }
    }
    Pstream::scatter(found);
    if (found)
    {
        Pstream::scatter(previousVelocity_);
        Pstream::scatter(previousP_);
        Pstream::scatter(previousL_);
    }
}


void Foam::ibParticles::writeState() const
{
    // Bodies held in place carry nothing from step to step
    if
    (
        !Pstream::master()
     || !backend_->movesParticles()
     || !mesh_.time().writeTime()
    )
    {
        return;
    }
    const fileName f(statePath());
    mkDir(f.path());
    OFstream os(f);
    os.precision(17);
    os  << "// ibParticles restart state (demIbFoam), t = "
        << mesh_.time().timeName() << nl;
    labelList ids(bodies_.size());
    forAll(bodies_, i)
    {
        ids[i] = bodies_[i].id;
    }
    os.writeEntry("id", ids);
    os.writeEntry("previousVelocity", previousVelocity_);
    os.writeEntry("previousP", previousP_);
    os.writeEntry("previousL", previousL_);
}


void Foam::ibParticles::updateLubrication()
{
    lubForce_.setSize(bodies_.size());
    lubForce_ = Zero;
    if (!lubrication_ || !lubrication_->active() || !Pstream::master())
    {
        return;
    }
    lubForce_ = lubrication_->forces
    (
        bodies_,
        backend_.get(),
        mesh_.time().value(),
        mu_,
        mesh_.time().deltaTValue()
    );
}


void Foam::ibParticles::readLubrication()
{
    lubrication_.reset
    (
        new ibLubrication(dict_.subOrEmptyDict("lubrication"))
    );
    mu_ = 0;
    if (lubrication_->active())
    {
        const dictionary& tp =
            mesh_.lookupObject<IOdictionary>("transportProperties");
        mu_ =
            dimensionedScalar("nu", dimViscosity, tp).value()
           *dimensionedScalar("rho", dimDensity, tp).value();
        Info<< "ibParticles: lubrication " << lubrication_->model()
            << ", mu = " << mu_ << " Pa s" << endl;
    }
    updateLubrication();
}


// ************************************************************************* //

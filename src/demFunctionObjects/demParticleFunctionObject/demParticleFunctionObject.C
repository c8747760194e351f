/*---------------------------------------------------------------------------*\
  Hedra: CFD-DEM for OpenFOAM
-------------------------------------------------------------------------------
Description
    Base of the DEM particle function objects (see
    demParticleFunctionObject.H).

\*---------------------------------------------------------------------------*/

#include "demParticleFunctionObject.H"
#include "OSspecific.H"
#include "Pstream.H"

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(demParticleFunctionObject, 0);
}
}


Foam::functionObjects::demParticleFunctionObject::demParticleFunctionObject
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    timeFunctionObject(name, runTime),
    startTimeName_(runTime.timeName()),
    interval_(0),
    lastSample_(-GREAT),
    source_(demParticleSource::find(runTime)),
    ready_(false),
    file_(),
    dict_(dict)
{
    if (!source_ && (Pstream::master() || !Pstream::parRun()))
    {
        FatalIOErrorInFunction(dict)
            << "Function object '" << name << "' (type "
            << dict.getOrDefault<word>("type", "?") << ") in " << dict.name()
            << " samples DEM particles, but this run has none: use it with "
            << "demFoam, demPimpleFoam or demIbFoam (a DEM set up by "
            << "constant/demProperties)" << nl << exit(FatalIOError);
    }
}


void Foam::functionObjects::demParticleFunctionObject::initialise()
{
    read(dict_);
    update();
}


bool Foam::functionObjects::demParticleFunctionObject::read
(
    const dictionary& dict
)
{
    timeFunctionObject::read(dict);
    dict_ = dict;
    interval_ = dict.getOrDefault<scalar>("interval", 0);
    if (interval_ < 0)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'interval' of function object '" << name() << "' in "
            << dict.name() << " is " << interval_
            << ": expected a time [s] >= 0 (0: every time step)" << nl
            << exit(FatalIOError);
    }
    if (source_)
    {
        readSettings(dict, source_->particleConfig());
        ready_ = true;
    }
    return true;
}


Foam::OFstream& Foam::functionObjects::demParticleFunctionObject::file()
{
    if (!file_.valid())
    {
        const fileName dir
        (
            time_.globalPath()/"postProcessing"/name()/startTimeName_
        );
        mkDir(dir);
        file_.reset(new OFstream(dir/(name() + ".dat")));
        file_().precision(10);
        file_() << "# ";
        writeHeader(file_());
        file_() << endl;
    }
    return file_();
}


void Foam::functionObjects::demParticleFunctionObject::update()
{
    if (!source_ || !ready_)
    {
        return;
    }
    const scalar t = source_->particleTime();
    if (interval_ > 0 && t < lastSample_ + interval_*(1 - 1e-9))
    {
        return;
    }
    lastSample_ = t;
    sample(t, source_->particleState());
}


bool Foam::functionObjects::demParticleFunctionObject::execute()
{
    update();
    return true;
}


bool Foam::functionObjects::demParticleFunctionObject::write()
{
    return true;
}

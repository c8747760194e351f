/*---------------------------------------------------------------------------*\
  Hedra: CFD-DEM for OpenFOAM
-------------------------------------------------------------------------------
Description
    Base class of demFoam's monitors: selection, sampling interval, output
    file postProcessing/<name>/<startTime>/<name>.dat.

\*---------------------------------------------------------------------------*/

#include "demMonitor.H"
#include "OSspecific.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(demMonitor, 0);
    defineRunTimeSelectionTable(demMonitor, dictionary);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::demMonitor::demMonitor
(
    const word& name,
    const dictionary& dict,
    const Time& runTime,
    const polydem::SimulationConfig& config
)
:
    name_(name),
    runTime_(runTime),
    startTimeName_(runTime.timeName()),
    interval_(dict.getOrDefault<scalar>("interval", 0)),
    lastSample_(-GREAT),
    file_(),
    dict_(dict),
    config_(config)
{}


// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::demMonitor> Foam::demMonitor::New
(
    const word& name,
    const dictionary& dict,
    const Time& runTime,
    const polydem::SimulationConfig& config
)
{
    const word type(dict.get<word>("type"));

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(type);

    if (!cstrIter.found())
    {
        FatalIOErrorInFunction(dict)
            << "Unknown monitor type '" << type << "' for monitor '" << name
            << "' in " << dict.name() << nl
            << "Valid monitor types: "
            << dictionaryConstructorTablePtr_->sortedToc() << nl
            << exit(FatalIOError);
    }

    Info<< "    monitor " << name << " (" << type << ")" << endl;
    return autoPtr<demMonitor>(cstrIter()(name, dict, runTime, config));
}


// * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * * //

Foam::OFstream& Foam::demMonitor::file()
{
    if (!file_.valid())
    {
        const fileName dir
        (
            runTime_.path()/"postProcessing"/name_/startTimeName_
        );
        mkDir(dir);
        file_.reset(new OFstream(dir/(name_ + ".dat")));
        file_().precision(10);
        file_() << "# ";
        writeHeader(file_());
        file_() << endl;
    }
    return file_();
}


void Foam::demMonitor::update(scalar t, const polydem::ParticleState& p)
{
    if (interval_ > 0 && t < lastSample_ + interval_*(1 - 1e-9))
    {
        return;
    }
    lastSample_ = t;
    sample(t, p);
}


// ************************************************************************* //

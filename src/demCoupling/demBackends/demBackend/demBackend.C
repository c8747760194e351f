#include "demBackend.H"
#include "OFstream.H"
#include "OSspecific.H"
#include "Map.H"
#include <cmath>
#include <fstream>

namespace Foam
{
    defineTypeNameAndDebug(demBackend, 0);
    defineRunTimeSelectionTable(demBackend, dictionary);
}


namespace
{
//- One file of held vectors: a comment line, the count, then "id x y z"
void writeVectors
(
    const Foam::fileName& f,
    const char* comment,
    const Foam::labelUList& ids,
    const Foam::UList<Foam::vector>& v
)
{
    using namespace Foam;
    OFstream os(f);
    os.precision(17);
    os  << comment << nl << v.size() << nl;
    forAll(v, i)
    {
        os  << ids[i] << ' ' << v[i].x() << ' ' << v[i].y() << ' '
            << v[i].z() << nl;
    }
}

//- v[i] = the value read for ids[i] (kept where the file has none);
//  false if there is no file
bool readVectors
(
    const Foam::fileName& f,
    const Foam::labelUList& ids,
    Foam::List<Foam::vector>& v
)
{
    using namespace Foam;
    if (!isFile(f))
    {
        return false;
    }
    std::ifstream is(f);
    std::string comment;
    std::getline(is, comment);
    long n = 0;
    is >> n;
    Map<vector> byId;
    for (long k = 0; k < n; ++k)
    {
        long id;
        double x, y, z;
        is >> id >> x >> y >> z;
        byId.set(label(id), vector(x, y, z));
    }
    if (!is)
    {
        FatalErrorInFunction
            << "Cannot read " << f << exit(FatalError);
    }
    forAll(v, i)
    {
        v[i] = byId.lookup(ids[i], v[i]);
    }
    return true;
}
}


Foam::demBackend::demBackend(const Time& runTime)
:
    runTime_(runTime)
{}


Foam::autoPtr<Foam::demBackend> Foam::demBackend::New
(
    const Time& runTime,
    const dictionary& dict
)
{
    const word modelType(dict.getOrDefault<word>("demBackend", "polyDEM"));
    Info<< "    DEM back end: " << modelType << endl;

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);
    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict, "demBackend", modelType, *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }
    return autoPtr<demBackend>
    (
        cstrIter()(modelType, runTime, dict)
    );
}


Foam::scalar Foam::demBackend::compatibleDeltaT
(
    const Time& runTime,
    const scalar wanted,
    const scalar demStep
)
{
    if (!(demStep > 0))
    {
        return wanted;
    }
    label k = max(label(1), label(std::floor(wanted/demStep*(1 + 1e-12))));

    const word writeControl
    (
        runTime.controlDict().getOrDefault<word>("writeControl", "timeStep")
    );
    if (writeControl == "adjustableRunTime" || writeControl == "adjustable")
    {
        const scalar interval =
            runTime.controlDict().get<scalar>("writeInterval");
        const scalar t = runTime.value() - runTime.startTime().value();
        // The next write time after t (a time within 1e-9 of the interval
        // is the write just done)
        const scalar nextWrite =
            (std::floor(t/interval + 1e-9) + 1)*interval;
        const label nDem = label(std::llround((nextWrite - t)/demStep));
        if (nDem >= 1)
        {
            // m fluid steps of at most k DEM steps reach the write time;
            // the steps are made as even as whole DEM steps allow
            const label m = (nDem + k - 1)/k;
            k = (nDem + m - 1)/m;
        }
    }
    return k*demStep;
}


void Foam::demBackend::refuseAdjustTimeStep
(
    const Time& runTime,
    const word& solver
)
{
    const dictionary& cd = runTime.controlDict();
    if (cd.getOrDefault<bool>("adjustTimeStep", false))
    {
        FatalIOErrorInFunction(cd)
            << "Entry 'adjustTimeStep' of " << cd.name() << " is yes, but "
            << solver << " runs with the fixed deltaT" << nl
            << "    (it has no Courant-number control; deltaT must stay a"
            << " whole number of DEM steps): set adjustTimeStep no and"
            << " choose deltaT" << nl
            << "    for the Courant number (demInterFoam adjusts its step)"
            << exit(FatalIOError);
    }
}


Foam::wordHashSet& Foam::demBackend::onAllRanksTable()
{
    static wordHashSet table;
    return table;
}


bool Foam::demBackend::onAllRanks(const dictionary& dict)
{
    return onAllRanksTable().found
    (
        dict.getOrDefault<word>("demBackend", "polyDEM")
    );
}


Foam::fileName Foam::demBackend::casePath() const
{
    return runTime_.globalPath();
}


Foam::fileName Foam::demBackend::stateDir() const
{
    return casePath()/runTime_.timeName()/"polyDEM";
}


void Foam::demBackend::writeHeldForces
(
    const labelUList& ids,
    const UList<vector>& F,
    const UList<vector>& T
) const
{
    const fileName dir(stateDir());
    mkDir(dir);
    writeVectors
    (
        dir/"fluidForces",
        "// demCloud: fluid force [N] per particle id, for restart",
        ids,
        F
    );
    if (T.size())
    {
        writeVectors
        (
            dir/"fluidTorques",
            "// fluid torque [N m] per particle id, for restart",
            ids,
            T
        );
    }
}


bool Foam::demBackend::readHeldForces
(
    const labelUList& ids,
    List<vector>& F,
    List<vector>& T
) const
{
    const fileName dir(stateDir());
    if (!readVectors(dir/"fluidForces", ids, F))
    {
        return false;
    }
    Info<< "demBackend: fluid forces of the restart read from "
        << dir/"fluidForces" << endl;
    if (isFile(dir/"fluidTorques"))
    {
        T.setSize(ids.size(), Zero);
        readVectors(dir/"fluidTorques", ids, T);
    }
    else
    {
        T.clear();  // held without torques: none acted
    }
    return true;
}

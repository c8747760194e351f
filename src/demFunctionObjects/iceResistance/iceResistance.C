/*---------------------------------------------------------------------------*\
  Hedra: CFD-DEM for OpenFOAM
-------------------------------------------------------------------------------
Description
    Ice and fluid resistance of a hull with steady means (see
    iceResistance.H).

\*---------------------------------------------------------------------------*/

#include "iceResistance.H"
#include "steadyMean.H"
#include "demParticleSource.H"
#include "addToRunTimeSelectionTable.H"
#include "fvMesh.H"
#include "IFstream.H"
#include "OFstream.H"
#include "OSspecific.H"
#include "Pstream.H"
#include "wordRes.H"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(iceResistance, 0);
    addToRunTimeSelectionTable(functionObject, iceResistance, dictionary);
}
}


namespace
{
    const double noValue = std::numeric_limits<double>::quiet_NaN();

    const char* seriesNames[] = {"Rice", "Rfluid", "Rtotal", "RiceNet"};
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::iceResistance::iceResistance
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    demParticleFunctionObject(name, runTime, dict),
    wall_(-1),
    wallName_(),
    direction_(1, 0, 0),
    CofR_(),
    openWater_(0),
    openWaterSource_("none given: RiceNet = Rtotal"),
    steadyStart_(-GREAT),
    nBatches_(10),
    plot_(true),
    plotScript_(),
    fluid_(),
    lastPressure_(Zero),
    lastViscous_(Zero),
    forceSteps_(),
    normalSteps_(),
    torqueSteps_(),
    contactSteps_(0),
    steps_(0),
    times_(),
    series_()
{
    // The fluid forces on every rank (their sums are parallel reductions)
    if (dict.found("patches", keyType::LITERAL))
    {
        if (runTime.foundObject<fvMesh>(polyMesh::defaultRegion))
        {
            dictionary fd(dict.subOrEmptyDict("fluid"));
            fd.set("patches", dict.get<wordRes>("patches"));
            fd.set("CofR", dict.getOrDefault<vector>("CofR", Zero));
            fd.set("log", false);
            fluid_.reset(new hullForces(name + "_fluid", runTime, fd));
        }
        else
        {
            WarningInFunction
                << "Function object " << name << " in " << dict.name()
                << ": 'patches' given but this run has no fluid mesh "
                << "(demFoam): the fluid force is left out (written as 0)"
                << endl;
        }
    }
    initialise();
}


// * * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * //

void Foam::functionObjects::iceResistance::readSettings
(
    const dictionary& dict,
    const polydem::SimulationConfig& config
)
{
    wallName_ = dict.get<word>("wall");
    wall_ = -1;
    for (size_t k = 0; k < config.planes.size(); ++k)
    {
        if (config.planes[k].name == wallName_) wall_ = int(k);
    }
    for (size_t k = 0; k < config.meshes.size(); ++k)
    {
        if (config.meshes[k].name == wallName_)
        {
            wall_ = int(config.planes.size() + k);
        }
    }
    if (wall_ < 0)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'wall' of function object " << name() << " in "
            << dict.name() << ": no wall '" << wallName_ << "' in "
            << "demProperties" << nl << exit(FatalIOError);
    }
    const vector d = dict.get<vector>("direction");
    if (!(mag(d) > 0))
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'direction' of function object " << name() << " in "
            << dict.name() << " must not be zero" << nl << exit(FatalIOError);
    }
    direction_ = polydem::Vec3(d.x(), d.y(), d.z())/mag(d);
    const vector c = dict.getOrDefault<vector>("CofR", Zero);
    CofR_ = polydem::Vec3(c.x(), c.y(), c.z());

    const bool owValue = dict.found("openWaterResistance", keyType::LITERAL);
    const bool owFile = dict.found("openWaterFile", keyType::LITERAL);
    if (owValue && owFile)
    {
        FatalIOErrorInFunction(dict)
            << "Function object " << name() << " in " << dict.name()
            << ": give 'openWaterResistance' or 'openWaterFile', not both"
            << nl << exit(FatalIOError);
    }
    if (owValue)
    {
        openWater_ = dict.get<scalar>("openWaterResistance");
        std::ostringstream os;
        os << "openWaterResistance " << openWater_ << " N";
        openWaterSource_ = string(os.str());
    }
    if (owFile)
    {
        fileName f(dict.get<fileName>("openWaterFile"));
        f.expand();
        if (!f.isAbsolute())
        {
            f = time_.globalPath()/f;
        }
        openWater_ = readOpenWater(f, dict);
        std::ostringstream os;
        os << "Rtotal mean " << openWater_ << " N of " << f;
        openWaterSource_ = string(os.str());
    }

    steadyStart_ = dict.getOrDefault<scalar>("steadyStart", -GREAT);
    nBatches_ = dict.getOrDefault<label>("nBatches", 10);
    if (nBatches_ < 2)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'nBatches' of function object " << name() << " in "
            << dict.name() << " must be >= 2, not " << nBatches_ << nl
            << exit(FatalIOError);
    }
    plot_ = dict.getOrDefault<bool>("plot", true);
    plotScript_ = dict.getOrDefault<fileName>
    (
        "plotScript",
        "$HEDRA_DIR/src/demFunctionObjects/iceResistance/plotIceResistance.py"
    );
    plotScript_.expand();

    source()->requestWallLoads();
}


Foam::scalar Foam::functionObjects::iceResistance::readOpenWater
(
    const fileName& file,
    const dictionary& dict
) const
{
    std::ifstream in(file);
    std::string line;
    while (in && std::getline(in, line))
    {
        std::istringstream ls(line);
        std::string key;
        double mean;
        if (ls >> key && key == "Rtotal" && ls >> mean && std::isfinite(mean))
        {
            return mean;
        }
    }
    FatalIOErrorInFunction(dict)
        << "Entry 'openWaterFile' of function object " << name() << " in "
        << dict.name() << ": " << file << " has no line 'Rtotal <mean> ...'"
        << " (the iceResistanceMean.dat of a run without ice, finished)"
        << nl << exit(FatalIOError);
    return 0;
}


void Foam::functionObjects::iceResistance::accumulate()
{
    const demParticleSource* src = source();
    if (!src || src->wallLoadSteps() == 0)
    {
        return;
    }
    const polydem::WallLoad& l = src->wallLoadMean()[wall_];
    const double n = src->wallLoadSteps();
    forceSteps_ += n*l.force;
    normalSteps_ += n*l.normalForce;
    // About CofR: shift from the load point
    torqueSteps_ += n*(l.torque + cross(l.point - CofR_, l.force));
    contactSteps_ += n*l.contacts;
    steps_ += src->wallLoadSteps();
}


void Foam::functionObjects::iceResistance::writeMeans() const
{
    const fileName dir
    (
        time_.globalPath()/"postProcessing"/name()/startTimeName()
    );
    mkDir(dir);

    // The steady window: from steadyStart, or MSER-5 of Rtotal
    std::vector<double> total;
    for (const auto& r : series_) total.push_back(r[2]);
    long start = 0;
    if (steadyStart_ > -0.5*GREAT)
    {
        while (start < long(times_.size()) && times_[start] < steadyStart_*(1 - 1e-12))
        {
            ++start;
        }
    }
    else
    {
        start = steadyMean::mser5(total);
    }

    OFstream os(dir/(name() + "Mean.dat"));
    os.precision(8);
    os  << "# iceResistance steady means of wall '" << wallName_ << "' along ("
        << direction_.x << ' ' << direction_.y << ' ' << direction_.z
        << "), window from t = "
        << (start < long(times_.size()) ? times_[start] : noValue)
        << " s (" << (steadyStart_ > -0.5*GREAT ? "steadyStart" : "MSER-5")
        << "), standard error from " << nBatches_ << " batch means" << nl
        << "# open water: " << openWaterSource_.c_str() << nl
        << "# quantity mean stdError samples windowStart batchLag1Correlation"
        << nl;
    for (size_t c = 0; c < 4; ++c)
    {
        std::vector<double> v;
        for (const auto& r : series_) v.push_back(r[c]);
        const steadyMean::result m = steadyMean::over(v, start, nBatches_);
        os  << seriesNames[c] << ' ' << m.mean << ' ' << m.stdError << ' '
            << label(m.samples) << ' '
            << (start < long(times_.size()) ? times_[start] : noValue) << ' '
            << m.batchCorrelation << nl;
    }
    os.flush();

    if (plot_ && times_.size() > 1)
    {
        // The first python3 with matplotlib (a pyenv shim may lack it)
        const std::string cmd =
            "for py in python3 /usr/bin/python3; do "
            "if \"$py\" -c 'import matplotlib' 2>/dev/null; then "
            "exec \"$py\" '" + plotScript_ + "' '"
          + std::string(dir/(name() + ".dat")) + "' '"
          + std::string(dir/(name() + "Mean.dat")) + "' '"
          + std::string(dir/(name() + ".png")) + "' > '"
          + std::string(dir/"log.plot") + "' 2>&1; fi; done; "
            "echo 'no python3 with matplotlib' > '"
          + std::string(dir/"log.plot") + "'; exit 3";
        if (std::system(cmd.c_str()) != 0)
        {
            WarningInFunction
                << "The plot of " << name() << " failed (" << cmd.c_str()
                << "): see " << dir/"log.plot" << endl;
        }
    }
}


// * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * * //

void Foam::functionObjects::iceResistance::writeHeader(Ostream& os) const
{
    os  << "iceResistance: wall '" << wallName_ << "', direction ("
        << direction_.x << ' ' << direction_.y << ' ' << direction_.z
        << "), moments about (" << CofR_.x << ' ' << CofR_.y << ' '
        << CofR_.z << "), fluid " << (fluid_ ? "patches" : "none")
        << ", open water: " << openWaterSource_.c_str() << nl
        << "# time Fice_x Fice_y Fice_z FiceNormal_x FiceNormal_y "
        << "FiceNormal_z FiceFriction_x FiceFriction_y FiceFriction_z "
        << "Mice_x Mice_y Mice_z contacts Fpressure_x Fpressure_y "
        << "Fpressure_z Fviscous_x Fviscous_y Fviscous_z Rice Rfluid Rtotal "
        << "RiceNet iceSteps";
}


void Foam::functionObjects::iceResistance::sample
(
    scalar t,
    const polydem::ParticleState&
)
{
    const double n = steps_ > 0 ? double(steps_) : noValue;
    const polydem::Vec3 F = (1.0/n)*forceSteps_;
    const polydem::Vec3 Fn = (1.0/n)*normalSteps_;
    const polydem::Vec3 Ff = F - Fn;
    const polydem::Vec3 M = (1.0/n)*torqueSteps_;
    const double contacts = contactSteps_/n;
    const polydem::Vec3 Fp(lastPressure_.x(), lastPressure_.y(), lastPressure_.z());
    const polydem::Vec3 Fv(lastViscous_.x(), lastViscous_.y(), lastViscous_.z());
    const double Rice = dot(F, direction_);
    const double Rfluid = dot(Fp + Fv, direction_);
    const double Rtotal = Rice + Rfluid;

    OFstream& os = file();
    os  << t;
    for (const polydem::Vec3& v : {F, Fn, Ff, M})
    {
        os  << ' ' << v.x << ' ' << v.y << ' ' << v.z;
    }
    os  << ' ' << contacts;
    for (const polydem::Vec3& v : {Fp, Fv})
    {
        os  << ' ' << v.x << ' ' << v.y << ' ' << v.z;
    }
    os  << ' ' << Rice << ' ' << Rfluid << ' ' << Rtotal << ' '
        << Rtotal - openWater_ << ' ' << steps_ << endl;

    // Only samples with a wall load (not the one at the start)
    if (steps_ > 0)
    {
        times_.push_back(t);
        series_.push_back({Rice, Rfluid, Rtotal, Rtotal - openWater_});
    }

    forceSteps_ = polydem::Vec3();
    normalSteps_ = polydem::Vec3();
    torqueSteps_ = polydem::Vec3();
    contactSteps_ = 0;
    steps_ = 0;
}


bool Foam::functionObjects::iceResistance::execute()
{
    if (fluid_)
    {
        fluid_->calcForcesMoment();
        lastPressure_ = fluid_->pressure();
        lastViscous_ = fluid_->viscous();
    }
    accumulate();
    return demParticleFunctionObject::execute();
}


bool Foam::functionObjects::iceResistance::write()
{
    if (source() && time_.writeTime())
    {
        writeMeans();
    }
    return true;
}


bool Foam::functionObjects::iceResistance::end()
{
    if (source())
    {
        writeMeans();
    }
    return true;
}


// ************************************************************************* //

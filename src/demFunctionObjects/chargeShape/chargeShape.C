/*---------------------------------------------------------------------------*\
  Hedra: CFD-DEM for OpenFOAM
-------------------------------------------------------------------------------
Description
    Shoulder, toe, centre of mass and power draw of a mill charge (see
    chargeShape.H).

\*---------------------------------------------------------------------------*/

#include "chargeShape.H"
#include "demParticleSource.H"
#include "addToRunTimeSelectionTable.H"
#include "mathematicalConstants.H"
#include "OFstream.H"
#include "polyDEM/Quaternion.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <string>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(chargeShape, 0);
    addToRunTimeSelectionTable(functionObject, chargeShape, dictionary);
}
}


namespace
{
    const double noValue = std::numeric_limits<double>::quiet_NaN();
    const double toDeg = 180.0/Foam::constant::mathematical::pi;

    // Angle in [0, 360)
    double wrap(double a)
    {
        a = std::fmod(a, 360.0);
        return a < 0 ? a + 360.0 : a;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::chargeShape::chargeShape
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    demParticleFunctionObject(name, runTime, dict),
    omega_(0),
    gravity_(0),
    shellRadius_(0),
    layer_(0),
    nBins_(72),
    coverFraction_(0.5),
    axialMin_(-GREAT),
    axialMax_(GREAT),
    axialGiven_(false),
    steadyStart_(0),
    nBatches_(8),
    torqueSteps_(0),
    steps_(0),
    dissipated_(0),
    wallWork_(0),
    externalWork_(0)
{
    initialise();
}


void Foam::functionObjects::chargeShape::readSettings
(
    const dictionary& dict,
    const polydem::SimulationConfig& config
)
{
    const vector o(dict.get<vector>("origin"));
    const vector a(dict.get<vector>("axis"));
    origin_ = polydem::Vec3(o.x(), o.y(), o.z());
    axis_ = polydem::Vec3(a.x(), a.y(), a.z());
    if (norm(axis_) < VSMALL)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'axis' of function object " << name() << " is zero in "
            << dict.name() << nl << exit(FatalIOError);
    }
    axis_ = axis_/norm(axis_);

    polydem::Vec3 up = -1.0*config.gravity;
    up = up - dot(up, axis_)*axis_;
    gravity_ = norm(up);
    if (gravity_ < VSMALL)
    {
        FatalIOErrorInFunction(dict)
            << "Function object " << name() << ": the mill axis is parallel to "
            << "gravity in " << dict.name() << nl << exit(FatalIOError);
    }
    up_ = up/gravity_;

    // The drive walls, by name; the first gives the rotation
    const wordList names(dict.get<wordList>("walls"));
    if (names.empty())
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'walls' of function object " << name() << " in "
            << dict.name() << " is empty: expected the names of the rotating "
            << "walls (demProperties walls) whose torque drives the mill"
            << nl << exit(FatalIOError);
    }
    walls_.clear();
    bool haveRotation = false;
    for (const word& n : names)
    {
        int found = -1;
        const polydem::WallMotion* motion = nullptr;
        for (size_t k = 0; k < config.planes.size(); ++k)
        {
            if (config.planes[k].name == n)
            {
                found = int(k);
                motion = &config.planes[k].motion;
            }
        }
        for (size_t k = 0; k < config.meshes.size(); ++k)
        {
            if (config.meshes[k].name == n)
            {
                found = int(config.planes.size() + k);
                motion = &config.meshes[k].motion;
            }
        }
        if (found < 0)
        {
            FatalIOErrorInFunction(dict)
                << "Entry 'walls' of function object " << name() << " in "
                << dict.name() << ": no wall '" << n << "' in demProperties"
                << nl << exit(FatalIOError);
        }
        walls_.push_back(found);
        if (!haveRotation && motion->kind == polydem::MotionKind::rotation)
        {
            // The shell's rotation about our axis (signed)
            const polydem::Vec3 wa = motion->axis/norm(motion->axis);
            const double c = dot(wa, axis_);
            const polydem::Vec3 off = motion->origin - origin_;
            const polydem::Vec3 offN = off - dot(off, axis_)*axis_;
            if (std::abs(std::abs(c) - 1) > 1e-9 || norm(offN) > 1e-9*(1 + norm(off)))
            {
                FatalIOErrorInFunction(dict)
                    << "Function object " << name() << " in " << dict.name()
                    << ": wall '" << n << "' rotates about another axis than"
                    << " 'origin' and 'axis'" << nl << exit(FatalIOError);
            }
            omega_ = c > 0 ? motion->omega : -motion->omega;
            haveRotation = true;
        }
    }
    if (!haveRotation || omega_ == 0)
    {
        FatalIOErrorInFunction(dict)
            << "Function object " << name() << " in " << dict.name()
            << ": none of the 'walls' rotates (demProperties walls/<name>/"
            << "motion type rotation): no shell speed for the power" << nl
            << exit(FatalIOError);
    }
    // Rising side: where the bottom of the shell moves to, sign(omega) up x a
    rising_ = (omega_ > 0 ? 1.0 : -1.0)*cross(up_, axis_);

    double dMax = 0;
    for (const auto& type : config.types)
    {
        dMax = std::max(dMax, 2*type.radius);
    }
    shellRadius_ = dict.get<scalar>("shellRadius");
    layer_ = dict.getOrDefault<scalar>("layer", 2*dMax);
    // Bins at least two largest diameters long at the shell (a bin of
    // less than a ball is covered or not by chance), at most 72 (5 deg)
    const label fitting =
        label(std::floor(constant::mathematical::twoPi*shellRadius_/(2*dMax)));
    nBins_ = dict.getOrDefault<label>("nBins", std::max(label(8), std::min(label(72), fitting)));
    coverFraction_ = dict.getOrDefault<scalar>("coverFraction", 0.5);
    axialGiven_ = dict.found("axialMin") || dict.found("axialMax");
    axialMin_ = dict.getOrDefault<scalar>("axialMin", -GREAT);
    axialMax_ = dict.getOrDefault<scalar>("axialMax", GREAT);
    const Time& rt = time_;
    steadyStart_ = dict.getOrDefault<scalar>
    (
        "steadyStart",
        0.5*(rt.startTime().value() + rt.endTime().value())
    );
    nBatches_ = dict.getOrDefault<label>("nBatches", 8);
    if
    (
        !(shellRadius_ > 0) || !(layer_ > 0) || layer_ >= shellRadius_
     || nBins_ < 8 || !(coverFraction_ > 0 && coverFraction_ < 1)
     || !(axialMax_ > axialMin_) || nBatches_ < 2
    )
    {
        FatalIOErrorInFunction(dict)
            << "Function object " << name() << " in " << dict.name()
            << ": expected shellRadius > 0, 0 < layer < shellRadius, nBins >= 8,"
            << " coverFraction in (0, 1), axialMax > axialMin and nBatches >= 2;"
            << " got shellRadius " << shellRadius_ << ", layer " << layer_
            << ", nBins " << nBins_ << ", coverFraction " << coverFraction_
            << ", axial range [" << axialMin_ << ", " << axialMax_
            << "], nBatches " << nBatches_ << nl << exit(FatalIOError);
    }

    source()->requestWallLoads();
    source()->requestEnergyFlows();
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::functionObjects::chargeShape::accumulate()
{
    const demParticleSource* src = source();
    if (!src || src->wallLoadSteps() == 0)
    {
        return;
    }
    const std::vector<polydem::WallLoad>& loads = src->wallLoadMean();
    double T = 0;
    for (const int w : walls_)
    {
        const polydem::WallLoad& l = loads[w];
        // About the axis: shift from the load point to the axis origin
        T += dot(l.torque + cross(l.point - origin_, l.force), axis_);
    }
    torqueSteps_ += T*src->wallLoadSteps();
    steps_ += src->wallLoadSteps();
    const polydem::EnergyFlows& f = src->energyFlowSum();
    dissipated_ += f.dissipation();
    wallWork_ += f.wallWork;
    externalWork_ += f.externalWork;
}


double Foam::functionObjects::chargeShape::mechanicalEnergy
(
    const polydem::ParticleState& p
) const
{
    // Kinetic (translation, and rotation about the principal axes, from the
    // body-frame angular velocity) and gravitational energy of all particles
    const polydem::Vec3 g = source()->particleConfig().gravity;
    double e = 0;
    for (size_t i = 0; i < p.size(); ++i)
    {
        const polydem::Vec3 wb = polydem::rotateInverse(p.orientation[i], p.omega[i]);
        const polydem::Vec3& I = p.inertia[i];
        e += 0.5*p.mass[i]*polydem::dot(p.velocity[i], p.velocity[i])
           + 0.5*(I.x*wb.x*wb.x + I.y*wb.y*wb.y + I.z*wb.z*wb.z)
           - p.mass[i]*polydem::dot(g, p.position[i]);
    }
    return e;
}


void Foam::functionObjects::chargeShape::arc
(
    const polydem::ParticleState& p,
    scalar& shoulder,
    scalar& toe
) const
{
    shoulder = noValue;
    toe = noValue;
    const int nb = int(nBins_);
    const double width = 360.0/nb;
    std::vector<double> vol(nb, 0);
    double sMin = GREAT, sMax = -GREAT;
    const double pi = constant::mathematical::pi;
    for (size_t i = 0; i < p.size(); ++i)
    {
        const polydem::Vec3 r = p.position[i] - origin_;
        const double s = dot(r, axis_);
        if (s < axialMin_ || s > axialMax_)
        {
            continue;
        }
        sMin = std::min(sMin, s - p.radius[i]);
        sMax = std::max(sMax, s + p.radius[i]);
        const double x = dot(r, rising_), y = dot(r, up_);
        const double rr = std::sqrt(x*x + y*y);
        if (rr <= shellRadius_ - layer_ || rr >= shellRadius_)
        {
            continue;
        }
        const double theta = wrap(std::atan2(y, x)*toDeg);
        const int b = std::min(nb - 1, int(theta/width));
        const double rad = p.radius[i];
        vol[b] += 4.0/3.0*pi*rad*rad*rad;
    }
    if (sMax <= sMin)
    {
        return;
    }
    const double length = axialGiven_ ? axialMax_ - axialMin_ : sMax - sMin;
    const double R0 = shellRadius_ - layer_;
    const double binVolume =
        pi*(sqr(shellRadius_) - sqr(R0))*length/nb;

    // Solid fraction, smoothed over three bins (periodic)
    std::vector<double> f(nb);
    for (int b = 0; b < nb; ++b)
    {
        f[b] = (vol[(b + nb - 1) % nb] + vol[b] + vol[(b + 1) % nb])/(3*binVolume);
    }
    const int bMax = int(std::max_element(f.begin(), f.end()) - f.begin());
    const double level = coverFraction_*f[bMax];
    if (!(level > 0))
    {
        return;
    }
    // Follow the covered arc: up in theta (sense of rotation) to the
    // shoulder, down to the toe; the crossing between the last covered
    // and the first uncovered bin centre
    auto crossing = [&](int step) -> double
    {
        int b = bMax;
        for (int k = 0; k < nb; ++k)
        {
            const int next = (b + step + nb) % nb;
            if (f[next] < level)
            {
                const double w = (f[b] - level)/(f[b] - f[next]);
                return (b + 0.5)*width + step*w*width;
            }
            b = next;
        }
        return noValue;   // covered all round (a centrifuged charge)
    };
    const double s = crossing(+1);
    const double t = crossing(-1);
    if (std::isfinite(s) && std::isfinite(t))
    {
        // In [-90, 270): cut at the bottom, which the charge covers, so
        // that a shoulder just below the rising-side horizontal stays
        // next to one just above it (-4, not 356) in the means
        shoulder = wrap(s + 90) - 90;
        toe = wrap(t + 90) - 90;
    }
}


void Foam::functionObjects::chargeShape::writeMeans() const
{
    const fileName dir
    (
        time_.globalPath()/"postProcessing"/name()/startTimeName()
    );
    mkDir(dir);
    OFstream os(dir/(name() + "Mean.dat"));
    os.precision(8);
    static const char* names[] =
    {
        "shoulder[deg]", "toe[deg]", "toeBelow[deg]", "shoulderHeight[m]",
        "toeHeight[m]", "M[kg]", "xc[m]", "yc[m]", "wallTorque[Nm]",
        "gravityTorque[Nm]", "power[W]", "powerGravity[W]",
        "dissipation[W]", "wallWorkRate[W]", "externalWorkRate[W]"
    };
    std::map<std::string, double> means;
    os  << "# chargeShape steady means over t >= " << steadyStart_
        << " with the standard error from " << nBatches_ << " batch means"
        << nl << "# quantity mean stdError samples" << nl;
    for (size_t c = 0; c < sizeof(names)/sizeof(names[0]); ++c)
    {
        std::vector<double> v;
        for (size_t k = 0; k < rows_.size(); ++k)
        {
            if (times_[k] >= steadyStart_*(1 - 1e-12) && std::isfinite(rows_[k][c]))
            {
                v.push_back(rows_[k][c]);
            }
        }
        const label n = label(v.size());
        double mean = noValue, err = noValue;
        if (n > 0)
        {
            mean = 0;
            for (double x : v) mean += x;
            mean /= n;
        }
        if (n >= nBatches_)
        {
            // Contiguous batches of (nearly) equal size
            std::vector<double> bm(nBatches_, 0);
            for (label b = 0; b < nBatches_; ++b)
            {
                const label i0 = b*n/nBatches_, i1 = (b + 1)*n/nBatches_;
                for (label i = i0; i < i1; ++i) bm[b] += v[i];
                bm[b] /= (i1 - i0);
            }
            double bMean = 0;
            for (double x : bm) bMean += x;
            bMean /= nBatches_;
            double var = 0;
            for (double x : bm) var += sqr(x - bMean);
            var /= (nBatches_ - 1);
            err = std::sqrt(var/nBatches_);
        }
        os  << names[c] << ' ' << mean << ' ' << err << ' ' << n << nl;
        means[names[c]] = mean;
    }

    // Energy balance over the window: the samples' power and dissipation
    // are means over the intervals ending at them, so the window starts at
    // the sample before its first
    size_t k0 = 0;
    while (k0 < times_.size() && times_[k0] < steadyStart_*(1 - 1e-12)) ++k0;
    double energyRate = noValue, balance = noValue;
    if (k0 < times_.size())
    {
        const size_t a = k0 > 0 ? k0 - 1 : k0;
        const size_t b = times_.size() - 1;
        if (times_[b] > times_[a])
        {
            energyRate = (energies_[b] - energies_[a])/(times_[b] - times_[a]);
            const double P = means["power[W]"];
            if (std::isfinite(P) && P != 0)
            {
                balance =
                    (
                        P + means["externalWorkRate[W]"]
                      - means["dissipation[W]"] - energyRate
                    )/P;
            }
        }
    }
    const label n = label(times_.size() - k0);
    os  << "energyRate[W] " << energyRate << ' ' << noValue << ' ' << n << nl
        << "energyBalance[-] " << balance << ' ' << noValue << ' ' << n << nl;
}


// * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * * //

void Foam::functionObjects::chargeShape::writeHeader(Ostream& os) const
{
    os  << "chargeShape: angles from the horizontal through the axis on the "
        << "rising side, positive with the rotation (0 rising side, 90 top, "
        << "180 falling side, 270 bottom); shell radius " << shellRadius_
        << " m, omega " << omega_ << " rad/s" << nl
        << "# time shoulder[deg] toe[deg] toeBelow[deg] shoulderHeight[m] "
        << "toeHeight[m] M[kg] xc[m] yc[m] wallTorque[Nm] gravityTorque[Nm] "
        << "power[W] powerGravity[W] wallSteps dissipation[W] wallWorkRate[W] "
        << "externalWorkRate[W] energy[J]";
}


void Foam::functionObjects::chargeShape::sample
(
    scalar t,
    const polydem::ParticleState& p
)
{
    scalar shoulder, toe;
    arc(p, shoulder, toe);
    const double pi = constant::mathematical::pi;
    const double sh = shellRadius_*(1 + std::sin(shoulder*pi/180));
    const double th = shellRadius_*(1 + std::sin(toe*pi/180));

    double M = 0, mx = 0, my = 0;
    for (size_t i = 0; i < p.size(); ++i)
    {
        const polydem::Vec3 r = p.position[i] - origin_;
        const double s = dot(r, axis_);
        if (s < axialMin_ || s > axialMax_)
        {
            continue;
        }
        M += p.mass[i];
        mx += p.mass[i]*dot(r, rising_);
        my += p.mass[i]*dot(r, up_);
    }
    const double xc = M > 0 ? mx/M : noValue;
    const double yc = M > 0 ? my/M : noValue;

    // Gravity's torque about the axis: (xc rising) x (-g up) . a
    // = -g M xc (rising x up).a = -g M xc sign(omega)
    const double sign = omega_ > 0 ? 1.0 : -1.0;
    const double gravityTorque = -gravity_*mx*sign;
    const double wallTorque = steps_ > 0 ? torqueSteps_/steps_ : noValue;
    const double power = -omega_*wallTorque;
    const double powerGravity = gravity_*mx*std::abs(omega_);

    // Energy flows over the same DEM steps as the torque, per second
    const double span = steps_*source()->particleConfig().timeStep;
    const double dissipation = span > 0 ? dissipated_/span : noValue;
    const double wallWorkRate = span > 0 ? wallWork_/span : noValue;
    const double externalWorkRate = span > 0 ? externalWork_/span : noValue;
    const double energy = mechanicalEnergy(p);

    const std::vector<scalar> row
    ({
        shoulder, toe, toe - 180, sh, th, M, xc, yc, wallTorque,
        gravityTorque, power, powerGravity, dissipation, wallWorkRate,
        externalWorkRate
    });
    OFstream& os = file();
    os  << t;
    for (size_t c = 0; c < row.size(); ++c)
    {
        // wallSteps stays the 14th column, as before the energy columns
        if (c == 12) os  << ' ' << steps_;
        os  << ' ' << row[c];
    }
    os  << ' ' << energy << endl;
    times_.push_back(t);
    rows_.push_back(row);
    energies_.push_back(energy);

    torqueSteps_ = 0;
    steps_ = 0;
    dissipated_ = 0;
    wallWork_ = 0;
    externalWork_ = 0;
}


bool Foam::functionObjects::chargeShape::execute()
{
    accumulate();
    return demParticleFunctionObject::execute();
}


bool Foam::functionObjects::chargeShape::end()
{
    if (source())
    {
        writeMeans();
    }
    return true;
}


// ************************************************************************* //

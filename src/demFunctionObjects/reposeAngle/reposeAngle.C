/*---------------------------------------------------------------------------*\
  Hedra: CFD-DEM for OpenFOAM
-------------------------------------------------------------------------------
Description
    Dynamic angle of repose of a drum's bed from a line fitted to the
    top-most particle of each bin across the free surface (see
    reposeAngle.H).

\*---------------------------------------------------------------------------*/

#include "reposeAngle.H"
#include "addToRunTimeSelectionTable.H"
#include "mathematicalConstants.H"

#include <algorithm>
#include <cmath>
#include <vector>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(reposeAngle, 0);
    addToRunTimeSelectionTable(functionObject, reposeAngle, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::reposeAngle::reposeAngle
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    demParticleFunctionObject(name, runTime, dict)
{
    initialise();
}


void Foam::functionObjects::reposeAngle::readSettings
(
    const dictionary& dict,
    const polydem::SimulationConfig& config
)
{
    fitFraction_ = dict.getOrDefault<scalar>("fitFraction", 0.6);
    axialMin_ = dict.getOrDefault<scalar>("axialMin", -GREAT);
    axialMax_ = dict.getOrDefault<scalar>("axialMax", GREAT);

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

    // Up: against gravity, made normal to the axis
    polydem::Vec3 up = -1.0*config.gravity;
    up = up - dot(up, axis_)*axis_;
    if (norm(up) < VSMALL)
    {
        FatalIOErrorInFunction(dict)
            << "Function object " << name() << ": the drum axis is parallel to gravity"
            << " in " << dict.name() << nl << exit(FatalIOError);
    }
    up_ = up/norm(up);
    across_ = cross(axis_, up_);

    double dMax = 0;
    for (const auto& type : config.types)
    {
        dMax = std::max(dMax, 2*type.radius);
    }
    binWidth_ = dict.getOrDefault<scalar>("binWidth", 2*dMax);
    if (!(binWidth_ > 0) || !(fitFraction_ > 0 && fitFraction_ <= 1))
    {
        FatalIOErrorInFunction(dict)
            << "Function object " << name() << ": binWidth must be positive and "
            << "fitFraction in (0, 1] in " << dict.name() << nl
            << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * * //

void Foam::functionObjects::reposeAngle::writeHeader(Ostream& os) const
{
    os  << "reposeAngle: free-surface line fitted over the central "
        << fitFraction_ << " of bins " << binWidth_ << " m wide" << nl
        << "# time angle[deg] absAngle[deg] bins rmsResidual[m]";
}


void Foam::functionObjects::reposeAngle::sample
(
    scalar t,
    const polydem::ParticleState& p
)
{
    std::vector<double> h, top;
    h.reserve(p.size());
    top.reserve(p.size());
    double hMin = GREAT, hMax = -GREAT;
    for (size_t i = 0; i < p.size(); ++i)
    {
        const polydem::Vec3 r = p.position[i] - origin_;
        const double s = dot(r, axis_);
        if (s < axialMin_ || s > axialMax_)
        {
            continue;
        }
        h.push_back(dot(r, across_));
        top.push_back(dot(r, up_) + p.radius[i]);
        hMin = std::min(hMin, h.back());
        hMax = std::max(hMax, h.back());
    }

    scalar angle = 0, rms = 0;
    label used = 0;
    if (h.size() > 1)
    {
        const int nBins = std::max(1, int(std::ceil((hMax - hMin)/binWidth_)));
        std::vector<double> binTop(nBins, -GREAT), binH(nBins, 0);
        for (size_t k = 0; k < h.size(); ++k)
        {
            const int b = std::min(nBins - 1, int((h[k] - hMin)/binWidth_));
            if (top[k] > binTop[b])
            {
                binTop[b] = top[k];
                binH[b] = h[k];
            }
        }
        // Occupied bins, central fraction
        std::vector<int> occupied;
        for (int b = 0; b < nBins; ++b)
        {
            if (binTop[b] > -GREAT)
            {
                occupied.push_back(b);
            }
        }
        const int nOcc = int(occupied.size());
        const int nUse = std::max(2, int(std::round(fitFraction_*nOcc)));
        const int first = std::max(0, (nOcc - nUse)/2);
        const int last = std::min(nOcc, first + nUse);

        double sh = 0, su = 0, shh = 0, shu = 0;
        for (int k = first; k < last; ++k)
        {
            const double x = binH[occupied[k]], y = binTop[occupied[k]];
            sh += x; su += y; shh += x*x; shu += x*y;
        }
        used = last - first;
        const double det = used*shh - sh*sh;
        if (used >= 2 && det > 0)
        {
            const double b = (used*shu - sh*su)/det;
            const double a = (su - b*sh)/used;
            angle = std::atan(b)*180.0/constant::mathematical::pi;
            for (int k = first; k < last; ++k)
            {
                const double x = binH[occupied[k]], y = binTop[occupied[k]];
                rms += sqr(y - (a + b*x));
            }
            rms = std::sqrt(rms/used);
        }
    }

    file()
        << t << ' ' << angle << ' ' << mag(angle) << ' ' << used << ' '
        << rms << endl;
}


// ************************************************************************* //

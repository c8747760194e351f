/*---------------------------------------------------------------------------*\
  Hedra: CFD-DEM for OpenFOAM
-------------------------------------------------------------------------------
Description
    Particle count and mass through a plane or out of the domain: a
    hopper's discharge rate (see planeFlux.H).

\*---------------------------------------------------------------------------*/

#include "planeFlux.H"
#include "addToRunTimeSelectionTable.H"

#include <tuple>
#include <unordered_set>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(planeFlux, 0);
    addToRunTimeSelectionTable(functionObject, planeFlux, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::planeFlux::planeFlux
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    demParticleFunctionObject(name, runTime, dict),
    count_(0),
    mass_(0)
{
    initialise();
}


void Foam::functionObjects::planeFlux::readSettings
(
    const dictionary& dict,
    const polydem::SimulationConfig&
)
{
    window_ = dict.getOrDefault<scalar>("averagingWindow", 0.1);

    const vector p(dict.get<vector>("point"));
    vector n(dict.get<vector>("normal"));
    if (mag(n) < VSMALL)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'normal' of function object " << name() << " is zero in "
            << dict.name() << nl << exit(FatalIOError);
    }
    n /= mag(n);
    point_ = polydem::Vec3(p.x(), p.y(), p.z());
    normal_ = polydem::Vec3(n.x(), n.y(), n.z());
}


// * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * * //

void Foam::functionObjects::planeFlux::writeHeader(Ostream& os) const
{
    os  << "planeFlux through point " << vector(point_.x, point_.y, point_.z)
        << " normal " << vector(normal_.x, normal_.y, normal_.z)
        << ", rates over " << window_ << " s" << nl
        << "# time count mass[kg] countRate[1/s] massFlowRate[kg/s]";
}


void Foam::functionObjects::planeFlux::sample
(
    scalar t,
    const polydem::ParticleState& p
)
{
    std::unordered_set<int64_t> present;
    present.reserve(p.size());

    for (size_t i = 0; i < p.size(); ++i)
    {
        const int64_t id = p.id[i];
        present.insert(id);
        const bool upstream = dot(p.position[i] - point_, normal_) < 0;
        auto it = seen_.find(id);
        if (it == seen_.end())
        {
            seen_.emplace(id, std::make_pair(upstream, p.mass[i]));
            continue;
        }
        if (it->second.first && !upstream)
        {
            count_ += 1;
            mass_ += p.mass[i];
        }
        else if (!it->second.first && upstream)
        {
            count_ -= 1;
            mass_ -= p.mass[i];
        }
        it->second = std::make_pair(upstream, p.mass[i]);
    }

    // Particles gone since the last sample (domain outlet)
    for (auto it = seen_.begin(); it != seen_.end(); )
    {
        if (present.count(it->first))
        {
            ++it;
            continue;
        }
        if (it->second.first)
        {
            count_ += 1;
            mass_ += it->second.second;
        }
        it = seen_.erase(it);
    }

    history_.emplace_back(t, count_, mass_);
    while (history_.size() > 1 && std::get<0>(history_.front()) < t - window_*(1 + 1e-9))
    {
        history_.pop_front();
    }
    const auto& first = history_.front();
    const scalar span = t - std::get<0>(first);
    const scalar countRate = span > 0 ? (count_ - std::get<1>(first))/span : 0;
    const scalar massRate = span > 0 ? (mass_ - std::get<2>(first))/span : 0;

    file()
        << t << ' ' << count_ << ' ' << mass_ << ' '
        << countRate << ' ' << massRate << endl;
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
  Hedra: CFD-DEM for OpenFOAM
-------------------------------------------------------------------------------
Description
    Bounding box, centre of mass and bed height of the particles (see
    boundingBox.H).

\*---------------------------------------------------------------------------*/

#include "boundingBox.H"
#include "addToRunTimeSelectionTable.H"

#include <algorithm>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(boundingBox, 0);
    addToRunTimeSelectionTable(functionObject, boundingBox, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::boundingBox::boundingBox
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


void Foam::functionObjects::boundingBox::readSettings
(
    const dictionary& dict,
    const polydem::SimulationConfig& config
)
{

    const vector o(dict.getOrDefault<vector>("origin", Zero));
    origin_ = polydem::Vec3(o.x(), o.y(), o.z());
    polydem::Vec3 up = -1.0*config.gravity;
    if (dict.found("up", keyType::LITERAL))
    {
        const vector u(dict.get<vector>("up"));
        up = polydem::Vec3(u.x(), u.y(), u.z());
    }
    if (norm(up) < VSMALL)
    {
        up = polydem::Vec3(0, 0, 1);
    }
    up_ = up/norm(up);
}


// * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * * //

void Foam::functionObjects::boundingBox::writeHeader(Ostream& os) const
{
    os  << "boundingBox of the particles; bedHeight along "
        << vector(up_.x, up_.y, up_.z) << nl
        << "# time particles minX minY minZ maxX maxY maxZ "
        << "comX comY comZ bedHeight";
}


void Foam::functionObjects::boundingBox::sample
(
    scalar t,
    const polydem::ParticleState& p
)
{
    polydem::Vec3 lo(0, 0, 0), hi(0, 0, 0), com(0, 0, 0);
    double mass = 0, height = 0;
    for (size_t i = 0; i < p.size(); ++i)
    {
        const polydem::Vec3& x = p.position[i];
        const double r = p.radius[i];
        for (int k = 0; k < 3; ++k)
        {
            lo[k] = i == 0 ? x[k] - r : std::min(lo[k], x[k] - r);
            hi[k] = i == 0 ? x[k] + r : std::max(hi[k], x[k] + r);
        }
        const double h = dot(x - origin_, up_) + r;
        height = i == 0 ? h : std::max(height, h);
        com += p.mass[i]*x;
        mass += p.mass[i];
    }
    if (mass > 0)
    {
        com = com/mass;
    }
    file()
        << t << ' ' << label(p.size()) << ' '
        << lo.x << ' ' << lo.y << ' ' << lo.z << ' '
        << hi.x << ' ' << hi.y << ' ' << hi.z << ' '
        << com.x << ' ' << com.y << ' ' << com.z << ' ' << height << endl;
}


// ************************************************************************* //

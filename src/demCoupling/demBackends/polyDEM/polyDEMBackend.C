#include "polyDEMBackend.H"
#include "addToRunTimeSelectionTable.H"
#include "polyDEM/Error.hpp"
#include "polyDEMConversions.H"
#include "polyDEM/Quaternion.hpp"
#include "polyDEM/MeshQueries.hpp"
#include "OSspecific.H"
#include "DynamicList.H"

namespace Foam
{
    defineTypeNameAndDebug(polyDEMBackend, 0);
    addToRunTimeSelectionTable(demBackend, polyDEMBackend, dictionary);
}


namespace
{
using Foam::polyDEMConversions::toVec3;
using Foam::polyDEMConversions::toVector;

//- Rigid motion of a wall at time t: x(t) = place(x(0)), and back
struct WallFrame
{
    const polydem::WallMotion& m;
    double t;

    polydem::Quaternion R() const
    {
        const polydem::Vec3 a = m.axis/norm(m.axis);
        return polydem::fromRotationVector((m.omega*t)*a);
    }

    Foam::vector forward(const Foam::vector& y) const
    {
        if (m.kind == polydem::MotionKind::translation)
        {
            return y + t*toVector(m.velocity);
        }
        if (m.kind == polydem::MotionKind::rotation)
        {
            return toVector(m.origin + polydem::rotate(R(), toVec3(y) - m.origin));
        }
        return y;
    }

    Foam::vector backward(const Foam::vector& x) const
    {
        if (m.kind == polydem::MotionKind::translation)
        {
            return x - t*toVector(m.velocity);
        }
        if (m.kind == polydem::MotionKind::rotation)
        {
            return toVector
            (
                m.origin + polydem::rotateInverse(R(), toVec3(x) - m.origin)
            );
        }
        return x;
    }

    Foam::vector rotateNormal(const Foam::vector& n) const
    {
        if (m.kind == polydem::MotionKind::rotation)
        {
            return toVector(polydem::rotate(R(), toVec3(n)));
        }
        return n;
    }

    //- Velocity of the wall's material point now at x
    Foam::vector velocity(const Foam::vector& x) const
    {
        if (m.kind == polydem::MotionKind::translation)
        {
            return toVector(m.velocity);
        }
        if (m.kind == polydem::MotionKind::rotation)
        {
            const Foam::vector a = toVector(m.axis/norm(m.axis));
            return (m.omega*a) ^ (x - toVector(m.origin));
        }
        return Foam::Zero;
    }
};
}


Foam::polyDEMBackend::polyDEMBackend
(
    const word& modelType,
    const Time& runTime,
    const dictionary& dict
)
:
    demBackend(runTime),
    parRunGuard_(),
    demProperties_
    (
        IOobject
        (
            "demProperties",
            runTime.globalPath()/runTime.constant(),
            runTime,
            IOobject::MUST_READ,
            IOobject::NO_WRITE
        )
    ),
    dem_(),
    heldForce_(),
    heldTorque_(),
    holding_(false),
    restartForces_(isFile(stateDir()/"fluidForces")),
    sample_(dict.getOrDefault<bool>("demSummary", true))
{
    try
    {
        dem_.reset(new demSimulation(runTime, demProperties_));
    }
    catch (const polydem::Error& err)
    {
        demPropertiesReader::reportError(err, demProperties_);
    }
    parRunGuard_.restore();
}


Foam::polyDEMBackend::~polyDEMBackend()
{}


Foam::scalar Foam::polyDEMBackend::timeStep() const
{
    return dem_->input().config().timeStep;
}


Foam::label Foam::polyDEMBackend::stepsPerFluidStep() const
{
    return dem_->stepsPerDeltaT();
}


Foam::wordList Foam::polyDEMBackend::typeNames() const
{
    const auto& types = dem_->input().config().types;
    wordList names(types.size());
    forAll(names, i)
    {
        names[i] = word(types[i].name);
    }
    return names;
}


Foam::scalar Foam::polyDEMBackend::typeDensity(label type) const
{
    const auto& cfg = dem_->input().config();
    return cfg.materials[cfg.types[type].material].density;
}


void Foam::polyDEMBackend::typeShape
(
    label type,
    scalar& sphericity,
    scalar& crosswiseSphericity
) const
{
    sphericity = 1;
    crosswiseSphericity = 1;
    const auto& cfg = dem_->input().config();
    const auto& t = cfg.types[type];
    if (t.shape == polydem::ShapeKind::polyhedron && t.shapeIndex >= 0)
    {
        const auto& shape = cfg.shapes[t.shapeIndex];
        sphericity = shape.sphericity;
        // Orientation average: the mean projected area of a convex body is
        // A/4 (Cauchy), so the mean crosswise sphericity (pi d^2/4)/(A/4)
        // equals the sphericity pi d^2/A. The particles' orientations are
        // not followed (ConvexShape::crosswiseSphericity has the values
        // along the principal axes).
        crosswiseSphericity = shape.sphericity;
    }
}


bool Foam::polyDEMBackend::typePolyhedron(label type, demShape& shape) const
{
    const auto& cfg = dem_->input().config();
    const auto& t = cfg.types[type];
    if (t.shape != polydem::ShapeKind::polyhedron || t.shapeIndex < 0)
    {
        return false;
    }
    const polydem::ConvexShape& s = cfg.shapes[t.shapeIndex];
    shape.vertices.setSize(s.nVertices());
    forAll(shape.vertices, i)
    {
        shape.vertices[i] = polyDEMConversions::toVector(s.vertices[i]);
    }
    const label nf = s.nFaces();
    shape.faces.setSize(nf);
    shape.normals.setSize(nf);
    shape.offsets.setSize(nf);
    for (label f = 0; f < nf; ++f)
    {
        face& fc = shape.faces[f];
        fc.setSize(s.faceStart[f + 1] - s.faceStart[f]);
        forAll(fc, k)
        {
            fc[k] = s.faceVertex[s.faceStart[f] + k];
        }
        shape.normals[f] = polyDEMConversions::toVector(s.faceNormals[f]);
        shape.offsets[f] = s.faceOffsets[f];
    }
    shape.volume = s.volume;
    return true;
}


void Foam::polyDEMBackend::particles(demParticleArrays& p) const
{
    const polydem::ParticleState s = dem_->system().engine().particles();
    const label n = s.size();
    p.setSize(n);
    for (label i = 0; i < n; ++i)
    {
        p.id[i] = label(s.id[i]);
        p.type[i] = s.type[i];
        p.radius[i] = s.radius[i];
        p.mass[i] = s.mass[i];
        p.position[i] = polyDEMConversions::toVector(s.position[i]);
        p.velocity[i] = polyDEMConversions::toVector(s.velocity[i]);
        p.omega[i] = polyDEMConversions::toVector(s.omega[i]);
        p.orientation[i] = polyDEMConversions::orientationTensor(s.orientation[i]);
    }
}


Foam::labelList Foam::polyDEMBackend::engineIds() const
{
    const polydem::ParticleState s = dem_->system().engine().particles();
    labelList ids(s.size());
    forAll(ids, i)
    {
        ids[i] = label(s.id[i]);
    }
    return ids;
}


Foam::vector Foam::polyDEMBackend::gravity() const
{
    return toVector(dem_->input().config().gravity);
}


Foam::List<Foam::demWallPoint> Foam::polyDEMBackend::wallPoints
(
    const point& x,
    scalar t
) const
{
    // The walls of the running system (removed walls are gone from it)
    const polydem::SimulationConfig& walls = dem_->system().config();
    DynamicList<demWallPoint> points
    (
        label(walls.planes.size() + walls.meshes.size())
    );

    for (const polydem::PlaneWall& pl : walls.planes)
    {
        const WallFrame frame{pl.motion, t};
        const vector p = frame.forward(toVector(pl.point));
        vector n = frame.rotateNormal(toVector(pl.normal));
        n /= mag(n);
        demWallPoint wp;
        wp.normal = n;
        wp.distance = (x - p) & n;
        wp.velocity = frame.velocity(x - wp.distance*n);
        points.append(wp);
    }

    for (const polydem::MeshWall& mw : walls.meshes)
    {
        // Nearest triangle point in the mesh's own frame
        const WallFrame frame{mw.motion, t};
        const vector y = frame.backward(x);
        scalar best = GREAT;
        vector closest(Zero);
        for (const auto& tri : mw.mesh.triangles)
        {
            const vector c = toVector
            (
                polydem::closestPointOnTriangle
                (
                    toVec3(y),
                    mw.mesh.points[tri[0]],
                    mw.mesh.points[tri[1]],
                    mw.mesh.points[tri[2]]
                )
            );
            const scalar dd = magSqr(y - c);
            if (dd < best)
            {
                best = dd;
                closest = c;
            }
        }
        const scalar dist = Foam::sqrt(best);
        // No triangles, or x on the surface (no normal)
        if (best >= GREAT || dist < VSMALL)
        {
            continue;
        }
        const vector c = frame.forward(closest);
        demWallPoint wp;
        wp.normal = (x - c)/mag(x - c);
        wp.distance = dist;
        wp.velocity = frame.velocity(c);
        points.append(wp);
    }

    List<demWallPoint> result;
    result.transfer(points);
    return result;
}


bool Foam::polyDEMBackend::restartForcesFound() const
{
    return restartForces_;
}


void Foam::polyDEMBackend::start(List<vector>& F, List<vector>& T)
{
    if (restartForces_)
    {
        readHeldForces(engineIds(), F, T);
    }
    setForces(F, T);
}


void Foam::polyDEMBackend::setForces
(
    const List<vector>& F,
    const List<vector>& T
)
{
    std::vector<polydem::Vec3> force(F.size()), torque(T.size());
    forAll(F, i)
    {
        force[i] = toVec3(F[i]);
    }
    forAll(T, i)
    {
        torque[i] = toVec3(T[i]);
    }
    try
    {
        dem_->system().engine().setExternalForces(force, torque);
    }
    catch (const polydem::Error& err)
    {
        FatalErrorInFunction
            << "polyDEM refused the fluid forces: " << err.what()
            << exit(FatalError);
    }
    heldForce_ = F;
    heldTorque_ = T;
    holding_ = true;
}


void Foam::polyDEMBackend::evolve()
{
    try
    {
        holding_ = false;
        dem_->evolve();
        if (sample_)
        {
            dem_->sample();
        }
    }
    catch (const polydem::Error& err)
    {
        demPropertiesReader::reportError(err, demProperties_);
    }
}


void Foam::polyDEMBackend::write()
{
    dem_->write();
    if (holding_ && runTime_.writeTime())
    {
        // Forces for the next advance: start() hands them over again at a
        // restart, so that the restarted run continues as if unbroken
        writeHeldForces(engineIds(), heldForce_, heldTorque_);
    }
}


Foam::scalar Foam::polyDEMBackend::time() const
{
    return dem_->system().engine().time();
}

#include "polyDEMBackend.H"
#include "addToRunTimeSelectionTable.H"
#include "polyDEM/Error.hpp"
#include "polyDEMConversions.H"

namespace Foam
{
    defineTypeNameAndDebug(polyDEMBackend, 0);
    addToRunTimeSelectionTable(demBackend, polyDEMBackend, dictionary);
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
    dem_()
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


void Foam::polyDEMBackend::setForces(const List<vector>& F)
{
    std::vector<polydem::Vec3> force(F.size());
    forAll(F, i)
    {
        force[i] = polyDEMConversions::toVec3(F[i]);
    }
    try
    {
        dem_->system().engine().setExternalForces(force, {});
    }
    catch (const polydem::Error& err)
    {
        FatalErrorInFunction
            << "polyDEM refused the fluid forces: " << err.what()
            << exit(FatalError);
    }
}


void Foam::polyDEMBackend::evolve()
{
    try
    {
        dem_->evolve();
        dem_->sample();
    }
    catch (const polydem::Error& err)
    {
        demPropertiesReader::reportError(err, demProperties_);
    }
}


void Foam::polyDEMBackend::write()
{
    dem_->write();
}


Foam::scalar Foam::polyDEMBackend::time() const
{
    return dem_->system().engine().time();
}

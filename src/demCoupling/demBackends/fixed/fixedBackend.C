#include "fixedBackend.H"
#include "addToRunTimeSelectionTable.H"
#include "demPropertiesErrors.H"
#include "unitConversion.H"
#include <string>

namespace Foam
{
    defineTypeNameAndDebug(fixedBackend, 0);
    addToRunTimeSelectionTable(demBackend, fixedBackend, dictionary);
}


Foam::fixedBackend::fixedBackend
(
    const word& modelType,
    const Time& runTime,
    const dictionary& dict
)
:
    demBackend(runTime),
    bodies_(),
    acceleration_(),
    shapes_()
{
    const List<dictionary> list(dict.lookup("bodies"));
    bodies_.setSize(list.size());
    acceleration_.setSize(list.size(), Zero);
    forAll(list, i)
    {
        const dictionary& d = list[i];
        demPropertiesErrors::checkKeys
        (
            dict, d, "bodies[" + std::to_string(i) + "]",
            {
                "shape", "radius", "size", "rotation", "position",
                "velocity", "omega", "acceleration"
            }
        );
        const word shape(d.get<word>("shape"));
        bodies_.id[i] = i;
        bodies_.mass[i] = 0;
        bodies_.position[i] = d.get<vector>("position");
        bodies_.velocity[i] = d.getOrDefault<vector>("velocity", Zero);
        bodies_.omega[i] = d.getOrDefault<vector>("omega", Zero);
        acceleration_[i] = d.getOrDefault<vector>("acceleration", Zero);
        if (shape == "sphere")
        {
            bodies_.type[i] = 0;
            bodies_.radius[i] = d.get<scalar>("radius");
            if (bodies_.radius[i] <= 0)
            {
                FatalIOErrorInFunction(d)
                    << "Body " << i << " of 'bodies' in " << dict.name()
                    << ": radius must be positive, not " << bodies_.radius[i]
                    << exit(FatalIOError);
            }
        }
        else if (shape == "box")
        {
            const vector L(d.get<vector>("size"));
            if (cmptMin(L) <= 0)
            {
                FatalIOErrorInFunction(d)
                    << "Body " << i << " of 'bodies' in " << dict.name()
                    << ": size must be positive, not " << L
                    << exit(FatalIOError);
            }
            tensor R(tensor::I);
            if (d.found("rotation"))
            {
                const dictionary& r = d.subDict("rotation");
                demPropertiesErrors::checkKeys
                (
                    dict, r, "bodies[" + std::to_string(i) + "]/rotation",
                    {"axis", "angle"}
                );
                const vector axis(r.get<vector>("axis"));
                if (mag(axis) < VSMALL)
                {
                    FatalIOErrorInFunction(r)
                        << "Body " << i << " of 'bodies' in " << dict.name()
                        << ": rotation axis must not be zero"
                        << exit(FatalIOError);
                }
                R = rotation(axis/mag(axis), degToRad(r.get<scalar>("angle")));
            }
            bodies_.orientation[i] = R;
            bodies_.type[i] = shapes_.size() + 1;
            shapes_.append(boxShape(L));
            // Bounding sphere: the half diagonal
            bodies_.radius[i] = 0.5*mag(L);
        }
        else
        {
            FatalIOErrorInFunction(d)
                << "Body " << i << " of 'bodies' in " << dict.name()
                << ": shape " << shape << "; demBackend fixed supports shape"
                << " sphere and box" << exit(FatalIOError);
        }
    }
}


Foam::tensor Foam::fixedBackend::rotation(const vector& n, const scalar a)
{
    // Rodrigues: R = cos a I + sin a [n]x + (1 - cos a) n n
    const scalar c = cos(a), s = sin(a);
    return tensor
    (
        c + (1 - c)*n.x()*n.x(),
        (1 - c)*n.x()*n.y() - s*n.z(),
        (1 - c)*n.x()*n.z() + s*n.y(),
        (1 - c)*n.y()*n.x() + s*n.z(),
        c + (1 - c)*n.y()*n.y(),
        (1 - c)*n.y()*n.z() - s*n.x(),
        (1 - c)*n.z()*n.x() - s*n.y(),
        (1 - c)*n.z()*n.y() + s*n.x(),
        c + (1 - c)*n.z()*n.z()
    );
}


Foam::demShape Foam::fixedBackend::boxShape(const vector& L)
{
    demShape s;
    const vector h = 0.5*L;
    s.vertices.setSize(8);
    for (label k = 0; k < 8; ++k)
    {
        s.vertices[k] = point
        (
            (k & 1) ? h.x() : -h.x(),
            (k & 2) ? h.y() : -h.y(),
            (k & 4) ? h.z() : -h.z()
        );
    }
    // Vertex loops counter-clockwise seen from outside
    s.faces.setSize(6);
    s.faces[0] = face(labelList({0, 4, 6, 2}));   // -x
    s.faces[1] = face(labelList({1, 3, 7, 5}));   // +x
    s.faces[2] = face(labelList({0, 1, 5, 4}));   // -y
    s.faces[3] = face(labelList({2, 6, 7, 3}));   // +y
    s.faces[4] = face(labelList({0, 2, 3, 1}));   // -z
    s.faces[5] = face(labelList({4, 5, 7, 6}));   // +z
    s.normals = List<vector>
    ({
        vector(-1, 0, 0), vector(1, 0, 0), vector(0, -1, 0),
        vector(0, 1, 0), vector(0, 0, -1), vector(0, 0, 1)
    });
    s.offsets = List<scalar>({h.x(), h.x(), h.y(), h.y(), h.z(), h.z()});
    s.volume = L.x()*L.y()*L.z();
    return s;
}


Foam::scalar Foam::fixedBackend::timeStep() const
{
    return runTime_.deltaTValue();
}


Foam::label Foam::fixedBackend::stepsPerFluidStep() const
{
    return 1;
}


Foam::wordList Foam::fixedBackend::typeNames() const
{
    wordList names(shapes_.size() + 1, word("sphere"));
    forAll(shapes_, t)
    {
        names[t + 1] = "box" + Foam::name(t);
    }
    return names;
}


bool Foam::fixedBackend::typePolyhedron(label type, demShape& shape) const
{
    if (type < 1 || type > shapes_.size())
    {
        return false;
    }
    shape = shapes_[type - 1];
    return true;
}


Foam::scalar Foam::fixedBackend::typeDensity(label) const
{
    return 0;
}


Foam::vector Foam::fixedBackend::gravity() const
{
    return Zero;
}


void Foam::fixedBackend::particles(demParticleArrays& p) const
{
    p = bodies_;
    // Prescribed uniform acceleration from the start time (the added-mass
    // check: a body accelerated from rest); zero by default
    const scalar t = runTime_.value() - runTime_.startTime().value();
    forAll(acceleration_, i)
    {
        p.position[i] += bodies_.velocity[i]*t + 0.5*acceleration_[i]*sqr(t);
        p.velocity[i] += acceleration_[i]*t;
    }
}


bool Foam::fixedBackend::restartForcesFound() const
{
    return false;
}


void Foam::fixedBackend::start(List<vector>& F, List<vector>& T)
{
    setForces(F, T);
}


void Foam::fixedBackend::setForces(const List<vector>&, const List<vector>&)
{}


void Foam::fixedBackend::evolve()
{}


void Foam::fixedBackend::write()
{}


Foam::scalar Foam::fixedBackend::time() const
{
    return runTime_.value();
}

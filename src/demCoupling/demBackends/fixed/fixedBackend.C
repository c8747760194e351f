#include "fixedBackend.H"
#include "addToRunTimeSelectionTable.H"
#include "demPropertiesErrors.H"
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
    bodies_()
{
    const List<dictionary> list(dict.lookup("bodies"));
    bodies_.setSize(list.size());
    forAll(list, i)
    {
        const dictionary& d = list[i];
        demPropertiesErrors::checkKeys
        (
            dict, d, "bodies[" + std::to_string(i) + "]",
            {"shape", "radius", "position", "velocity", "omega"}
        );
        const word shape(d.get<word>("shape"));
        if (shape != "sphere")
        {
            FatalIOErrorInFunction(d)
                << "Body " << i << " of 'bodies' in " << dict.name()
                << ": shape " << shape << "; demBackend fixed supports shape"
                << " sphere only (polyhedra come from the DEM: demBackend"
                << " polyDEM)" << exit(FatalIOError);
        }
        bodies_.id[i] = i;
        bodies_.type[i] = 0;
        bodies_.radius[i] = d.get<scalar>("radius");
        bodies_.mass[i] = 0;
        bodies_.position[i] = d.get<vector>("position");
        bodies_.velocity[i] = d.getOrDefault<vector>("velocity", Zero);
        bodies_.omega[i] = d.getOrDefault<vector>("omega", Zero);
        if (bodies_.radius[i] <= 0)
        {
            FatalIOErrorInFunction(d)
                << "Body " << i << " of 'bodies' in " << dict.name()
                << ": radius must be positive, not " << bodies_.radius[i]
                << exit(FatalIOError);
        }
    }
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
    return wordList(1, word("sphere"));
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

#include "demCloudSettings.H"
#include "error.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::demCloudSettings::demCloudSettings(const dictionary& dict)
:
    dict_(dict),
    formulation_
    (
        readChoice(dict, "formulation", {"setI", "setII"}, "setI") == "setI"
      ? couplingFormulation::setI
      : couplingFormulation::setII
    ),
    implicit_
    (
        readChoice
        (
            dict, "momentumCoupling", {"implicit", "explicit"}, "implicit"
        ) == "implicit"
    ),
    fluxVelocity_
    (
        readChoice(dict, "fluidVelocity", {"flux", "cell"}, "flux") == "flux"
    ),
    forceModelNames_(dict.get<wordList>("forceModels"))
{
    Info<< "Reading couplingProperties (demCloud)" << endl;
    Info<< "    fluid velocity at the particles: "
        << (fluxVelocity_ ? "reconstruct(alphaPhi)/voidfraction" : "cell U")
        << endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::word Foam::demCloudSettings::readChoice
(
    const dictionary& dict,
    const word& key,
    const wordList& valid,
    const word& def
)
{
    const word value(dict.getOrDefault<word>(key, def));
    if (!valid.found(value))
    {
        FatalIOErrorInFunction(dict)
            << "Unknown " << key << " '" << value << "' in " << dict.name()
            << nl << "Valid " << key << " values: " << valid
            << exit(FatalIOError);
    }
    return value;
}


void Foam::demCloudSettings::checkSubSteps
(
    const label nSubSteps,
    const scalar deltaT
) const
{
    // Sub-cycling: the DEM steps per fluid step given in couplingProperties
    // must be those of the time steps (the back end checks the division)
    if (dict_.found("demStepsPerFluidStep"))
    {
        const label n = dict_.get<label>("demStepsPerFluidStep");
        if (n != nSubSteps)
        {
            FatalIOErrorInFunction(dict_)
                << "demStepsPerFluidStep " << n << " in " << dict_.name()
                << " does not match deltaT/timeStep = " << nSubSteps
                << " (controlDict deltaT " << deltaT
                << " s, DEM time step "
                << deltaT/max(nSubSteps, 1) << " s)"
                << nl << "    deltaT must be demStepsPerFluidStep DEM steps"
                << exit(FatalIOError);
        }
    }
    Info<< "    " << nSubSteps << " DEM steps per fluid step" << endl;
}


void Foam::demCloudSettings::readParticleShapes
(
    const wordList& typeNames,
    List<scalar>& sphericity,
    List<scalar>& crosswiseSphericity,
    List<scalar>& dnByDv
) const
{
    // Defaults from the back end (1 for spheres, the shape's for polyhedra)
    const label nTypes = typeNames.size();
    dnByDv.setSize(nTypes, scalar(1));
    forAll(sphericity, t)
    {
        if (sphericity[t] != 1 || crosswiseSphericity[t] != 1)
        {
            Info<< "    particle type " << typeNames[t]
                << " (polyhedron): sphericity " << sphericity[t]
                << ", crosswise " << crosswiseSphericity[t] << endl;
        }
    }

    const dictionary shapes(dict_.subOrEmptyDict("particleShapes"));
    for (const entry& e : shapes)
    {
        const label t = typeNames.find(e.keyword());
        if (t < 0 || !e.isDict())
        {
            FatalIOErrorInFunction(shapes)
                << "Unknown particle type '" << e.keyword() << "' in "
                << shapes.name() << nl << "Valid particle types: "
                << typeNames << exit(FatalIOError);
        }
        const dictionary& d = e.dict();
        sphericity[t] = d.get<scalar>("sphericity");
        crosswiseSphericity[t] =
            d.getOrDefault<scalar>("crosswiseSphericity", sphericity[t]);
        dnByDv[t] = d.getOrDefault<scalar>("dnByDv", 1);
        if (sphericity[t] <= 0 || sphericity[t] > 1)
        {
            FatalIOErrorInFunction(d)
                << "sphericity must be in (0, 1] in " << d.name()
                << exit(FatalIOError);
        }
        Info<< "    particle type " << e.keyword() << ": sphericity "
            << sphericity[t] << ", crosswise " << crosswiseSphericity[t]
            << endl;
    }
}


void Foam::demCloudSettings::checkFreeSurface() const
{
    if (formulation_ != couplingFormulation::setI)
    {
        FatalIOErrorInFunction(dict_)
            << "formulation setII in " << dict_.name() << " is not available"
            << " with a free surface (demInterFoam): use setI" << nl
            << "    (-eps grad p in the fluid, the pressure force on the"
            << " particles alone)" << exit(FatalIOError);
    }
}

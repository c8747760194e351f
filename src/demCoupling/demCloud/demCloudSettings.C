#include "demCloudSettings.H"
#include "error.H"
#include "demPropertiesErrors.H"
#include "DynamicList.H"

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
    // With solidVelocity rigidBody the cell velocities are the default:
    // the flux reconstruction over the void fraction is poor cell by cell
    // where the void fraction jumps (inside a block at alphaMin), and with
    // it the per-cell drag fed a floating slab's heave (docs/models.md)
    fluxVelocity_
    (
        readChoice
        (
            dict, "fluidVelocity", {"flux", "cell"},
            readChoice
            (
                dict, "solidVelocity", {"centre", "rigidBody"}, "centre"
            ) == "rigidBody"
          ? "cell"
          : "flux"
        ) == "flux"
    ),
    rigidBodySolid_
    (
        readChoice
        (
            dict, "solidVelocity", {"centre", "rigidBody"}, "centre"
        ) == "rigidBody"
    ),
    twoWay_
    (
        readChoice
        (
            dict, "couplingDirection", {"twoWay", "oneWay"}, "twoWay"
        ) == "twoWay"
    ),
    forceModelNames_(dict.get<wordList>("forceModels"))
{
    Info<< "Reading couplingProperties (demCloud)" << endl;
    Info<< "    fluid velocity at the particles: "
        << (fluxVelocity_ ? "reconstruct(alphaPhi)/voidfraction" : "cell U")
        << endl;
    if (rigidBodySolid_)
    {
        Info<< "    solidVelocity rigidBody: each cell's drag towards the"
            << " particle's velocity there, Up + omega x (x_c - x_p)"
            << endl;
    }
    if (!twoWay_)
    {
        Info<< "    couplingDirection oneWay: the particles feel the fluid;"
            << " the fluid does not feel the particles (fluid fraction 1,"
            << " no momentum exchange)" << endl;
    }
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
        demPropertiesErrors::checkKeys
        (
            dict_, d, "particleShapes/" + e.keyword(),
            {"sphericity", "crosswiseSphericity", "dnByDv"}
        );
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
        if (crosswiseSphericity[t] <= 0 || crosswiseSphericity[t] > 1)
        {
            FatalIOErrorInFunction(d)
                << "crosswiseSphericity " << crosswiseSphericity[t]
                << " must be in (0, 1] in " << d.name()
                << exit(FatalIOError);
        }
        if (dnByDv[t] <= 0)
        {
            FatalIOErrorInFunction(d)
                << "dnByDv " << dnByDv[t] << " must be > 0 in " << d.name()
                << " (projected-area diameter over volume-equivalent"
                << " diameter)" << exit(FatalIOError);
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


void Foam::demCloudSettings::checkEntries
(
    const HashTable<wordList>& coeffKeys,
    const wordList& backendKeys,
    const wordHashSet& modelNames,
    const bool freeSurface
) const
{
    DynamicList<word> valid
    (wordList({
        "demBackend", "formulation", "momentumCoupling", "fluidVelocity",
        "solidVelocity", "couplingDirection",
        "forceModels", "demStepsPerFluidStep", "particleShapes",
        "locateModel", "voidFractionModel", "smoothingModel"
    }));
    valid.append(backendKeys);
    if (freeSurface)
    {
        // demInterFoam: the coupling mode and the submerged volume
        valid.append
        (
            wordList({"couplingMode", "submergedVolume",
                      "interfacePlaneBelowSizeRatio"})
        );
    }
    valid.append(coeffKeys.sortedToc());

    // Unused coefficient dictionaries of registered models are kept
    for (const entry& e : dict_)
    {
        const word& key = e.keyword();
        if
        (
            e.isDict() && !valid.found(key) && key.size() > 6
         && key.substr(key.size() - 6) == "Coeffs"
         && modelNames.found(key.substr(0, key.size() - 6))
        )
        {
            Info<< "    " << key << " in " << dict_.name()
                << ": not used (the model is not selected)" << endl;
            valid.append(key);
        }
    }

    demPropertiesErrors::checkKeys(dict_, dict_, "", valid);

    forAllConstIters(coeffKeys, iter)
    {
        const entry* e = dict_.findEntry(iter.key(), keyType::LITERAL);
        if (!e)
        {
            continue;
        }
        if (!e->isDict())
        {
            FatalIOErrorInFunction(dict_)
                << "Entry '" << iter.key() << "' in " << dict_.name()
                << " must be a dictionary of the model's coefficients"
                << nl << "    valid entries: " << iter.val()
                << exit(FatalIOError);
        }
        demPropertiesErrors::checkKeys(dict_, e->dict(), iter.key(), iter.val());
    }
}

/*---------------------------------------------------------------------------*\
  Hedra: CFD-DEM for OpenFOAM
-------------------------------------------------------------------------------
Application
    demFoam

Group
    grpLagrangianSolvers

Description
    DEM alone in an OpenFOAM case: the polyDEM engine set up from
    constant/demProperties and driven by system/controlDict (startTime,
    endTime, deltaT, writeControl, writeInterval). No mesh is needed.

    Each deltaT advances the DEM by deltaT/timeStep steps (a whole number).
    Write times get <time>/polyDEM/state (restart: a run starting from a time
    with a state continues it bit for bit), particles.vtp and walls.vtp;
    particles.pvd and walls.pvd in the case folder open the whole run in
    ParaView; with polyhedral particle types also polyhedra.vtp (the true
    shapes) and polyhedra.pvd. postProcessing/demFoam/<startTime>/summary.dat
    has a line per deltaT; monitors (planeFlux, reposeAngle, boundingBox) write to
    postProcessing/<name>/<startTime>/<name>.dat.

    Input syntax: docs/demProperties.md.

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "Time.H"
#include "IOdictionary.H"

#include "demSimulation.H"

#include "polyDEM/Error.hpp"

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "DEM (polyDEM engine) alone, set up by constant/demProperties"
    );
    argList::noParallel();

    #include "setRootCase.H"
    #include "createTime.H"

    // Engine errors (polydem::Error) name the demProperties entry at fault
    const fileName propertiesPath(runTime.constantPath()/"demProperties");
    const IOdictionary* propertiesPtr = nullptr;

    try
    {
        #include "createDem.H"
        propertiesPtr = &demProperties;

        Info<< "\nStarting time loop\n" << endl;

        while (runTime.run())
        {
            ++runTime;

            dem.evolve();
            dem.sample();
            dem.write();

            runTime.write();
        }

        dem.report(true);
        runTime.printExecutionTime(Info);
    }
    catch (const polydem::Error& err)
    {
        if (propertiesPtr)
        {
            demPropertiesReader::reportError(err, *propertiesPtr);
        }
        // Failed while constructing: read the dictionary again to name it
        IOdictionary demProperties
        (
            IOobject
            (
                "demProperties",
                runTime.constant(),
                runTime,
                IOobject::MUST_READ,
                IOobject::NO_WRITE
            )
        );
        demPropertiesReader::reportError(err, demProperties);
    }

    Info<< "End\n" << endl;

    return 0;
}


// ************************************************************************* //

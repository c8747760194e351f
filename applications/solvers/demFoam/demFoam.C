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

    Parallel (-parallel, e.g. a stage of a decomposed coupled case run with
    foamJob -parallel): the DEM is not decomposed. The master rank runs it
    (with its OpenMP threads or GPU) and reads and writes the case folder,
    <case>/<time>/polyDEM and <case>/*.pvd, as a serial run does; the other
    ranks only follow the time loop. Extra ranks give no speed-up.

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "Time.H"
#include "IOdictionary.H"

#include "demSimulation.H"

#include "polyDEM/Error.hpp"

#include <memory>

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "DEM (polyDEM engine) alone, set up by constant/demProperties"
    );

    #include "setRootCase.H"
    #include "createTime.H"

    // Engine errors (polydem::Error) name the demProperties entry at fault
    autoPtr<IOdictionary> demPropertiesPtr;
    std::unique_ptr<demSimulation> demPtr;

    try
    {
        #include "createDem.H"

        Info<< "\nStarting time loop\n" << endl;

        while (runTime.run())
        {
            ++runTime;

            if (demPtr)
            {
                demPtr->evolve();
                demPtr->sample();
                demPtr->write();
            }

            runTime.write();
        }

        if (demPtr)
        {
            demPtr->report(true);
        }
        runTime.printExecutionTime(Info);
    }
    catch (const polydem::Error& err)
    {
        // Only the rank that runs the DEM throws these (FatalIOError ends
        // the parallel job)
        if (demPropertiesPtr)
        {
            demPropertiesReader::reportError(err, demPropertiesPtr());
        }
        // Failed while reading the dictionary: read it again to name it
        Pstream::parRun() = false;
        IOdictionary demProperties
        (
            IOobject
            (
                "demProperties",
                runTime.globalPath()/runTime.constant(),
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

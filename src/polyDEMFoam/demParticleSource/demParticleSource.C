/*---------------------------------------------------------------------------*\
  Hedra: CFD-DEM for OpenFOAM
-------------------------------------------------------------------------------
Description
    The DEM particles in the registry (see demParticleSource.H).

\*---------------------------------------------------------------------------*/

#include "demParticleSource.H"

namespace Foam
{
    defineTypeNameAndDebug(demParticleSource, 0);
}

const Foam::word Foam::demParticleSource::registryName("demParticles");


Foam::demParticleSource::demParticleSource(const Time& runTime)
:
    regIOobject
    (
        IOobject
        (
            registryName,
            runTime.timeName(),
            runTime,
            IOobject::NO_READ,
            IOobject::NO_WRITE,
            true
        )
    )
{}


const Foam::demParticleSource* Foam::demParticleSource::find
(
    const objectRegistry& obr
)
{
    return obr.findObject<demParticleSource>(registryName);
}

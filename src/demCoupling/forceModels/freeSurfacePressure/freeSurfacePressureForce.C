#include "freeSurfacePressureForce.H"
#include "addToRunTimeSelectionTable.H"
#include "fvc.H"

namespace Foam
{
    makeForceModel(freeSurfacePressureForce);
}


Foam::freeSurfacePressureForce::freeSurfacePressureForce
(
    const word& modelType,
    const dictionary& dict,
    const forceModelContext& context
)
:
    forceModel(modelType, dict, context)
{}


void Foam::freeSurfacePressureForce::cacheFields(const bool store)
{
    if (!store)
    {
        dynamicGradPP_.clear();
        return;
    }

    const demFreeSurface* fs = context_.freeSurface();
    if (!fs)
    {
        const dictionary& dict = context_.settings().dict();
        FatalIOErrorInFunction(dict)
            << "forceModels in " << dict.name() << " holds "
            << typeName << ", which needs a two-phase (VOF) solver"
            << " (demInterFoam)" << nl
            << "    use pressureGradient with a single-phase solver"
            << exit(FatalIOError);
    }

    // grad p - rho g in the face form of the momentum equation (zero in a
    // fluid at rest)
    const volVectorField dynamicGradP
    (
        fvc::reconstruct
        (
            (fvc::snGrad(fs->p_rgh) + fs->ghf*fvc::snGrad(fs->rho))
           *context_.mesh().magSf()
        )
    );
    dynamicGradPP_ = context_.sample(dynamicGradP);
}


void Foam::freeSurfacePressureForce::addForce
(
    const particleSample& s,
    particleForce& f
) const
{
    const demFreeSurface& fs = *context_.freeSurface();
    const scalar sf = s.submergedFraction;
    const scalar rhoDisplaced = fs.rho1*sf + fs.rho2*(1 - sf);
    f.Fparticle +=
        -s.Vp*dynamicGradPP_[s.index] - s.Vp*rhoDisplaced*fs.g;
    // Righting moment: the buoyancy of the submerged part at its centroid,
    // the emerged part's (whose arm is the opposite, weighted) folded in
    f.Tparticle += -(fs.rho1 - fs.rho2)*sf*s.Vp*(s.buoyancyArm ^ fs.g);
}

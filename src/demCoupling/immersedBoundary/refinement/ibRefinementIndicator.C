#include "ibRefinementIndicator.H"

Foam::ibRefinementIndicator::ibRefinementIndicator
(
    const fvMesh& mesh,
    const dictionary& ibDict
)
:
    mesh_(mesh),
    band_(ibDict.subOrEmptyDict("refinement").getOrDefault<scalar>("band", -1)),
    indicator_
    (
        IOobject
        (
            "ibRefinement",
            mesh.time().timeName(),
            mesh,
            IOobject::NO_READ,
            IOobject::NO_WRITE
        ),
        mesh,
        dimensionedScalar(dimless, Zero),
        "zeroGradient"
    )
{
    if (ibDict.found("refinement") && ibDict.subDict("refinement").found("band") && band_ < 0)
    {
        FatalIOErrorInFunction(ibDict.subDict("refinement"))
            << "band must be >= 0 [m] in " << ibDict.subDict("refinement").name()
            << ", not " << band_ << exit(FatalIOError);
    }
}


void Foam::ibRefinementIndicator::update(const UList<ibBody>& bodies)
{
    scalar band = band_;
    if (band < 0)
    {
        band = 0;
        for (const ibBody& b : bodies)
        {
            band = max(band, b.radius);
        }
    }

    const vectorField& C = mesh_.C();
    const scalarField& V = mesh_.V();
    scalarField& f = indicator_.primitiveFieldRef();
    f = 0;
    forAll(C, celli)
    {
        // Half the diagonal of a cube of the cell's volume (hexahedra)
        const scalar h = 0.5*sqrt(3.0)*cbrt(V[celli]);
        for (const ibBody& b : bodies)
        {
            const scalar reach = b.radius + band + h;
            if (magSqr(C[celli] - b.position) < reach*reach)
            {
                f[celli] = 1;
                break;
            }
        }
    }
    indicator_.correctBoundaryConditions();
}

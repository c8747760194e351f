#include "ibRefinementIndicator.H"
#include "labelIOList.H"

Foam::ibRefinementIndicator::ibRefinementIndicator
(
    const fvMesh& mesh,
    const dictionary& ibDict,
    const bool freeSurfaceAvailable
)
:
    mesh_(mesh),
    band_(ibDict.subOrEmptyDict("refinement").getOrDefault<scalar>("band", -1)),
    freeSurface_
    (
        ibDict.subOrEmptyDict("refinement").getOrDefault<bool>
        (
            "freeSurface",
            false
        )
    ),
    surfaceBand_
    (
        ibDict.subOrEmptyDict("refinement").getOrDefault<scalar>
        (
            "surfaceBand",
            -1
        )
    ),
    refineInterval_(0),
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
    const IOdictionary meshDict
    (
        IOobject
        (
            "dynamicMeshDict",
            mesh.time().constant(),
            mesh,
            IOobject::READ_IF_PRESENT,
            IOobject::NO_WRITE,
            false
        )
    );
    if
    (
        meshDict.getOrDefault<word>("dynamicFvMesh", "staticFvMesh")
     == "dynamicRefineFvMesh"
    )
    {
        const dictionary& coeffs =
            meshDict.optionalSubDict("dynamicRefineFvMeshCoeffs");
        const word field(coeffs.get<word>("field"));
        if (field != indicator_.name())
        {
            FatalIOErrorInFunction(coeffs)
                << "dynamicRefineFvMeshCoeffs field " << field << " in "
                << meshDict.objectPath() << " with resolved bodies"
                << " (refinement around them): expected field "
                << indicator_.name() << ", which marks the cells around the"
                << " bodies (and the free surface with refinement"
                << " { freeSurface yes; } in demInterFoam)" << nl
                << "    A refinement that follows another field would not"
                << " wrap the bodies in fine cells and would merge cells a"
                << " body cuts, where the water is not kept"
                << exit(FatalIOError);
        }
        refineInterval_ = coeffs.get<label>("refineInterval");
    }

    if (ibDict.subOrEmptyDict("refinement").found("surfaceBand"))
    {
        const dictionary& rd = ibDict.subDict("refinement");
        if (!freeSurface_)
        {
            FatalIOErrorInFunction(rd)
                << "surfaceBand in " << rd.name() << " limits the refined"
                << " free surface to the bodies' neighbourhood: it needs"
                << " freeSurface yes" << exit(FatalIOError);
        }
        if (surfaceBand_ < 0)
        {
            FatalIOErrorInFunction(rd)
                << "surfaceBand must be >= 0 [m] in " << rd.name()
                << ", not " << surfaceBand_ << exit(FatalIOError);
        }
    }
    if (freeSurface_ && !freeSurfaceAvailable)
    {
        FatalIOErrorInFunction(ibDict.subDict("refinement"))
            << "freeSurface yes in " << ibDict.subDict("refinement").name()
            << ": this solver has no free surface (demInterFoam has)"
            << exit(FatalIOError);
    }
}


Foam::scalar Foam::ibRefinementIndicator::mark
(
    const UList<ibBody>& bodies,
    const scalar band,
    const point& c,
    const scalar h,
    const label level
)
{
    scalar value = 0;
    for (const ibBody& b : bodies)
    {
        const scalar d2 = magSqr(c - b.position);
        const scalar reach = b.radius + band + h;
        if (d2 < reach*reach)
        {
            return 1;
        }
        const scalar keep = b.radius + band + 5*h;
        if (level > 0 && d2 < keep*keep)
        {
            value = 0.5;
        }
    }
    return value;
}


void Foam::ibRefinementIndicator::update
(
    const UList<ibBody>& bodies,
    const volScalarField* alpha
)
{
    // dynamicRefineFvMesh reads the field only in the steps it refines
    if
    (
        refineInterval_ <= 0
     || mesh_.time().timeIndex() % refineInterval_ != 0
    )
    {
        return;
    }

    scalar band = band_;
    if (band < 0)
    {
        band = 0;
        for (const ibBody& b : bodies)
        {
            band = max(band, b.radius);
        }
    }

    // The refinement level of each cell (hexRef8's cellLevel, registered by
    // dynamicRefineFvMesh; none on a static mesh)
    const labelIOList* levelPtr =
        mesh_.findObject<labelIOList>("cellLevel");

    const vectorField& C = mesh_.C();
    const scalarField& V = mesh_.V();
    scalarField& f = indicator_.primitiveFieldRef();
    f = 0;
    forAll(C, celli)
    {
        // Half the diagonal of a cube of the cell's volume (hexahedra)
        const scalar h = 0.5*sqrt(3.0)*cbrt(V[celli]);
        // A cell made by a refinement is kept (0.5: neither refined nor
        // merged with lowerRefineLevel = unrefineLevel = 0.5) as long as its
        // parent could be selected again. dynamicRefineFvMesh refines a
        // cell when one of its corners has a mean of the surrounding cells
        // above 0.5, so a parent P is refined when a marked cell Q touches
        // one of its corners: P's centre lies within h_P + h_Q of Q's, and
        // Q (refined to the finest level, h_Q <= h_c) within its reach
        // r_b + band + h_Q of the body, so P's children lie within
        // r_b + band + 2 h_Q + h_P + h_c <= r_b + band + 5 h_c. Without the
        // keep the cells at the band's edge were refined and merged in turn
        // every step (112 of 11 000 cells of a floating cube's mesh)
        const label level = levelPtr ? (*levelPtr)[celli] : 0;
        f[celli] = mark(bodies, band, C[celli], h, level);
    }
    if (freeSurface_)
    {
        if (!alpha)
        {
            FatalErrorInFunction
                << "freeSurface: no phase fraction given" << abort(FatalError);
        }
        const scalarField& a = alpha->primitiveField();
        forAll(f, celli)
        {
            if (!(a[celli] > 0.001 && a[celli] < 0.999) || f[celli] == 1)
            {
                continue;
            }
            if (surfaceBand_ < 0)
            {
                f[celli] = 1;
                continue;
            }
            // Near a body only, with the kept cells at the edge as above
            f[celli] = max
            (
                f[celli],
                mark
                (
                    bodies,
                    surfaceBand_,
                    C[celli],
                    0.5*sqrt(3.0)*cbrt(V[celli]),
                    levelPtr ? (*levelPtr)[celli] : 0
                )
            );
        }
    }
    indicator_.correctBoundaryConditions();
}

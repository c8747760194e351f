#include "implicitDiffusionSmoothing.H"
#include "addToRunTimeSelectionTable.H"
#include "fvm.H"
#include "fvMatrices.H"
#include "zeroGradientFvPatchFields.H"

namespace Foam
{
    defineTypeNameAndDebug(implicitDiffusionSmoothing, 0);
    addToRunTimeSelectionTable(smoothingModel, implicitDiffusionSmoothing, dictionary);
}


Foam::implicitDiffusionSmoothing::implicitDiffusionSmoothing
(
    const word& modelType,
    const dictionary& dict,
    const fvMesh& mesh
)
:
    smoothingModel(modelType, dict, mesh),
    lengthScale_(coeffs_.get<scalar>("lengthScale")),
    tolerance_(coeffs_.getOrDefault<scalar>("tolerance", defaultTolerance))
{
    if (lengthScale_ <= 0)
    {
        FatalIOErrorInFunction(coeffs_)
            << "lengthScale must be > 0 in " << coeffs_.name()
            << exit(FatalIOError);
    }
    if (!(tolerance_ > 0 && tolerance_ <= 1e-3))
    {
        FatalIOErrorInFunction(coeffs_)
            << "Entry 'tolerance' " << tolerance_ << " in " << coeffs_.name()
            << ": expected a linear-solver tolerance in (0, 1e-3]"
            << " (default " << defaultTolerance << ")"
            << exit(FatalIOError);
    }
}


template<class Type>
void Foam::implicitDiffusionSmoothing::smoothField
(
    GeometricField<Type, fvPatchField, volMesh>& f
) const
{
    typedef GeometricField<Type, fvPatchField, volMesh> fieldType;

    fieldType g
    (
        IOobject(f.name() + "Smooth", mesh_.time().timeName(), mesh_),
        mesh_,
        dimensioned<Type>(f.dimensions(), Zero),
        zeroGradientFvPatchField<Type>::typeName
    );
    g.primitiveFieldRef() = f.primitiveField();
    g.correctBoundaryConditions();

    const dimensionedScalar L2("L2", dimArea, sqr(lengthScale_));
    fvMatrix<Type> eqn
    (
        fvm::Sp(dimensionedScalar("one", dimless, 1), g)
      - fvm::laplacian(L2, g)
     ==
        f
    );
    // Linear solver: PCG/DIC (the matrix is symmetric)
    dictionary solverDict;
    solverDict.add("solver", "PCG");
    solverDict.add("preconditioner", "DIC");
    solverDict.add("tolerance", tolerance_);
    solverDict.add("relTol", 0);
    eqn.solve(solverDict);

    if (tolerance_ > defaultTolerance)
    {
        // Sum over cells of (A g) is sum V g (the Laplacian's rows sum to
        // zero with zero-gradient walls and coupled interfaces), so adding
        // the residual b - A g back makes sum V g = sum V f0 exactly
        g.primitiveFieldRef() += eqn.residual()/mesh_.V().field();
    }

    f.primitiveFieldRef() = g.primitiveField();
    f.correctBoundaryConditions();
}


void Foam::implicitDiffusionSmoothing::smooth(volScalarField& f) const
{
    smoothField(f);
}


void Foam::implicitDiffusionSmoothing::smooth(volVectorField& f) const
{
    smoothField(f);
}

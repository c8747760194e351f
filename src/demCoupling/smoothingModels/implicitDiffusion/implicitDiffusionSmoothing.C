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
    lengthScale_(coeffs_.get<scalar>("lengthScale"))
{
    if (lengthScale_ <= 0)
    {
        FatalIOErrorInFunction(coeffs_)
            << "lengthScale must be > 0 in " << coeffs_.name()
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
    // Linear solver: PCG/DIC to 1e-14 (the matrix is symmetric)
    dictionary solverDict;
    solverDict.add("solver", "PCG");
    solverDict.add("preconditioner", "DIC");
    solverDict.add("tolerance", 1e-14);
    solverDict.add("relTol", 0);
    eqn.solve(solverDict);

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

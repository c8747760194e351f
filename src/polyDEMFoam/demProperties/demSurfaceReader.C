/*---------------------------------------------------------------------------*\
  Hedra: CFD-DEM for OpenFOAM
-------------------------------------------------------------------------------
Description
    STL files named in demProperties (see demSurfaceReader.H).

\*---------------------------------------------------------------------------*/

#include "demSurfaceReader.H"
#include "IOstreams.H"

#include "polyDEM/Error.hpp"
#include "polyDEM/StlReader.hpp"

// * * * * * * * * * * * * * * Static Functions  * * * * * * * * * * * * * * //

Foam::fileName Foam::demSurfaceReader::resolve
(
    const dictionary& demProperties,
    const fileName& file
)
{
    fileName f(file);
    f.expand();
    if (f.isAbsolute())
    {
        return f;
    }
    // demProperties' name is <case>/constant/demProperties
    return fileName(demProperties.name()).path()/"triSurface"/f;
}


polydem::TriangleMesh Foam::demSurfaceReader::read
(
    const dictionary& demProperties,
    const dictionary& entryDict,
    const word& fileKey,
    const std::string& entryPath
)
{
    const fileName file(resolve(demProperties, entryDict.get<fileName>(fileKey)));
    const scalar scale = entryDict.getOrDefault<scalar>("scale", 1.0);
    try
    {
        polydem::StlReadInfo info;
        polydem::TriangleMesh mesh = polydem::readStl(file, scale, &info);
        Info<< "    " << entryPath.c_str() << ": " << file << ", "
            << mesh.size() << " triangles";
        if (info.degenerateDropped)
        {
            Info<< " (" << label(info.degenerateDropped)
                << " degenerate dropped)";
        }
        Info<< endl;
        return mesh;
    }
    catch (const polydem::Error& err)
    {
        const entry* e = entryDict.findEntry(fileKey, keyType::LITERAL);
        FatalIOError
        (
            FUNCTION_NAME, __FILE__, __LINE__,
            demProperties.name(),
            e ? e->startLineNumber() : -1
        )
            << "Cannot use the surface file " << file << nl
            << "    named in entry '" << entryPath.c_str() << "' of "
            << demProperties.name() << nl
            << "    " << err.message().c_str() << nl
            << exit(FatalIOError);
    }
    return polydem::TriangleMesh();
}


// ************************************************************************* //

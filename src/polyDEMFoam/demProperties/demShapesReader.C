/*---------------------------------------------------------------------------*\
  Hedra: CFD-DEM for OpenFOAM
-------------------------------------------------------------------------------
Description
    demProperties 'particleTypes': spheres and polyhedra, the polyhedra from
    a table of geometry generators (see demShapesReader.H).

\*---------------------------------------------------------------------------*/

#include "demShapesReader.H"
#include "demMaterialsReader.H"
#include "demPropertiesErrors.H"
#include "demSurfaceReader.H"
#include "IOstreams.H"
#include "vector.H"

#include "polyDEM/Error.hpp"
#include "polyDEM/StlReader.hpp"

#include "ConvexShapeBuilder.hpp"
#include "ShapeFiles.hpp"
#include "ShapeGenerators.hpp"

#include <cmath>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace Foam
{

typedef demShapesReader::geometryInput geometryInput;

//- STL (or OBJ) point set: its convex hull. A surface that is not convex
//  (hull volume above the enclosed volume) is refused unless
//  'convexHull true;' asks for its hull.
static std::vector<polydem::ConvexShape> makeHullOfFile
(
    const geometryInput& in,
    label
)
{
    const dictionary& gd = in.dict();
    const dictionary& dict = in.demProperties();
    const fileName file(demSurfaceReader::resolve(dict, gd.get<fileName>("file")));
    const scalar scale = gd.getOrDefault<scalar>("scale", 1.0);
    const bool takeHull = gd.getOrDefault<bool>("convexHull", false);
    std::vector<polydem::ConvexShape> result;
    try
    {
        std::vector<polydem::Vec3> points;
        double enclosed = -1;
        if (file.hasExt("obj") || file.hasExt("OBJ"))
        {
            points = polydem::readPointSet(file);
            for (auto& x : points)
            {
                x = scale*x;
            }
        }
        else
        {
            const polydem::TriangleMesh mesh = polydem::readStl(file, scale);
            points = mesh.points;
            // Enclosed volume (divergence theorem; orientation-free)
            double v6 = 0;
            for (const auto& t : mesh.triangles)
            {
                v6 += dot(mesh.points[t[0]], cross(mesh.points[t[1]], mesh.points[t[2]]));
            }
            enclosed = std::abs(v6)/6.0;
        }
        polydem::ConvexShape s = polydem::buildConvexShape(points, in.typeName());
        if (enclosed >= 0 && !takeHull && s.volume > (1 + 1e-3)*enclosed)
        {
            const entry* e = gd.findEntry("file", keyType::LITERAL);
            FatalIOError
            (
                FUNCTION_NAME, __FILE__, __LINE__,
                dict.name(), e ? e->startLineNumber() : -1
            )
                << "The surface " << file << " of entry '"
                << (in.where() + "/file").c_str() << "' of " << dict.name()
                << " is not convex (or not closed):" << nl
                << "    its convex hull has volume " << s.volume
                << " m3, the surface encloses " << enclosed << " m3" << nl
                << "    polyhedral particles are convex: give a convex"
                << " surface, or set 'convexHull true;' to use its hull"
                << nl << exit(FatalIOError);
        }
        s.check();
        result.push_back(std::move(s));
    }
    catch (const polydem::Error& err)
    {
        in.fail(err, "file", file);
    }
    return result;
}


static std::vector<polydem::ConvexShape> makeRocks
(
    const geometryInput& in,
    label nShapes
)
{
    const dictionary& gd = in.dict();
    const scalar d = in.positive("equivalentDiameter");
    const scalar el = gd.getOrDefault<scalar>("elongation", 1.0);
    const scalar fl = gd.getOrDefault<scalar>("flatness", 1.0);
    const label np = gd.getOrDefault<label>("points", 20);
    const label seed = gd.getOrDefault<label>("seed", 1);
    if (!(el > 0 && el <= 1) || !(fl > 0 && fl <= 1) || np < 4)
    {
        FatalIOErrorInFunction(gd)
            << "Entry '" << in.where().c_str() << "': elongation and"
            << " flatness must be in (0, 1], points >= 4, in "
            << in.demProperties().name() << nl << exit(FatalIOError);
    }
    std::vector<polydem::ConvexShape> result;
    for (label k = 0; k < nShapes; ++k)
    {
        result.push_back
        (
            polydem::makeRock(d, el, fl, int(np), uint64_t(seed + k))
        );
    }
    return result;
}


static std::vector<polydem::ConvexShape> makeBox
(
    const geometryInput& in,
    label
)
{
    const vector a(in.dict().get<vector>("size"));
    if (!(a.x() > 0 && a.y() > 0 && a.z() > 0))
    {
        FatalIOErrorInFunction(in.dict())
            << "Entry '" << in.where().c_str() << "/size' must be"
            << " positive edges (a b c) in " << in.demProperties().name()
            << nl << exit(FatalIOError);
    }
    return {polydem::makeBox(a.x(), a.y(), a.z())};
}


static std::vector<polydem::ConvexShape> makeCube(const geometryInput& in, label)
{
    return {polydem::makeCube(in.positive("edge"))};
}


static std::vector<polydem::ConvexShape> makeTetrahedron(const geometryInput& in, label)
{
    return {polydem::makeTetrahedron(in.positive("equivalentDiameter"))};
}


static std::vector<polydem::ConvexShape> makeOctahedron(const geometryInput& in, label)
{
    return {polydem::makeOctahedron(in.positive("equivalentDiameter"))};
}


static std::vector<polydem::ConvexShape> makeDodecahedron(const geometryInput& in, label)
{
    return {polydem::makeDodecahedron(in.positive("equivalentDiameter"))};
}


static std::vector<polydem::ConvexShape> makeIcosahedron(const geometryInput& in, label)
{
    return {polydem::makeIcosahedron(in.positive("equivalentDiameter"))};
}


static std::vector<polydem::ConvexShape> makeSettling(const geometryInput& in, label)
{
    const scalar d = in.positive("equivalentDiameter");
    const scalar aspect = in.positive("aspectRatio");
    const int facets = int(in.dict().get<label>("facets"));
    return {polydem::makeSettlingParticle(d, aspect, facets)};
}

} // End namespace Foam


// * * * * * * * * * * * * * * * geometryInput  * * * * * * * * * * * * * * //

Foam::demShapesReader::geometryInput::geometryInput
(
    const dictionary& demProperties,
    const dictionary& geometry,
    const word& typeName
)
:
    demProperties_(demProperties),
    geometry_(geometry),
    typeName_(typeName),
    where_("particleTypes/" + typeName + "/geometry")
{}


Foam::scalar Foam::demShapesReader::geometryInput::positive
(
    const word& key
) const
{
    const scalar v = geometry_.get<scalar>(key);
    if (!(v > 0))
    {
        FatalIOErrorInFunction(geometry_)
            << "Entry '" << (where_ + "/" + key).c_str() << "' must be positive,"
            << " got " << v << " in " << demProperties_.name() << nl
            << exit(FatalIOError);
    }
    return v;
}


void Foam::demShapesReader::geometryInput::fail
(
    const polydem::Error& err,
    const word& key,
    const std::string& file
) const
{
    const entry* e = geometry_.findEntry(key, keyType::LITERAL);
    FatalIOError
    (
        FUNCTION_NAME, __FILE__, __LINE__,
        demProperties_.name(), e ? e->startLineNumber() : -1
    )
        << "Cannot make the polyhedron of entry '" << (where_ + "/" + key).c_str()
        << "' of " << demProperties_.name() << nl;
    if (!file.empty())
    {
        FatalIOError<< "    file " << file.c_str() << nl;
    }
    FatalIOError
        << "    " << err.message().c_str() << nl
        << "    (at most " << polydem::kMaxPolyhedronVertices << " vertices and "
        << polydem::kMaxPolyhedronFaces << " faces per shape)" << nl
        << exit(FatalIOError);
}


// * * * * * * * * * * * * Private Static Functions  * * * * * * * * * * * * //

const std::vector<Foam::demShapesReader::generator>&
Foam::demShapesReader::generators()
{
    // name, several shapes, entry blamed for a refused hull, generator
    // and the entries it reads
    typedef wordList keys;
    const keys dEq({"equivalentDiameter"});
    static const std::vector<generator> table
    ({
        generator{"stl", false, "", &makeHullOfFile, keys({"file", "scale", "convexHull"})},
        generator
        {
            "rock", true, "points", &makeRocks,
            keys({"equivalentDiameter", "elongation", "flatness", "points", "seed"})
        },
        generator{"box", false, "type", &makeBox, keys({"size"})},
        generator{"cube", false, "type", &makeCube, keys({"edge"})},
        generator{"tetrahedron", false, "type", &makeTetrahedron, dEq},
        generator{"octahedron", false, "type", &makeOctahedron, dEq},
        generator{"dodecahedron", false, "type", &makeDodecahedron, dEq},
        generator{"icosahedron", false, "type", &makeIcosahedron, dEq},
        generator
        {
            "settling", false, "facets", &makeSettling,
            keys({"equivalentDiameter", "aspectRatio", "facets"})
        }
    });
    return table;
}


std::vector<polydem::ConvexShape> Foam::demShapesReader::readGeometry
(
    const dictionary& dict,
    const dictionary& td,
    const word& typeName
)
{
    const dictionary& gd = td.subDict("geometry");
    const std::string where = "particleTypes/" + typeName + "/geometry";
    const std::vector<generator>& table = generators();
    wordList kinds(label(table.size()));
    forAll(kinds, i)
    {
        kinds[i] = table[i].name;
    }
    const generator& gen =
        table[demPropertiesErrors::selectName
        (
            gd, "type", kinds, "polyhedron geometry type"
        )];

    wordList valid(gen.keys);
    valid.append("type");
    valid.append("shapes");
    demPropertiesErrors::checkKeys(dict, gd, where, valid);

    // Number of shapes: several only for random rocks (one per seed)
    const label nShapes = gd.getOrDefault<label>("shapes", 1);
    if (nShapes < 1 || (nShapes > 1 && !gen.manyShapes))
    {
        FatalIOErrorInFunction(gd)
            << "Entry '" << where.c_str() << "/shapes' must be >= 1, and more"
            << " than one only for 'type rock' (one random rock per seed), in "
            << dict.name() << nl << exit(FatalIOError);
    }

    const geometryInput in(dict, gd, typeName);
    std::vector<polydem::ConvexShape> result;
    if (gen.sizeEntry.empty())
    {
        // The generator reports its own errors (the file it read)
        result = gen.make(in, nShapes);
    }
    else
    {
        try
        {
            result = gen.make(in, nShapes);
            for (auto& s : result)
            {
                s.check();
            }
        }
        catch (const polydem::Error& err)
        {
            // Blame the entry that sets the size of the hull
            in.fail(err, gen.sizeEntry, "");
        }
    }
    for (size_t k = 0; k < result.size(); ++k)
    {
        result[k].name = typeName + (result.size() > 1 ? "_" + std::to_string(k) : "");
    }
    return result;
}


// * * * * * * * * * * * * * * Static Functions  * * * * * * * * * * * * * * //

//- Psi = pi^(1/3) (6V)^(2/3) / A of a 39:39:1 square plate is 0.20: flatter
//  ice plates than that are floes, not brash-ice blocks or grains
const Foam::scalar Foam::demShapesReader::minSphericity = 0.2;


std::vector<Foam::demShapesReader::userType> Foam::demShapesReader::read
(
    const dictionary& dict,
    polydem::SimulationConfig& config
)
{
    std::vector<userType> userTypes;
    const dictionary& d = dict.subDict("particleTypes");
    static const wordList shapes({"sphere", "polyhedron"});
    for (const entry& e : d)
    {
        if (!e.isDict())
        {
            FatalIOErrorInFunction(d)
                << "Entry 'particleTypes/" << e.keyword()
                << "' must be a dictionary in " << dict.name() << nl
                << exit(FatalIOError);
        }
        const dictionary& td = e.dict();
        demPropertiesErrors::checkKeys
        (
            dict, td, "particleTypes/" + e.keyword(),
            {"shape", "material", "diameter", "geometry"}
        );
        userType u;
        u.name = e.keyword();
        u.firstType = int(config.types.size());
        polydem::ParticleType t;
        t.name = e.keyword();
        t.material = demMaterialsReader::materialIndex(config, td, "material");
        const label shape = demPropertiesErrors::selectNameOrDefault
        (
            td, "shape", shapes, "particle shape", 0
        );
        if (shape == 0)
        {
            t.shape = polydem::ShapeKind::sphere;
            t.radius = 0.5*td.get<scalar>("diameter");
            config.types.push_back(t);
        }
        else
        {
            if (config.contact.law != polydem::ContactLaw::overlapVolume)
            {
                const entry* le = dict.subDict("contactModel").findEntry("law", keyType::LITERAL);
                FatalIOError
                (
                    FUNCTION_NAME, __FILE__, __LINE__,
                    dict.name(), le ? le->startLineNumber() : -1
                )
                    << "Particle type '" << e.keyword() << "' is a polyhedron:"
                    << " polyhedral particles need 'law overlapVolume;' in"
                    << " entry 'contactModel/law' of " << dict.name()
                    << " (with volumetricStiffness [N/m3])" << nl
                    << exit(FatalIOError);
            }
            u.polyhedron = true;
            t.shape = polydem::ShapeKind::polyhedron;
            std::vector<polydem::ConvexShape> ss = readGeometry(dict, td, e.keyword());
            u.nTypes = int(ss.size());
            for (auto& s : ss)
            {
                t.shapeIndex = int(config.shapes.size());
                t.radius = s.boundingRadius;
                Info<< "    particle type " << e.keyword() << ": shape "
                    << s.name.c_str() << ", " << s.nVertices() << " vertices, "
                    << s.nFaces() << " faces, d_eq " << s.equivalentDiameter
                    << " m, bounding diameter " << 2*s.boundingRadius
                    << " m, sphericity " << s.sphericity << endl;
                // A sliver (a 4-point rock, a degenerate hull) has no
                // stable time step and a volumetric overlap that jumps
                // with orientation: refuse it with its figure
                if (!(s.sphericity >= minSphericity))
                {
                    FatalIOErrorInFunction(td)
                        << "Particle type '" << e.keyword() << "' of "
                        << dict.name() << ": shape " << s.name.c_str()
                        << " has sphericity " << s.sphericity
                        << ", below the floor " << minSphericity
                        << " (that of a 39:39:1 square plate)" << nl
                        << "    " << s.nVertices() << " vertices, "
                        << s.nFaces() << " faces; check entry 'particleTypes/"
                        << e.keyword() << "/geometry' (for type rock: more "
                        << "points, or less extreme elongation and flatness)"
                        << nl << exit(FatalIOError);
                }
                config.shapes.push_back(std::move(s));
                config.types.push_back(t);
            }
        }
        userTypes.push_back(u);
    }
    if (config.types.empty())
    {
        FatalIOErrorInFunction(d)
            << "Entry 'particleTypes' of " << dict.name()
            << " defines no particle type" << nl << exit(FatalIOError);
    }
    return userTypes;
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
  Hedra: CFD-DEM for OpenFOAM
-------------------------------------------------------------------------------
Description
    demProperties -> polydem::SimulationConfig (see demPropertiesReader.H and
    docs/demProperties.md).

\*---------------------------------------------------------------------------*/

#include "demPropertiesReader.H"
#include "IOstreams.H"
#include "Tuple2.H"
#include "mathematicalConstants.H"

#include "polyDEM/MeshQueries.hpp"
#include "polyDEM/StlReader.hpp"

#include "ConvexShapeBuilder.hpp"
#include "ShapeFiles.hpp"
#include "ShapeGenerators.hpp"

#include <algorithm>
#include <cmath>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace Foam
{

//- Read a word entry that must be one of valid; returns its position
static label selectName
(
    const dictionary& d,
    const word& key,
    const wordList& valid,
    const word& what
)
{
    const word name(d.get<word>(key));
    const label i = valid.find(name);
    if (i < 0)
    {
        FatalIOErrorInFunction(d)
            << "Unknown " << what << " '" << name << "' in entry '" << key
            << "' of " << d.name() << nl
            << "Valid " << what << "s: " << valid << nl
            << exit(FatalIOError);
    }
    return i;
}


//- As selectName, with a default when the entry is absent
static label selectNameOrDefault
(
    const dictionary& d,
    const word& key,
    const wordList& valid,
    const word& what,
    const label deflt
)
{
    if (!d.found(key, keyType::LITERAL))
    {
        return deflt;
    }
    return selectName(d, key, valid, what);
}


//- A required sub-dictionary (FatalIOError naming it when absent)
static const dictionary& requiredDict(const dictionary& d, const word& key)
{
    return d.subDict(key);
}


//- The entry at a slash-separated path ("walls/hopper/file"), or nullptr
static const entry* findPath(const dictionary& top, const std::string& path)
{
    const dictionary* d = &top;
    const entry* e = nullptr;
    std::string rest = path;
    while (!rest.empty() && d)
    {
        const auto slash = rest.find('/');
        const word key(rest.substr(0, slash));
        e = d->findEntry(key, keyType::LITERAL);
        if (!e)
        {
            return nullptr;
        }
        rest = slash == std::string::npos ? "" : rest.substr(slash + 1);
        d = e->isDict() ? &e->dict() : nullptr;
    }
    return rest.empty() ? e : nullptr;
}

//- Run read(); an OpenFOAM error inside it (ill-formed list, wrong token,
//  excess tokens) stops with a FatalIOError naming the file and the entry
//  path (e.g. insertion/release/particles[1]/position) and what was expected
template<class Read>
static void readOrFail
(
    const dictionary& top,
    const dictionary& context,
    const std::string& path,
    const std::string& expected,
    const Read& read
)
{
    const bool prevIO = FatalIOError.throwExceptions();
    const bool prev = FatalError.throwExceptions();
    try
    {
        read();
    }
    catch (const Foam::error& err)
    {
        FatalIOError.throwExceptions(prevIO);
        FatalError.throwExceptions(prev);
        FatalIOErrorIn("demPropertiesReader::readParticleList", context)
            << "Cannot read entry '" << path.c_str() << "' of " << top.name()
            << nl << "Expected " << expected.c_str() << nl
            << "(" << err.message().c_str() << ")" << nl
            << exit(FatalIOError);
    }
    FatalIOError.throwExceptions(prevIO);
    FatalError.throwExceptions(prev);
}

} // End namespace Foam


// * * * * * * * * * * * * * * Static Functions  * * * * * * * * * * * * * * //

polydem::Quaternion Foam::demPropertiesReader::orientationQuaternion
(
    const vector& abc
)
{
    const scalar deg = constant::mathematical::pi/180.0;
    const polydem::Quaternion qx =
        polydem::fromAxisAngle(polydem::Vec3(1, 0, 0), abc.x()*deg);
    const polydem::Quaternion qy =
        polydem::fromAxisAngle(polydem::Vec3(0, 1, 0), abc.y()*deg);
    const polydem::Quaternion qz =
        polydem::fromAxisAngle(polydem::Vec3(0, 0, 1), abc.z()*deg);
    // x first, then y, then z (all about the world axes)
    return polydem::normalised(qz*(qy*qx));
}


Foam::fileName Foam::demPropertiesReader::resolveSurface
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


polydem::TriangleMesh Foam::demPropertiesReader::readSurface
(
    const dictionary& demProperties,
    const dictionary& entryDict,
    const word& fileKey,
    const std::string& entryPath
)
{
    const fileName file(resolveSurface(demProperties, entryDict.get<fileName>(fileKey)));
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


void Foam::demPropertiesReader::reportError
(
    const polydem::Error& err,
    const dictionary& demProperties
)
{
    const entry* e = findPath(demProperties, err.entry());
    string where = demProperties.name();
    if (!err.file().empty() && err.file() != demProperties.name())
    {
        where = err.file();
    }

    FatalIOError
    (
        FUNCTION_NAME, __FILE__, __LINE__,
        demProperties.name(),
        e ? e->startLineNumber() : -1
    )
        << "polyDEM: " << err.message().c_str() << nl;

    if (!err.entry().empty())
    {
        FatalIOError
            << "    entry '" << err.entry().c_str() << "' of "
            << demProperties.name() << nl;
    }
    if (where != demProperties.name())
    {
        FatalIOError<< "    file " << where << nl;
    }
    FatalIOError<< exit(FatalIOError);
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

int Foam::demPropertiesReader::materialIndex
(
    const dictionary& d,
    const word& key
) const
{
    const word name(d.get<word>(key));
    for (size_t i = 0; i < config_.materials.size(); ++i)
    {
        if (config_.materials[i].name == name)
        {
            return int(i);
        }
    }
    wordList valid;
    for (const auto& m : config_.materials)
    {
        valid.append(word(m.name));
    }
    FatalIOErrorInFunction(d)
        << "Unknown material '" << name << "' in entry '" << key << "' of "
        << d.name() << nl
        << "Valid materials (from 'materials'): " << valid << nl
        << exit(FatalIOError);
    return -1;
}


int Foam::demPropertiesReader::typeIndex
(
    const dictionary& d,
    const word& key
) const
{
    const word name(d.get<word>(key));
    for (size_t i = 0; i < userTypes_.size(); ++i)
    {
        if (userTypes_[i].name == name)
        {
            return int(i);
        }
    }
    wordList valid;
    for (const auto& t : userTypes_)
    {
        valid.append(t.name);
    }
    FatalIOErrorInFunction(d)
        << "Unknown particle type '" << name << "' in entry '" << key
        << "' of " << d.name() << nl
        << "Valid particle types (from 'particleTypes'): " << valid << nl
        << exit(FatalIOError);
    return -1;
}


void Foam::demPropertiesReader::readGeneral()
{
    config_.source = dict_.name();
    config_.device = dict_.getOrDefault<word>("device", "cpu");
    config_.timeStep = dict_.get<scalar>("timeStep");
    if (!(config_.timeStep > 0))
    {
        FatalIOErrorInFunction(dict_)
            << "Entry 'timeStep' must be positive, got " << config_.timeStep
            << " in " << dict_.name() << nl << exit(FatalIOError);
    }
    config_.gravity = toVec3(dict_.getOrDefault<vector>("gravity", vector(0, 0, -9.81)));
    config_.skinFraction = dict_.getOrDefault<scalar>("skin", 0.2);

    if (const dictionary* dom = dict_.findDict("domain"))
    {
        config_.domainMin = toVec3(dom->get<vector>("min"));
        config_.domainMax = toVec3(dom->get<vector>("max"));
        for (int k = 0; k < 3; ++k)
        {
            if (!(config_.domainMin[k] < config_.domainMax[k]))
            {
                FatalIOErrorInFunction(*dom)
                    << "Entry 'domain': min must be below max in every "
                    << "direction, in " << dict_.name() << nl
                    << exit(FatalIOError);
            }
        }
    }
}


void Foam::demPropertiesReader::readContactModel()
{
    const dictionary& d = requiredDict(dict_, "contactModel");

    static const wordList laws
    ({
        "hertzMindlin", "linearSpringDashpot", "overlapVolume"
    });
    static const wordList rollings({"none", "constantTorque", "elasticPlastic"});

    config_.contact.law = polydem::ContactLaw(selectName(d, "law", laws, "contact law"));
    config_.contact.rolling =
        polydem::RollingModel(selectNameOrDefault(d, "rolling", rollings, "rolling model", 0));

    if (config_.contact.law == polydem::ContactLaw::linearSpringDashpot)
    {
        config_.contact.normalStiffness = d.get<scalar>("normalStiffness");
        config_.contact.tangentialStiffnessRatio =
            d.getOrDefault<scalar>("tangentialStiffnessRatio", 2.0/7.0);
    }
    else if (config_.contact.law == polydem::ContactLaw::overlapVolume)
    {
        // Fn = volumetricStiffness * overlap volume [N/m3]
        config_.contact.volumetricStiffness = d.get<scalar>("volumetricStiffness");
        config_.contact.tangentialStiffnessRatio =
            d.getOrDefault<scalar>("tangentialStiffnessRatio", 2.0/7.0);
        if (!(config_.contact.volumetricStiffness > 0))
        {
            FatalIOErrorInFunction(d)
                << "Entry 'contactModel/volumetricStiffness' must be positive"
                << " [N/m3], got " << config_.contact.volumetricStiffness
                << " in " << dict_.name() << nl << exit(FatalIOError);
        }
    }
    if (!(config_.contact.tangentialStiffnessRatio > 0))
    {
        FatalIOErrorInFunction(d)
            << "Entry 'contactModel/tangentialStiffnessRatio' must be positive"
            << " in " << dict_.name() << nl << exit(FatalIOError);
    }
}


void Foam::demPropertiesReader::readMaterials()
{
    const dictionary& d = requiredDict(dict_, "materials");
    for (const entry& e : d)
    {
        if (!e.isDict())
        {
            FatalIOErrorInFunction(d)
                << "Entry 'materials/" << e.keyword()
                << "' must be a dictionary { youngsModulus ..; poissonsRatio ..; "
                << "density ..; } in " << dict_.name() << nl
                << exit(FatalIOError);
        }
        const dictionary& md = e.dict();
        polydem::Material m;
        m.name = e.keyword();
        m.youngsModulus = md.get<scalar>("youngsModulus");
        m.poissonsRatio = md.get<scalar>("poissonsRatio");
        m.density = md.get<scalar>("density");
        config_.materials.push_back(m);
    }
    if (config_.materials.empty())
    {
        FatalIOErrorInFunction(d)
            << "Entry 'materials' of " << dict_.name()
            << " defines no material" << nl << exit(FatalIOError);
    }
}


void Foam::demPropertiesReader::readInteractions()
{
    const dictionary& d = requiredDict(dict_, "interactions");
    const size_t nm = config_.materials.size();
    config_.pairs.assign(nm*nm, polydem::PairProperties());
    std::vector<bool> given(nm*nm, false);

    const bool rolling =
        config_.contact.rolling != polydem::RollingModel::none;

    auto readPair = [&](const dictionary& pd, polydem::PairProperties& p)
    {
        p.restitution = pd.get<scalar>("restitution");
        p.friction = pd.get<scalar>("friction");
        if (rolling)
        {
            p.rollingFriction = pd.get<scalar>("rollingFriction");
        }
        else
        {
            p.rollingFriction = pd.getOrDefault<scalar>("rollingFriction", 0);
        }
        p.rollingDamping = pd.getOrDefault<scalar>("rollingDamping", 0.3);
    };

    if (const dictionary* def = d.findDict("default"))
    {
        polydem::PairProperties p;
        readPair(*def, p);
        config_.pairs.assign(nm*nm, p);
        given.assign(nm*nm, true);
    }

    for (const entry& e : d)
    {
        if (e.keyword() == "default")
        {
            continue;
        }
        if (!e.isDict())
        {
            FatalIOErrorInFunction(d)
                << "Entry 'interactions/" << e.keyword() << "' must be a "
                << "dictionary { materials (a b); restitution ..; ... } in "
                << dict_.name() << nl << exit(FatalIOError);
        }
        const dictionary& pd = e.dict();
        const wordList names(pd.get<wordList>("materials"));
        if (names.size() != 2)
        {
            FatalIOErrorInFunction(pd)
                << "Entry 'interactions/" << e.keyword()
                << "/materials' must name two materials, e.g. (glass steel), in "
                << dict_.name() << nl << exit(FatalIOError);
        }
        int idx[2];
        for (int k = 0; k < 2; ++k)
        {
            dictionary one;
            one.add("material", names[k]);
            one.name() = pd.name() + "/materials";
            idx[k] = materialIndex(one, "material");
        }
        polydem::PairProperties p;
        readPair(pd, p);
        config_.pairs[idx[0]*nm + idx[1]] = p;
        config_.pairs[idx[1]*nm + idx[0]] = p;
        given[idx[0]*nm + idx[1]] = given[idx[1]*nm + idx[0]] = true;
    }

    for (size_t a = 0; a < nm; ++a)
    {
        for (size_t b = a; b < nm; ++b)
        {
            if (!given[a*nm + b])
            {
                FatalIOErrorInFunction(d)
                    << "Entry 'interactions' of " << dict_.name()
                    << " gives no properties for the pair ("
                    << config_.materials[a].name.c_str() << ' '
                    << config_.materials[b].name.c_str()
                    << "): add a 'default' dictionary or one with "
                    << "materials (" << config_.materials[a].name.c_str() << ' '
                    << config_.materials[b].name.c_str() << ");" << nl
                    << exit(FatalIOError);
            }
        }
    }
}


std::vector<polydem::ConvexShape> Foam::demPropertiesReader::readGeometry
(
    const dictionary& td,
    const word& typeName
) const
{
    const dictionary& gd = td.subDict("geometry");
    const std::string where = "particleTypes/" + typeName + "/geometry";
    static const wordList kinds
    ({
        "stl", "rock", "box", "cube", "tetrahedron", "octahedron",
        "dodecahedron", "icosahedron", "settling"
    });
    const label kind = selectName(gd, "type", kinds, "polyhedron geometry type");

    // Number of shapes: several only for random rocks (one per seed)
    const label nShapes = gd.getOrDefault<label>("shapes", 1);
    if (nShapes < 1 || (nShapes > 1 && kind != 1))
    {
        FatalIOErrorInFunction(gd)
            << "Entry '" << where.c_str() << "/shapes' must be >= 1, and more"
            << " than one only for 'type rock' (one random rock per seed), in "
            << dict_.name() << nl << exit(FatalIOError);
    }

    // Report a polydem::Error (degenerate hull, caps) naming the entry
    auto fail = [&](const polydem::Error& err, const word& key, const std::string& file)
    {
        const entry* e = gd.findEntry(key, keyType::LITERAL);
        FatalIOError
        (
            FUNCTION_NAME, __FILE__, __LINE__,
            dict_.name(), e ? e->startLineNumber() : -1
        )
            << "Cannot make the polyhedron of entry '" << (where + "/" + key).c_str()
            << "' of " << dict_.name() << nl;
        if (!file.empty())
        {
            FatalIOError<< "    file " << file.c_str() << nl;
        }
        FatalIOError
            << "    " << err.message().c_str() << nl
            << "    (at most " << polydem::kMaxPolyhedronVertices << " vertices and "
            << polydem::kMaxPolyhedronFaces << " faces per shape)" << nl
            << exit(FatalIOError);
    };

    auto positive = [&](const word& key) -> scalar
    {
        const scalar v = gd.get<scalar>(key);
        if (!(v > 0))
        {
            FatalIOErrorInFunction(gd)
                << "Entry '" << (where + "/" + key).c_str() << "' must be positive,"
                << " got " << v << " in " << dict_.name() << nl
                << exit(FatalIOError);
        }
        return v;
    };

    std::vector<polydem::ConvexShape> result;
    if (kind == 0)
    {
        // STL (or OBJ) point set: its convex hull. A surface that is not
        // convex (hull volume above the enclosed volume) is refused unless
        // 'convexHull true;' asks for its hull.
        const fileName file(resolveSurface(dict_, gd.get<fileName>("file")));
        const scalar scale = gd.getOrDefault<scalar>("scale", 1.0);
        const bool takeHull = gd.getOrDefault<bool>("convexHull", false);
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
            polydem::ConvexShape s = polydem::buildConvexShape(points, typeName);
            if (enclosed >= 0 && !takeHull && s.volume > (1 + 1e-3)*enclosed)
            {
                const entry* e = gd.findEntry("file", keyType::LITERAL);
                FatalIOError
                (
                    FUNCTION_NAME, __FILE__, __LINE__,
                    dict_.name(), e ? e->startLineNumber() : -1
                )
                    << "The surface " << file << " of entry '"
                    << (where + "/file").c_str() << "' of " << dict_.name()
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
            fail(err, "file", file);
        }
    }
    else
    {
        try
        {
            switch (kind)
            {
                case 1:
                {
                    const scalar d = positive("equivalentDiameter");
                    const scalar el = gd.getOrDefault<scalar>("elongation", 1.0);
                    const scalar fl = gd.getOrDefault<scalar>("flatness", 1.0);
                    const label np = gd.getOrDefault<label>("points", 20);
                    const label seed = gd.getOrDefault<label>("seed", 1);
                    if (!(el > 0 && el <= 1) || !(fl > 0 && fl <= 1) || np < 4)
                    {
                        FatalIOErrorInFunction(gd)
                            << "Entry '" << where.c_str() << "': elongation and"
                            << " flatness must be in (0, 1], points >= 4, in "
                            << dict_.name() << nl << exit(FatalIOError);
                    }
                    for (label k = 0; k < nShapes; ++k)
                    {
                        result.push_back
                        (
                            polydem::makeRock(d, el, fl, int(np), uint64_t(seed + k))
                        );
                    }
                    break;
                }
                case 2:
                {
                    const vector a(gd.get<vector>("size"));
                    if (!(a.x() > 0 && a.y() > 0 && a.z() > 0))
                    {
                        FatalIOErrorInFunction(gd)
                            << "Entry '" << where.c_str() << "/size' must be"
                            << " positive edges (a b c) in " << dict_.name()
                            << nl << exit(FatalIOError);
                    }
                    result.push_back(polydem::makeBox(a.x(), a.y(), a.z()));
                    break;
                }
                case 3:
                    result.push_back(polydem::makeCube(positive("edge")));
                    break;
                case 4:
                    result.push_back(polydem::makeTetrahedron(positive("equivalentDiameter")));
                    break;
                case 5:
                    result.push_back(polydem::makeOctahedron(positive("equivalentDiameter")));
                    break;
                case 6:
                    result.push_back(polydem::makeDodecahedron(positive("equivalentDiameter")));
                    break;
                case 7:
                    result.push_back(polydem::makeIcosahedron(positive("equivalentDiameter")));
                    break;
                default:
                    result.push_back
                    (
                        polydem::makeSettlingParticle
                        (
                            positive("equivalentDiameter"),
                            positive("aspectRatio"),
                            int(gd.get<label>("facets"))
                        )
                    );
                    break;
            }
            for (auto& s : result)
            {
                s.check();
            }
        }
        catch (const polydem::Error& err)
        {
            // Blame the entry that sets the size of the hull
            fail(err, kind == 1 ? "points" : (kind == 8 ? "facets" : "type"), "");
        }
    }
    for (size_t k = 0; k < result.size(); ++k)
    {
        result[k].name = typeName + (result.size() > 1 ? "_" + std::to_string(k) : "");
    }
    return result;
}


void Foam::demPropertiesReader::readParticleTypes()
{
    const dictionary& d = requiredDict(dict_, "particleTypes");
    static const wordList shapes({"sphere", "polyhedron"});
    for (const entry& e : d)
    {
        if (!e.isDict())
        {
            FatalIOErrorInFunction(d)
                << "Entry 'particleTypes/" << e.keyword()
                << "' must be a dictionary in " << dict_.name() << nl
                << exit(FatalIOError);
        }
        const dictionary& td = e.dict();
        userType u;
        u.name = e.keyword();
        u.firstType = int(config_.types.size());
        polydem::ParticleType t;
        t.name = e.keyword();
        t.material = materialIndex(td, "material");
        const label shape = selectNameOrDefault(td, "shape", shapes, "particle shape", 0);
        if (shape == 0)
        {
            t.shape = polydem::ShapeKind::sphere;
            t.radius = 0.5*td.get<scalar>("diameter");
            config_.types.push_back(t);
        }
        else
        {
            if (config_.contact.law != polydem::ContactLaw::overlapVolume)
            {
                const entry* le = dict_.subDict("contactModel").findEntry("law", keyType::LITERAL);
                FatalIOError
                (
                    FUNCTION_NAME, __FILE__, __LINE__,
                    dict_.name(), le ? le->startLineNumber() : -1
                )
                    << "Particle type '" << e.keyword() << "' is a polyhedron:"
                    << " polyhedral particles need 'law overlapVolume;' in"
                    << " entry 'contactModel/law' of " << dict_.name()
                    << " (with volumetricStiffness [N/m3])" << nl
                    << exit(FatalIOError);
            }
            u.polyhedron = true;
            t.shape = polydem::ShapeKind::polyhedron;
            std::vector<polydem::ConvexShape> ss = readGeometry(td, e.keyword());
            u.nTypes = int(ss.size());
            for (auto& s : ss)
            {
                t.shapeIndex = int(config_.shapes.size());
                t.radius = s.boundingRadius;
                Info<< "    particle type " << e.keyword() << ": shape "
                    << s.name.c_str() << ", " << s.nVertices() << " vertices, "
                    << s.nFaces() << " faces, d_eq " << s.equivalentDiameter
                    << " m, bounding diameter " << 2*s.boundingRadius
                    << " m, sphericity " << s.sphericity << endl;
                config_.shapes.push_back(std::move(s));
                config_.types.push_back(t);
            }
        }
        userTypes_.push_back(u);
    }
    if (config_.types.empty())
    {
        FatalIOErrorInFunction(d)
            << "Entry 'particleTypes' of " << dict_.name()
            << " defines no particle type" << nl << exit(FatalIOError);
    }
}


polydem::WallMotion Foam::demPropertiesReader::readMotion
(
    const dictionary& wallDict
) const
{
    polydem::WallMotion m;
    const dictionary* md = wallDict.findDict("motion");
    if (!md)
    {
        return m;
    }
    static const wordList kinds({"fixed", "translation", "rotation"});
    m.kind = polydem::MotionKind(selectName(*md, "type", kinds, "wall motion type"));
    if (m.kind == polydem::MotionKind::translation)
    {
        m.velocity = toVec3(md->get<vector>("velocity"));
    }
    else if (m.kind == polydem::MotionKind::rotation)
    {
        m.origin = toVec3(md->get<vector>("origin"));
        m.axis = toVec3(md->get<vector>("axis"));
        const bool hasRpm = md->found("rpm", keyType::LITERAL);
        const bool hasOmega = md->found("omega", keyType::LITERAL);
        if (hasRpm == hasOmega)
        {
            FatalIOErrorInFunction(*md)
                << "Rotation of " << md->name() << " needs exactly one of "
                << "'rpm' (revolutions per minute) or 'omega' [rad/s]" << nl
                << exit(FatalIOError);
        }
        m.omega = hasRpm
            ? md->get<scalar>("rpm")*constant::mathematical::twoPi/60.0
            : md->get<scalar>("omega");
    }
    return m;
}


void Foam::demPropertiesReader::readWalls()
{
    const dictionary* d = dict_.findDict("walls");
    if (!d)
    {
        return;
    }
    static const wordList types({"plane", "mesh"});
    for (const entry& e : *d)
    {
        if (!e.isDict())
        {
            FatalIOErrorInFunction(*d)
                << "Entry 'walls/" << e.keyword() << "' must be a dictionary in "
                << dict_.name() << nl << exit(FatalIOError);
        }
        const dictionary& wd = e.dict();
        wallInfo info;
        info.name = e.keyword();
        info.activeUntil = wd.getOrDefault<scalar>("activeUntil", GREAT);
        info.displaySize = wd.getOrDefault<scalar>("displaySize", 0);

        const label kind = selectName(wd, "type", types, "wall type");
        if (kind == 0)
        {
            polydem::PlaneWall w;
            w.name = e.keyword();
            w.point = toVec3(wd.get<vector>("point"));
            w.normal = toVec3(wd.get<vector>("normal"));
            w.material = materialIndex(wd, "material");
            w.motion = readMotion(wd);
            info.isPlane = true;
            info.index = label(config_.planes.size());
            config_.planes.push_back(w);
        }
        else
        {
            polydem::MeshWall w;
            w.name = e.keyword();
            w.material = materialIndex(wd, "material");
            w.motion = readMotion(wd);
            w.mesh = readSurface(dict_, wd, "file", "walls/" + e.keyword() + "/file");
            info.isPlane = false;
            info.index = label(config_.meshes.size());
            config_.meshes.push_back(std::move(w));
        }
        walls_.push_back(info);
    }
}


polydem::SizeDistribution Foam::demPropertiesReader::readDistribution
(
    const dictionary& id,
    const polydem::ParticleType& type
) const
{
    polydem::SizeDistribution s;
    const dictionary* dd = id.findDict("diameterDistribution");
    if (!dd)
    {
        s = polydem::SizeDistribution::fixedDiameter(2*type.radius);
    }
    else
    {
        static const wordList kinds({"fixed", "uniform", "normal", "discrete"});
        const label kind = selectName(*dd, "type", kinds, "diameter distribution");
        switch (kind)
        {
            case 0:
                s = polydem::SizeDistribution::fixedDiameter
                (
                    dd->getOrDefault<scalar>("diameter", 2*type.radius)
                );
                break;
            case 1:
                s = polydem::SizeDistribution::uniform
                (
                    dd->get<scalar>("min"), dd->get<scalar>("max")
                );
                break;
            case 2:
                s = polydem::SizeDistribution::normal
                (
                    dd->get<scalar>("mean"),
                    dd->get<scalar>("standardDeviation"),
                    dd->get<scalar>("min"),
                    dd->get<scalar>("max")
                );
                break;
            default:
            {
                const List<Tuple2<scalar, scalar>> f
                (
                    dd->get<List<Tuple2<scalar, scalar>>>("fractions")
                );
                std::vector<std::pair<double, double>> fr;
                for (const auto& t : f)
                {
                    fr.emplace_back(t.first(), t.second());
                }
                s = polydem::SizeDistribution::discrete(fr);
                break;
            }
        }
    }
    s.source = dict_.name();
    try
    {
        s.validate();
    }
    catch (const polydem::Error& err)
    {
        // The engine names the distribution's own entry: prefix its path
        const std::string sub = err.entry() == "sd" ? "standardDeviation" : err.entry();
        reportError
        (
            polydem::Error
            (
                err.message(), dict_.name(),
                "insertion/" + std::string(id.dictName())
              + "/diameterDistribution" + (sub.empty() ? "" : "/" + sub)
            ),
            dict_
        );
    }
    return s;
}


polydem::FillRegion Foam::demPropertiesReader::readRegion
(
    const dictionary& id
) const
{
    const dictionary& rd = id.subDict("region");
    static const wordList kinds({"box", "stl"});
    const label kind = selectName(rd, "type", kinds, "region type");
    if (kind == 0)
    {
        return polydem::FillRegion::box
        (
            toVec3(rd.get<vector>("min")), toVec3(rd.get<vector>("max"))
        );
    }

    const std::string path =
        "insertion/" + std::string(id.dictName()) + "/region/file";
    polydem::TriangleMesh mesh = readSurface(dict_, rd, "file", path);
    try
    {
        if (rd.found("min", keyType::LITERAL) || rd.found("max", keyType::LITERAL))
        {
            return polydem::FillRegion::insideMesh
            (
                std::move(mesh),
                toVec3(rd.get<vector>("min")), toVec3(rd.get<vector>("max"))
            );
        }
        return polydem::FillRegion::insideMesh(std::move(mesh));
    }
    catch (const polydem::Error& err)
    {
        reportError(polydem::Error(err.message(), err.file(), path), dict_);
    }
    return polydem::FillRegion();
}


void Foam::demPropertiesReader::readInsertions()
{
    const dictionary* d = dict_.findDict("insertion");
    if (!d)
    {
        return;
    }
    static const wordList kinds({"randomFill", "list"});
    for (const entry& e : *d)
    {
        if (!e.isDict())
        {
            FatalIOErrorInFunction(*d)
                << "Entry 'insertion/" << e.keyword()
                << "' must be a dictionary in " << dict_.name() << nl
                << exit(FatalIOError);
        }
        const dictionary& id = e.dict();
        const label kind = selectName(id, "type", kinds, "insertion type");
        insertion ins;
        ins.name = e.keyword();
        ins.type = typeIndex(id, "particleType");
        ins.time = id.getOrDefault<scalar>("time", -GREAT);
        if (kind == 1)
        {
            ins.kind = insertion::method::list;
            readParticleList(id, ins);
            insertions_.push_back(std::move(ins));
            continue;
        }
        ins.number = id.get<label>("number");
        ins.seed = id.getOrDefault<label>("seed", 1);
        ins.gap = id.getOrDefault<scalar>("gap", 0);
        ins.velocity = toVec3(id.getOrDefault<vector>("velocity", Zero));
        if (id.found("orientation", keyType::LITERAL))
        {
            ins.fixedOrientation = true;
            ins.orientation =
                orientationQuaternion(id.get<vector>("orientation"));
        }
        if (ins.number < 0)
        {
            FatalIOErrorInFunction(id)
                << "Entry 'insertion/" << e.keyword()
                << "/number' must not be negative in " << dict_.name() << nl
                << exit(FatalIOError);
        }
        const userType& ut = userTypes_[ins.type];
        if (ut.polyhedron)
        {
            // Placed by bounding sphere: one diameter per shape, equally likely
            if (id.found("diameterDistribution", keyType::LITERAL))
            {
                FatalIOErrorInFunction(id)
                    << "Entry 'insertion/" << e.keyword() << "/diameterDistribution'"
                    << ": particle type '" << ut.name << "' is a polyhedron, whose"
                    << " size is set by its geometry; remove the entry from "
                    << dict_.name() << nl << exit(FatalIOError);
            }
            std::vector<std::pair<double, double>> fr;
            for (int k = 0; k < ut.nTypes; ++k)
            {
                fr.emplace_back(2*config_.types[ut.firstType + k].radius, 1.0);
            }
            ins.sizes = ut.nTypes == 1
                ? polydem::SizeDistribution::fixedDiameter(fr[0].first)
                : polydem::SizeDistribution::discrete(fr);
            ins.sizes.source = dict_.name();
        }
        else
        {
            ins.sizes = readDistribution(id, config_.types[ut.firstType]);
        }
        ins.region = readRegion(id);
        insertions_.push_back(std::move(ins));
    }
}


void Foam::demPropertiesReader::readParticleList
(
    const dictionary& id,
    insertion& ins
) const
{
    const std::string base = "insertion/" + ins.name + "/particles";
    const char* listSyntax =
        "a list of particle dictionaries: particles ( { position (x y z);"
        " orientation (a b c); velocity (u v w); omega (wx wy wz); } ... );"
        " orientation, velocity, omega optional";

    for (const word key : {"number", "region", "seed", "gap",
        "diameterDistribution", "orientation"})
    {
        if (id.found(key, keyType::LITERAL))
        {
            FatalIOErrorInFunction(id)
                << "Entry 'insertion/" << ins.name << "/" << key
                << "' is not used by an insertion of type list (the particles"
                << " are given one by one in 'particles'); remove it from "
                << dict_.name() << nl << exit(FatalIOError);
        }
    }

    const entry* pe = id.findEntry("particles", keyType::LITERAL);
    if (!pe || pe->isDict())
    {
        FatalIOErrorInFunction(id)
            << "Entry '" << base.c_str() << "' "
            << (pe ? "must be a list, not a dictionary," : "is missing")
            << " in " << dict_.name() << nl
            << "Expected " << listSyntax << nl << exit(FatalIOError);
    }

    List<dictionary> list;
    readOrFail
    (
        dict_, id, base, listSyntax,
        [&]()
        {
            ITstream& is = pe->stream();
            is >> list;
            if (is.nRemainingTokens())
            {
                FatalIOErrorInFunction(is)
                    << is.nRemainingTokens() << " excess tokens after the"
                    << " list" << exit(FatalIOError);
            }
        }
    );
    if (list.empty())
    {
        FatalIOErrorInFunction(id)
            << "Entry '" << base.c_str() << "' is an empty list in "
            << dict_.name() << nl << "Expected " << listSyntax << nl
            << exit(FatalIOError);
    }

    // The insertion's velocity: default of its particles
    vector listVelocity(Zero);
    readOrFail
    (
        dict_, id, "insertion/" + ins.name + "/velocity",
        "a velocity (u v w) [m/s]",
        [&]() { listVelocity = id.getOrDefault<vector>("velocity", Zero); }
    );
    ins.velocity = toVec3(listVelocity);

    const userType& ut = userTypes_[ins.type];
    static const wordList valid
    ({
        "position", "orientation", "velocity", "omega", "shape", "diameter"
    });
    forAll(list, k)
    {
        const dictionary& pd = list[k];
        const std::string path = base + "[" + std::to_string(k) + "]";
        for (const entry& pdE : pd)
        {
            if (!valid.found(pdE.keyword()))
            {
                FatalIOErrorInFunction(id)
                    << "Unknown keyword '" << pdE.keyword() << "' in entry '"
                    << path.c_str() << "' of " << dict_.name() << nl
                    << "Valid keywords: " << valid << nl << exit(FatalIOError);
            }
        }
        if (!pd.found("position", keyType::LITERAL))
        {
            FatalIOErrorInFunction(id)
                << "Entry '" << path.c_str() << "/position' is missing in "
                << dict_.name() << nl << "Expected " << listSyntax << nl
                << exit(FatalIOError);
        }

        auto readVector = [&]
        (
            const word& key,
            const char* what,
            const vector& deflt = Zero
        )
        {
            vector v(deflt);
            if (pd.found(key, keyType::LITERAL))
            {
                readOrFail
                (
                    dict_, id, path + "/" + key, what,
                    [&]() { v = pd.get<vector>(key); }
                );
            }
            return v;
        };

        listParticle p;
        p.position = toVec3(readVector("position", "a position (x y z) [m]"));
        p.orientation = orientationQuaternion
        (
            readVector
            (
                "orientation",
                "an orientation (a b c) [degrees]: rotations about the world"
                " x, then y, then z axes"
            )
        );
        p.velocity = toVec3
        (
            readVector("velocity", "a velocity (u v w) [m/s]", listVelocity)
        );
        p.omega = toVec3
        (
            readVector("omega", "an angular velocity (wx wy wz) [rad/s]")
        );

        label shape = 0;
        if (pd.found("shape", keyType::LITERAL))
        {
            readOrFail
            (
                dict_, id, path + "/shape", "a shape index (label)",
                [&]() { shape = pd.get<label>("shape"); }
            );
            if (shape < 0 || shape >= ut.nTypes)
            {
                FatalIOErrorInFunction(id)
                    << "Entry '" << path.c_str() << "/shape' is " << shape
                    << ": particle type '" << ut.name << "' has " << ut.nTypes
                    << " shape(s), indices 0.." << ut.nTypes - 1 << ", in "
                    << dict_.name() << nl << exit(FatalIOError);
            }
        }
        p.type = ut.firstType + int(shape);
        p.radius = config_.types[p.type].radius;
        if (pd.found("diameter", keyType::LITERAL))
        {
            if (ut.polyhedron)
            {
                FatalIOErrorInFunction(id)
                    << "Entry '" << path.c_str() << "/diameter': particle type '"
                    << ut.name << "' is a polyhedron, whose size is set by its"
                    << " geometry; remove the entry from " << dict_.name()
                    << nl << exit(FatalIOError);
            }
            scalar d = 0;
            readOrFail
            (
                dict_, id, path + "/diameter", "a diameter [m]",
                [&]() { d = pd.get<scalar>("diameter"); }
            );
            if (!(d > 0))
            {
                FatalIOErrorInFunction(id)
                    << "Entry '" << path.c_str() << "/diameter' must be"
                    << " positive in " << dict_.name() << nl
                    << exit(FatalIOError);
            }
            p.radius = 0.5*d;
        }
        ins.particles.push_back(p);
    }
    ins.number = label(ins.particles.size());
}


void Foam::demPropertiesReader::readOutput()
{
    stateFormat_ = polydem::StateFormat::ascii;
    writeVtk_ = true;
    reportInterval_ = dict_.getOrDefault<scalar>("reportInterval", 5);
    if (const dictionary* od = dict_.findDict("output"))
    {
        static const wordList formats({"ascii", "binary"});
        stateFormat_ = polydem::StateFormat
        (
            selectNameOrDefault(*od, "format", formats, "state format", 0)
        );
        writeVtk_ = od->getOrDefault<bool>("vtk", true);
    }
}


void Foam::demPropertiesReader::computeScene()
{
    polydem::Vec3 lo(GREAT, GREAT, GREAT), hi(-GREAT, -GREAT, -GREAT);
    auto grow = [&](const polydem::Vec3& a, const polydem::Vec3& b)
    {
        for (int k = 0; k < 3; ++k)
        {
            lo[k] = std::min(lo[k], a[k]);
            hi[k] = std::max(hi[k], b[k]);
        }
    };
    for (const auto& m : config_.meshes)
    {
        const auto bb = polydem::boundingBox(m.mesh);
        grow(bb.first, bb.second);
    }
    for (const auto& ins : insertions_)
    {
        if (ins.kind == insertion::method::list)
        {
            for (const auto& p : ins.particles)
            {
                const polydem::Vec3 r(p.radius, p.radius, p.radius);
                grow(p.position - r, p.position + r);
            }
            continue;
        }
        const auto bb = ins.region.bounds();
        grow(bb.first, bb.second);
    }
    if (config_.domainMax.x < 1e29)
    {
        grow(config_.domainMin, config_.domainMax);
    }
    if (lo.x > hi.x)
    {
        sceneSize_ = 0.1;
        sceneCentre_ = polydem::Vec3();
        for (const auto& p : config_.planes)
        {
            sceneCentre_ = p.point;
        }
        return;
    }
    sceneSize_ = std::max(norm(hi - lo), SMALL);
    sceneCentre_ = 0.5*(lo + hi);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::demPropertiesReader::demPropertiesReader(const dictionary& demProperties)
:
    dict_(demProperties),
    stateFormat_(polydem::StateFormat::ascii),
    writeVtk_(true),
    reportInterval_(5),
    sceneSize_(0.1)
{
    readGeneral();
    readContactModel();
    readMaterials();
    readInteractions();
    readParticleTypes();
    readWalls();
    readInsertions();
    readOutput();
    computeScene();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

polydem::SimulationConfig Foam::demPropertiesReader::configWith
(
    const std::vector<bool>& activeWalls,
    std::vector<int>& wallMap
) const
{
    polydem::SimulationConfig c = config_;
    c.planes.clear();
    c.meshes.clear();

    const size_t nPl = config_.planes.size();
    wallMap.assign(nPl + config_.meshes.size(), -1);

    // Keep planes first, then meshes: the engine's wall numbering
    for (size_t k = 0; k < walls_.size(); ++k)
    {
        const wallInfo& w = walls_[k];
        if (w.isPlane && activeWalls[k])
        {
            wallMap[w.index] = int(c.planes.size());
            c.planes.push_back(config_.planes[w.index]);
        }
    }
    for (size_t k = 0; k < walls_.size(); ++k)
    {
        const wallInfo& w = walls_[k];
        if (!w.isPlane && activeWalls[k])
        {
            c.meshes.push_back(config_.meshes[w.index]);
            wallMap[nPl + w.index] = -2 - int(c.meshes.size() - 1);
        }
    }
    // Mesh indices come after the kept planes
    for (size_t k = nPl; k < wallMap.size(); ++k)
    {
        if (wallMap[k] <= -2)
        {
            wallMap[k] = int(c.planes.size()) + (-2 - wallMap[k]);
        }
    }
    return c;
}


// ************************************************************************* //

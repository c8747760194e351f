/*---------------------------------------------------------------------------*\
  Hedra: CFD-DEM for OpenFOAM
-------------------------------------------------------------------------------
Description
    demProperties 'insertion' entries (see demInsertionsReader.H).

\*---------------------------------------------------------------------------*/

#include "demInsertionsReader.H"
#include "demPropertiesErrors.H"
#include "demSurfaceReader.H"
#include "polyDEMConversions.H"
#include "IOstreams.H"
#include "Tuple2.H"
#include "vector.H"

using Foam::polyDEMConversions::toVec3;
using Foam::polyDEMConversions::orientationFromAngles;

// * * * * * * * * * * * * Private Static Functions  * * * * * * * * * * * * //

int Foam::demInsertionsReader::typeIndex
(
    const std::vector<demShapesReader::userType>& userTypes,
    const dictionary& d,
    const word& key
)
{
    const word name(d.get<word>(key));
    for (size_t i = 0; i < userTypes.size(); ++i)
    {
        if (userTypes[i].name == name)
        {
            return int(i);
        }
    }
    wordList valid;
    for (const auto& t : userTypes)
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


polydem::SizeDistribution Foam::demInsertionsReader::readDistribution
(
    const dictionary& dict,
    const dictionary& id,
    const polydem::ParticleType& type
)
{
    polydem::SizeDistribution s;
    const dictionary* dd = id.findDict("diameterDistribution");
    if (!dd)
    {
        s = polydem::SizeDistribution::fixedDiameter(2*type.radius);
    }
    else
    {
        demPropertiesErrors::checkKeys
        (
            dict, *dd, "insertion/" + id.dictName() + "/diameterDistribution",
            {"type", "diameter", "min", "max", "mean", "standardDeviation", "fractions"}
        );
        static const wordList kinds({"fixed", "uniform", "normal", "discrete"});
        const label kind = demPropertiesErrors::selectName(*dd, "type", kinds, "diameter distribution");
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
    s.source = dict.name();
    try
    {
        s.validate();
    }
    catch (const polydem::Error& err)
    {
        // The engine names the distribution's own entry: prefix its path
        const std::string sub = err.entry() == "sd" ? "standardDeviation" : err.entry();
        demPropertiesErrors::reportError
        (
            polydem::Error
            (
                err.message(), dict.name(),
                "insertion/" + std::string(id.dictName())
              + "/diameterDistribution" + (sub.empty() ? "" : "/" + sub)
            ),
            dict
        );
    }
    return s;
}


polydem::FillRegion Foam::demInsertionsReader::readRegion
(
    const dictionary& dict,
    const dictionary& id
)
{
    const dictionary& rd = id.subDict("region");
    demPropertiesErrors::checkKeys
    (
        dict, rd, "insertion/" + id.dictName() + "/region",
        {"type", "min", "max", "file", "scale"}
    );
    static const wordList kinds({"box", "stl"});
    const label kind = demPropertiesErrors::selectName(rd, "type", kinds, "region type");
    if (kind == 0)
    {
        const std::string at = "insertion/" + id.dictName() + "/region/";
        return polydem::FillRegion::box
        (
            toVec3(demPropertiesErrors::boundedVector
            (
                dict, rd, "min", at + "min", demPropertiesErrors::maxMagnitude,
                "a point (x y z) [m]"
            )),
            toVec3(demPropertiesErrors::boundedVector
            (
                dict, rd, "max", at + "max", demPropertiesErrors::maxMagnitude,
                "a point (x y z) [m]"
            ))
        );
    }

    const std::string path =
        "insertion/" + std::string(id.dictName()) + "/region/file";
    polydem::TriangleMesh mesh = demSurfaceReader::read(dict, rd, "file", path);
    try
    {
        if (rd.found("min", keyType::LITERAL) || rd.found("max", keyType::LITERAL))
        {
            const std::string at = "insertion/" + id.dictName() + "/region/";
            return polydem::FillRegion::insideMesh
            (
                std::move(mesh),
                toVec3(demPropertiesErrors::boundedVector
                (
                    dict, rd, "min", at + "min", demPropertiesErrors::maxMagnitude,
                    "a point (x y z) [m]"
                )),
                toVec3(demPropertiesErrors::boundedVector
                (
                    dict, rd, "max", at + "max", demPropertiesErrors::maxMagnitude,
                    "a point (x y z) [m]"
                ))
            );
        }
        return polydem::FillRegion::insideMesh(std::move(mesh));
    }
    catch (const polydem::Error& err)
    {
        demPropertiesErrors::reportError(polydem::Error(err.message(), err.file(), path), dict);
    }
    return polydem::FillRegion();
}


void Foam::demInsertionsReader::readParticleList
(
    const dictionary& dict,
    const polydem::SimulationConfig& config,
    const std::vector<demShapesReader::userType>& userTypes,
    const dictionary& id,
    insertion& ins
)
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
                << dict.name() << nl << exit(FatalIOError);
        }
    }

    const entry* pe = id.findEntry("particles", keyType::LITERAL);
    if (!pe || pe->isDict())
    {
        FatalIOErrorInFunction(id)
            << "Entry '" << base.c_str() << "' "
            << (pe ? "must be a list, not a dictionary," : "is missing")
            << " in " << dict.name() << nl
            << "Expected " << listSyntax << nl << exit(FatalIOError);
    }

    List<dictionary> list;
    demPropertiesErrors::readOrFail
    (
        dict, id, base, listSyntax,
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
            << dict.name() << nl << "Expected " << listSyntax << nl
            << exit(FatalIOError);
    }

    // The insertion's velocity: default of its particles
    vector listVelocity(Zero);
    demPropertiesErrors::readOrFail
    (
        dict, id, "insertion/" + ins.name + "/velocity",
        "a velocity (u v w) [m/s]",
        [&]() { listVelocity = id.getOrDefault<vector>("velocity", Zero); }
    );
    ins.velocity = toVec3(listVelocity);

    const demShapesReader::userType& ut = userTypes[ins.type];
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
                    << path.c_str() << "' of " << dict.name() << nl
                    << "Valid keywords: " << valid << nl << exit(FatalIOError);
            }
        }
        if (!pd.found("position", keyType::LITERAL))
        {
            FatalIOErrorInFunction(id)
                << "Entry '" << path.c_str() << "/position' is missing in "
                << dict.name() << nl << "Expected " << listSyntax << nl
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
                demPropertiesErrors::readOrFail
                (
                    dict, id, path + "/" + key, what,
                    [&]() { v = pd.get<vector>(key); }
                );
                // Positions: 1e6 m (velocities and spins have their own
                // check against the time step, checkInsertedMotion)
                if (key == "position")
                {
                    demPropertiesErrors::boundedVector
                    (
                        dict, pd, key, path + "/" + key,
                        demPropertiesErrors::maxMagnitude, what
                    );
                }
            }
            return v;
        };

        listParticle p;
        p.position = toVec3(readVector("position", "a position (x y z) [m]"));
        p.orientation = orientationFromAngles
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
            demPropertiesErrors::readOrFail
            (
                dict, id, path + "/shape", "a shape index (label)",
                [&]() { shape = pd.get<label>("shape"); }
            );
            if (shape < 0 || shape >= ut.nTypes)
            {
                FatalIOErrorInFunction(id)
                    << "Entry '" << path.c_str() << "/shape' is " << shape
                    << ": particle type '" << ut.name << "' has " << ut.nTypes
                    << " shape(s), indices 0.." << ut.nTypes - 1 << ", in "
                    << dict.name() << nl << exit(FatalIOError);
            }
        }
        p.type = ut.firstType + int(shape);
        p.radius = config.types[p.type].radius;
        if (pd.found("diameter", keyType::LITERAL))
        {
            if (ut.polyhedron)
            {
                FatalIOErrorInFunction(id)
                    << "Entry '" << path.c_str() << "/diameter': particle type '"
                    << ut.name << "' is a polyhedron, whose size is set by its"
                    << " geometry; remove the entry from " << dict.name()
                    << nl << exit(FatalIOError);
            }
            scalar d = 0;
            demPropertiesErrors::readOrFail
            (
                dict, id, path + "/diameter", "a diameter [m]",
                [&]() { d = pd.get<scalar>("diameter"); }
            );
            if (!(d > 0))
            {
                FatalIOErrorInFunction(id)
                    << "Entry '" << path.c_str() << "/diameter' must be"
                    << " positive in " << dict.name() << nl
                    << exit(FatalIOError);
            }
            p.radius = 0.5*d;
        }
        ins.particles.push_back(p);
    }
    ins.number = label(ins.particles.size());
}


void Foam::demInsertionsReader::readInflow
(
    const dictionary& dict,
    const dictionary& id,
    insertion& ins
)
{
    const std::string base = "insertion/" + ins.name + "/";
    ins.kind = insertion::method::inflow;
    ins.solidFraction = id.get<scalar>("solidFraction");
    if (!(ins.solidFraction > 0 && ins.solidFraction < 1))
    {
        FatalIOErrorInFunction(id)
            << "Entry '" << base.c_str() << "solidFraction' must lie in (0, 1) "
            << "(the region's target solid volume fraction, 1 - porosity), "
            << "not " << ins.solidFraction << ", in " << dict.name() << nl
            << exit(FatalIOError);
    }
    ins.interval = id.getOrDefault<scalar>("interval", 0);
    if (!(ins.interval >= 0))
    {
        FatalIOErrorInFunction(id)
            << "Entry '" << base.c_str() << "interval' must be >= 0 [s] "
            << "(0: check at every deltaT), not " << ins.interval << ", in "
            << dict.name() << nl << exit(FatalIOError);
    }
    ins.attempts = id.getOrDefault<label>("attempts", 200);
    if (ins.attempts < 1)
    {
        FatalIOErrorInFunction(id)
            << "Entry '" << base.c_str() << "attempts' must be >= 1, not "
            << ins.attempts << ", in " << dict.name() << nl
            << exit(FatalIOError);
    }
    ins.randomYaw = id.getOrDefault<bool>("randomYaw", false);
    ins.yawAxis = toVec3(id.getOrDefault<vector>("yawAxis", vector(0, 0, 1)));
    if (!(norm(ins.yawAxis) > 0))
    {
        FatalIOErrorInFunction(id)
            << "Entry '" << base.c_str() << "yawAxis' must not be zero in "
            << dict.name() << nl << exit(FatalIOError);
    }
    ins.endTime = id.getOrDefault<scalar>("endTime", GREAT);
}


// * * * * * * * * * * * * * * Static Functions  * * * * * * * * * * * * * * //

std::vector<Foam::demInsertionsReader::insertion>
Foam::demInsertionsReader::read
(
    const dictionary& dict,
    const polydem::SimulationConfig& config,
    const std::vector<demShapesReader::userType>& userTypes
)
{
    std::vector<insertion> insertions;
    const dictionary* d = dict.findDict("insertion");
    if (!d)
    {
        return insertions;
    }
    static const wordList kinds({"randomFill", "list", "inflow"});
    for (const entry& e : *d)
    {
        if (!e.isDict())
        {
            FatalIOErrorInFunction(*d)
                << "Entry 'insertion/" << e.keyword()
                << "' must be a dictionary in " << dict.name() << nl
                << exit(FatalIOError);
        }
        const dictionary& id = e.dict();
        static const wordList insertionKeys
        ({
            "type", "particleType", "time", "number", "seed", "gap",
            "velocity", "orientation", "region", "diameterDistribution",
            "particles"
        });
        static const wordList inflowKeys
        ({
            "type", "particleType", "particleTypes", "time", "seed", "gap",
            "velocity", "orientation", "region", "diameterDistribution",
            "solidFraction", "interval", "attempts", "randomYaw", "yawAxis",
            "endTime", "approach", "orientations"
        });
        const label kind = demPropertiesErrors::selectName(id, "type", kinds, "insertion type");
        demPropertiesErrors::checkKeys
        (
            dict, id, "insertion/" + e.keyword(),
            kind == 2 ? inflowKeys : insertionKeys
        );
        insertion ins;
        ins.name = e.keyword();
        if (kind == 2 && id.found("particleTypes", keyType::LITERAL))
        {
            // An inflow drawing from several types (the size classes of a
            // brash-ice channel), each equally likely
            if (id.found("particleType", keyType::LITERAL))
            {
                FatalIOErrorInFunction(id)
                    << "Entries 'insertion/" << e.keyword() << "/particleType'"
                    << " and 'particleTypes' are exclusive (one type, or a "
                    << "list drawn with equal probability); keep one in "
                    << dict.name() << nl << exit(FatalIOError);
            }
            const wordList names(id.get<wordList>("particleTypes"));
            if (names.empty())
            {
                FatalIOErrorInFunction(id)
                    << "Entry 'insertion/" << e.keyword() << "/particleTypes'"
                    << " must name at least one particle type in "
                    << dict.name() << nl << exit(FatalIOError);
            }
            for (const word& n : names)
            {
                dictionary one;
                one.add("particleTypes", n);
                one.name() = id.name();
                ins.types.push_back(typeIndex(userTypes, one, "particleTypes"));
            }
            ins.type = ins.types[0];
        }
        else
        {
            ins.type = typeIndex(userTypes, id, "particleType");
            ins.types.assign(1, ins.type);
        }
        ins.time = id.getOrDefault<scalar>("time", -GREAT);
        if (id.found("time", keyType::LITERAL) && !(ins.time >= 0))
        {
            FatalIOErrorInFunction(id)
                << "Entry 'insertion/" << e.keyword() << "/time' must be a "
                << "time >= 0 [s] (leave it out to insert at the start), not "
                << ins.time << ", in " << dict.name() << nl
                << exit(FatalIOError);
        }
        if (kind == 1)
        {
            ins.kind = insertion::method::list;
            readParticleList(dict, config, userTypes, id, ins);
            insertions.push_back(std::move(ins));
            continue;
        }
        if (kind == 2)
        {
            readInflow(dict, id, ins);
        }
        else
        {
            ins.number = id.get<label>("number");
        }
        ins.seed = id.getOrDefault<label>("seed", 1);
        ins.gap = id.getOrDefault<scalar>("gap", 0);
        if (!(ins.gap >= 0))
        {
            FatalIOErrorInFunction(id)
                << "Entry 'insertion/" << e.keyword() << "/gap' must be >= 0 "
                << "[m] (the smallest surface distance between inserted "
                << "particles), not " << ins.gap << ", in " << dict.name()
                << nl << exit(FatalIOError);
        }
        ins.velocity = toVec3(id.getOrDefault<vector>("velocity", Zero));
        if (id.found("orientation", keyType::LITERAL))
        {
            ins.fixedOrientation = true;
            ins.orientation =
                orientationFromAngles(id.get<vector>("orientation"));
        }
        if (ins.randomYaw && !userTypes[ins.type].polyhedron)
        {
            FatalIOErrorInFunction(id)
                << "Entry 'insertion/" << e.keyword() << "/randomYaw': "
                << "particle type '" << userTypes[ins.type].name << "' is a "
                << "sphere, which has no heading; remove the entry from "
                << dict.name() << nl << exit(FatalIOError);
        }
        if (ins.randomYaw && !ins.fixedOrientation)
        {
            // A random heading about the given flat orientation; without
            // one, the blocks keep their body axes flat
            ins.fixedOrientation = true;
            ins.orientation = polydem::Quaternion();
        }
        if (ins.number < 0)
        {
            FatalIOErrorInFunction(id)
                << "Entry 'insertion/" << e.keyword()
                << "/number' must not be negative in " << dict.name() << nl
                << exit(FatalIOError);
        }
        const demShapesReader::userType& ut = userTypes[ins.type];
        if (ut.polyhedron)
        {
            // Placed by bounding sphere: one diameter per shape, equally likely
            if (id.found("diameterDistribution", keyType::LITERAL))
            {
                FatalIOErrorInFunction(id)
                    << "Entry 'insertion/" << e.keyword() << "/diameterDistribution'"
                    << ": particle type '" << ut.name << "' is a polyhedron, whose"
                    << " size is set by its geometry; remove the entry from "
                    << dict.name() << nl << exit(FatalIOError);
            }
            std::vector<std::pair<double, double>> fr;
            for (int k = 0; k < ut.nTypes; ++k)
            {
                fr.emplace_back(2*config.types[ut.firstType + k].radius, 1.0);
            }
            ins.sizes = ut.nTypes == 1
                ? polydem::SizeDistribution::fixedDiameter(fr[0].first)
                : polydem::SizeDistribution::discrete(fr);
            ins.sizes.source = dict.name();
        }
        else
        {
            ins.sizes = readDistribution(dict, id, config.types[ut.firstType]);
        }
        ins.region = readRegion(dict, id);
        if (kind == 2)
        {
            readApproach(dict, id, userTypes, ins);
        }
        insertions.push_back(std::move(ins));
    }
    return insertions;
}


void Foam::demInsertionsReader::readApproach
(
    const dictionary& dict,
    const dictionary& id,
    const std::vector<demShapesReader::userType>& userTypes,
    insertion& ins
)
{
    const std::string base = "insertion/" + ins.name + "/";
    if (ins.types.size() > 1 && !id.found("approach", keyType::LITERAL))
    {
        FatalIOErrorInFunction(id)
            << "Entry '" << base.c_str() << "particleTypes' (several types) "
            << "needs an 'approach' region (a floating layer); give one "
            << "'particleType' otherwise, in " << dict.name() << nl
            << exit(FatalIOError);
    }
    if (!id.found("approach", keyType::LITERAL))
    {
        return;
    }
    const dictionary* ad = id.findDict("approach");
    if (!ad)
    {
        FatalIOErrorInFunction(id)
            << "Entry '" << base.c_str() << "approach' must be a dictionary "
            << "{ min (x y z); max (x y z); height z; } in " << dict.name()
            << nl << exit(FatalIOError);
    }
    demPropertiesErrors::checkKeys
    (
        dict, *ad, base + "approach", wordList({"min", "max", "height"})
    );
    const std::string at = base + "approach/";
    for (const char* key : {"min", "max", "height"})
    {
        if (!ad->found(key, keyType::LITERAL))
        {
            FatalIOErrorInFunction(*ad)
                << "Entry '" << at.c_str() << key << "' is missing in "
                << dict.name() << " (approach { min (x y z); max (x y z); "
                << "height z; }: the kinematic box and the centre height of "
                << "the blocks placed in the region)" << nl
                << exit(FatalIOError);
        }
    }
    if (id.found("orientations", keyType::LITERAL))
    {
        if (id.found("orientation", keyType::LITERAL))
        {
            FatalIOErrorInFunction(id)
                << "Entries '" << base.c_str() << "orientation' and "
                << "'orientations' are exclusive (one for all types, or one "
                << "per entry of particleTypes); keep one in " << dict.name()
                << nl << exit(FatalIOError);
        }
        const List<vector> angles(id.get<List<vector>>("orientations"));
        if (angles.size() != label(ins.types.size()))
        {
            FatalIOErrorInFunction(id)
                << "Entry '" << base.c_str() << "orientations' must give one "
                << "orientation (a b c) [degrees] per particle type listed ("
                << label(ins.types.size()) << "), not " << angles.size()
                << ", in " << dict.name() << nl << exit(FatalIOError);
        }
        for (const vector& a : angles)
        {
            ins.typeOrientations.push_back(orientationFromAngles(a));
        }
    }
    ins.approach = true;
    ins.approachMin = toVec3(ad->get<vector>("min"));
    ins.approachMax = toVec3(ad->get<vector>("max"));
    ins.height = ad->get<scalar>("height");
    for (int d = 0; d < 3; ++d)
    {
        if (!(ins.approachMin[d] < ins.approachMax[d]))
        {
            FatalIOErrorInFunction(*ad)
                << "Entry '" << at.c_str() << "max' must exceed '"
                << at.c_str() << "min' in every component, in "
                << dict.name() << nl << exit(FatalIOError);
        }
    }
    if (!id.found("velocity", keyType::LITERAL) || !(norm(ins.velocity) > 0))
    {
        FatalIOErrorInFunction(id)
            << "Entry '" << base.c_str() << "velocity' must be given and "
            << "non-zero with an 'approach' region: the particles there move "
            << "at it (the drift of the ice), in " << dict.name() << nl
            << exit(FatalIOError);
    }
    if (ins.gap > 0)
    {
        FatalIOErrorInFunction(id)
            << "Entry '" << base.c_str() << "gap' is not used with an "
            << "'approach' region (blocks are placed with zero overlap "
            << "volume, exactly); remove it from " << dict.name() << nl
            << exit(FatalIOError);
    }
    if (ins.region.kind != polydem::FillRegion::Kind::box)
    {
        FatalIOErrorInFunction(id)
            << "Entry '" << base.c_str() << "region' must be a box with an "
            << "'approach' region, in " << dict.name() << nl
            << exit(FatalIOError);
    }
    const polydem::Vec3& lo = ins.region.min;
    const polydem::Vec3& hi = ins.region.max;
    bool inside = true;
    for (int d = 0; d < 3; ++d)
    {
        inside = inside && lo[d] >= ins.approachMin[d] && hi[d] <= ins.approachMax[d];
    }
    if (!inside)
    {
        FatalIOErrorInFunction(id)
            << "Entry '" << base.c_str() << "region' must lie inside '"
            << at.c_str() << "min/max' (the blocks are placed where they "
            << "move kinematically), in " << dict.name() << nl
            << exit(FatalIOError);
    }
    if (!(ins.height >= lo.z && ins.height <= hi.z))
    {
        FatalIOErrorInFunction(*ad)
            << "Entry '" << at.c_str() << "height' (" << ins.height
            << ") must lie within the region's height [" << lo.z << ", "
            << hi.z << "] (the layer the solid fraction is measured in), in "
            << dict.name() << nl << exit(FatalIOError);
    }
    // All polyhedra or all spheres (the spheres' own diameters)
    for (const int t : ins.types)
    {
        if (userTypes[t].polyhedron != userTypes[ins.types[0]].polyhedron)
        {
            FatalIOErrorInFunction(id)
                << "Entry '" << base.c_str() << "approach': particle types '"
                << userTypes[ins.types[0]].name << "' and '"
                << userTypes[t].name << "' are one a sphere and one a "
                << "polyhedron; the floating layer of an approach region "
                << "places one kind (all spheres or all polyhedra), in "
                << dict.name() << nl << exit(FatalIOError);
        }
    }
}


polydem::InsertionTypes Foam::demInsertionsReader::insertionTypes
(
    const demShapesReader::userType& type
)
{
    polydem::InsertionTypes t;
    t.firstType = type.firstType;
    t.nTypes = type.nTypes;
    t.polyhedron = type.polyhedron;
    return t;
}


// ************************************************************************* //

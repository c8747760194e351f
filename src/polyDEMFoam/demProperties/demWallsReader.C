/*---------------------------------------------------------------------------*\
  Hedra: CFD-DEM for OpenFOAM
-------------------------------------------------------------------------------
Description
    demProperties 'walls' (see demWallsReader.H).

\*---------------------------------------------------------------------------*/

#include "demWallsReader.H"
#include "demMaterialsReader.H"
#include "demPropertiesErrors.H"
#include "demSurfaceReader.H"
#include "polyDEMConversions.H"
#include "IOstreams.H"
#include "mathematicalConstants.H"

using Foam::polyDEMConversions::toVec3;

// * * * * * * * * * * * * Private Static Functions  * * * * * * * * * * * * //

polydem::WallMotion Foam::demWallsReader::readMotion
(
    const dictionary& demProperties,
    const dictionary& wallDict
)
{
    polydem::WallMotion m;
    const dictionary* md = wallDict.findDict("motion");
    if (!md)
    {
        return m;
    }
    demPropertiesErrors::checkKeys
    (
        demProperties, *md, "walls/" + wallDict.dictName() + "/motion",
        {"type", "velocity", "origin", "axis", "rpm", "omega"}
    );
    static const wordList kinds({"fixed", "translation", "rotation"});
    m.kind = polydem::MotionKind
    (
        demPropertiesErrors::selectName(*md, "type", kinds, "wall motion type")
    );
    if (m.kind == polydem::MotionKind::translation)
    {
        m.velocity = toVec3(demPropertiesErrors::boundedVector
        (
            demProperties, *md, "velocity",
            "walls/" + wallDict.dictName() + "/motion/velocity",
            demPropertiesErrors::maxMagnitude, "a velocity (u v w) [m/s]"
        ));
    }
    else if (m.kind == polydem::MotionKind::rotation)
    {
        const std::string at = "walls/" + wallDict.dictName() + "/motion/";
        m.origin = toVec3(demPropertiesErrors::boundedVector
        (
            demProperties, *md, "origin", at + "origin",
            demPropertiesErrors::maxMagnitude, "a point (x y z) [m]"
        ));
        m.axis = toVec3
        (
            demPropertiesErrors::unitDirection(demProperties, *md, "axis", at + "axis")
        );
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


polydem::Vec3 Foam::demWallsReader::readLoadPoint
(
    const dictionary& wallDict,
    const polydem::WallMotion& motion
)
{
    // About the rotation axis unless given: the torque that drives a drum
    if (wallDict.found("loadPoint", keyType::LITERAL))
    {
        return toVec3(demPropertiesErrors::boundedVector
        (
            wallDict, wallDict, "loadPoint",
            "walls/" + wallDict.dictName() + "/loadPoint",
            demPropertiesErrors::maxMagnitude, "a point (x y z) [m]"
        ));
    }
    return motion.kind == polydem::MotionKind::rotation
        ? motion.origin
        : polydem::Vec3();
}


// * * * * * * * * * * * * * * Static Functions  * * * * * * * * * * * * * * //

std::vector<Foam::demWallsReader::wallInfo> Foam::demWallsReader::read
(
    const dictionary& dict,
    polydem::SimulationConfig& config
)
{
    std::vector<wallInfo> walls;
    const dictionary* d = dict.findDict("walls");
    if (!d)
    {
        return walls;
    }
    static const wordList types({"plane", "mesh"});
    for (const entry& e : *d)
    {
        if (!e.isDict())
        {
            FatalIOErrorInFunction(*d)
                << "Entry 'walls/" << e.keyword() << "' must be a dictionary in "
                << dict.name() << nl << exit(FatalIOError);
        }
        const dictionary& wd = e.dict();
        static const wordList wallKeys
        ({
            "type", "point", "normal", "material", "motion", "file", "scale",
            "activeUntil", "displaySize", "loadPoint"
        });
        demPropertiesErrors::checkKeys(dict, wd, "walls/" + e.keyword(), wallKeys);
        wallInfo info;
        info.name = e.keyword();
        info.activeUntil = wd.getOrDefault<scalar>("activeUntil", GREAT);
        if (!(info.activeUntil >= 0))
        {
            FatalIOErrorInFunction(wd)
                << "Entry 'walls/" << e.keyword() << "/activeUntil' must be a "
                << "time >= 0 [s] (leave it out for a wall that stays), not "
                << info.activeUntil << ", in " << dict.name() << nl
                << exit(FatalIOError);
        }
        info.displaySize = wd.getOrDefault<scalar>("displaySize", 0);

        const label kind =
            demPropertiesErrors::selectName(wd, "type", types, "wall type");
        if (kind == 0)
        {
            polydem::PlaneWall w;
            w.name = e.keyword();
            const std::string at = "walls/" + e.keyword() + "/";
            w.point = toVec3(demPropertiesErrors::boundedVector
            (
                dict, wd, "point", at + "point",
                demPropertiesErrors::maxMagnitude, "a point (x y z) [m]"
            ));
            w.normal = toVec3
            (
                demPropertiesErrors::unitDirection(dict, wd, "normal", at + "normal")
            );
            w.material = demMaterialsReader::materialIndex(config, wd, "material");
            w.motion = readMotion(dict, wd);
            w.loadPoint = readLoadPoint(wd, w.motion);
            info.isPlane = true;
            info.index = label(config.planes.size());
            config.planes.push_back(w);
        }
        else
        {
            polydem::MeshWall w;
            w.name = e.keyword();
            w.material = demMaterialsReader::materialIndex(config, wd, "material");
            w.motion = readMotion(dict, wd);
            w.loadPoint = readLoadPoint(wd, w.motion);
            w.mesh = demSurfaceReader::read
            (
                dict, wd, "file", "walls/" + e.keyword() + "/file"
            );
            info.isPlane = false;
            info.index = label(config.meshes.size());
            config.meshes.push_back(std::move(w));
        }
        walls.push_back(info);
    }
    return walls;
}


// ************************************************************************* //

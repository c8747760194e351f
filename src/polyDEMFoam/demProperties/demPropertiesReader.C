/*---------------------------------------------------------------------------*\
  Hedra: CFD-DEM for OpenFOAM
-------------------------------------------------------------------------------
Description
    demProperties -> polydem::SimulationConfig (see demPropertiesReader.H and
    docs/demProperties.md): the general entries, the contact model and the
    output here; materials, particle types, walls and insertions in their
    own readers.

\*---------------------------------------------------------------------------*/

#include "demPropertiesReader.H"
#include "demMaterialsReader.H"
#include "polyDEMConversions.H"
#include "IOstreams.H"

#include "polyDEM/MeshQueries.hpp"
#include "polyDEM/System.hpp"

#include <algorithm>
#include <cmath>

using Foam::polyDEMConversions::toVec3;

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::demPropertiesReader::readGeneral()
{
    // 'monitors' is refused later with a message saying where it moved
    static const wordList topKeys
    ({
        "device", "timeStep", "gravity", "skin", "domain", "contactModel",
        "materials", "interactions", "particleTypes", "walls", "insertion",
        "output", "reportInterval", "freshStart", "monitors", "outlets"
    });
    demPropertiesErrors::checkKeys(dict_, dict_, "", topKeys);

    config_.source = dict_.name();
    config_.device = dict_.getOrDefault<word>("device", "cpu");
    config_.timeStep = dict_.get<scalar>("timeStep");
    // The engine's own check (System::checkTimeStep), done here because
    // demSimulation divides by the time step before it makes the System
    try
    {
        polydem::System::checkTimeStep(config_);
    }
    catch (const polydem::Error& err)
    {
        demPropertiesErrors::reportError(err, dict_);
    }
    config_.gravity =
        dict_.found("gravity", keyType::LITERAL)
      ? toVec3(demPropertiesErrors::boundedVector
        (
            dict_, dict_, "gravity", "gravity",
            demPropertiesErrors::maxMagnitude, "an acceleration (x y z) [m/s2]"
        ))
      : polydem::Vec3(0, 0, -9.81);
    config_.skinFraction = dict_.getOrDefault<scalar>("skin", 0.2);
    if (!(config_.skinFraction > 0))
    {
        FatalIOErrorInFunction(dict_)
            << "Entry 'skin' must be positive (a fraction of the largest "
            << "diameter), not " << config_.skinFraction << ", in "
            << dict_.name() << nl << exit(FatalIOError);
    }

    if (const dictionary* dom = dict_.findDict("domain"))
    {
        demPropertiesErrors::checkKeys(dict_, *dom, "domain", {"min", "max"});
        config_.domainMin = toVec3(demPropertiesErrors::boundedVector
        (
            dict_, *dom, "min", "domain/min",
            demPropertiesErrors::maxMagnitude, "a point (x y z) [m]"
        ));
        config_.domainMax = toVec3(demPropertiesErrors::boundedVector
        (
            dict_, *dom, "max", "domain/max",
            demPropertiesErrors::maxMagnitude, "a point (x y z) [m]"
        ));
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

    // Outlet regions: boxes whose particles are removed, counted per region
    if (dict_.found("outlets", keyType::LITERAL))
    {
        const dictionary* od = dict_.findDict("outlets");
        if (!od)
        {
            FatalIOErrorInFunction(dict_)
                << "Entry 'outlets' must be a dictionary of named boxes, "
                << "outlets { <name> { min (x y z); max (x y z); } }, in "
                << dict_.name() << nl << exit(FatalIOError);
        }
        for (const entry& e : *od)
        {
            const std::string path = "outlets/" + std::string(e.keyword());
            if (!e.isDict())
            {
                FatalIOErrorInFunction(*od)
                    << "Entry '" << path.c_str() << "' must be a dictionary "
                    << "{ min (x y z); max (x y z); } in " << dict_.name()
                    << nl << exit(FatalIOError);
            }
            const dictionary& bd = e.dict();
            demPropertiesErrors::checkKeys(dict_, bd, path, {"min", "max"});
            polydem::OutletRegion o;
            o.name = e.keyword();
            o.min = toVec3(bd.get<vector>("min"));
            o.max = toVec3(bd.get<vector>("max"));
            for (int k = 0; k < 3; ++k)
            {
                if (!(o.min[k] < o.max[k]))
                {
                    FatalIOErrorInFunction(bd)
                        << "Entry '" << path.c_str() << "': min must be below "
                        << "max in every direction, in " << dict_.name() << nl
                        << exit(FatalIOError);
                }
            }
            config_.outlets.push_back(o);
        }
    }
}


void Foam::demPropertiesReader::readContactModel()
{
    const dictionary& d = dict_.subDict("contactModel");
    demPropertiesErrors::checkKeys
    (
        dict_, d, "contactModel",
        {
            "law", "rolling", "twisting", "normalStiffness",
            "volumetricStiffness", "tangentialStiffnessRatio"
        }
    );

    static const wordList laws
    ({
        "hertzMindlin", "linearSpringDashpot", "overlapVolume"
    });
    static const wordList rollings({"none", "constantTorque", "elasticPlastic"});

    config_.contact.law = polydem::ContactLaw(demPropertiesErrors::selectName(d, "law", laws, "contact law"));
    config_.contact.rolling =
        polydem::RollingModel(demPropertiesErrors::selectNameOrDefault(d, "rolling", rollings, "rolling model", 0));
    // Twisting (torsional) resistance about the contact normal: an option of
    // the rolling model, with its coefficient per interaction (twistingFriction)
    config_.contact.twisting = d.getOrDefault<bool>("twisting", false);

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


void Foam::demPropertiesReader::readOutput()
{
    stateFormat_ = polydem::StateFormat::ascii;
    writeVtk_ = true;
    reportInterval_ = dict_.getOrDefault<scalar>("reportInterval", 5);
    if (!(reportInterval_ >= 0))
    {
        FatalIOErrorInFunction(dict_)
            << "Entry 'reportInterval' must be >= 0 [s of wall time], not "
            << reportInterval_ << ", in " << dict_.name() << nl
            << exit(FatalIOError);
    }
    freshStart_ = dict_.getOrDefault<bool>("freshStart", false);
    if (const dictionary* od = dict_.findDict("output"))
    {
        demPropertiesErrors::checkKeys(dict_, *od, "output", {"format", "vtk"});
        static const wordList formats({"ascii", "binary"});
        stateFormat_ = polydem::StateFormat
        (
            demPropertiesErrors::selectNameOrDefault(*od, "format", formats, "state format", 0)
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
    freshStart_(false),
    sceneSize_(0.1)
{
    readGeneral();
    readContactModel();
    demMaterialsReader::readMaterials(dict_, config_);
    demMaterialsReader::readInteractions(dict_, config_);
    userTypes_ = demShapesReader::read(dict_, config_);
    walls_ = demWallsReader::read(dict_, config_);
    insertions_ = demInsertionsReader::read(dict_, config_, userTypes_);
    // The approach regions of the inflows: kinematic boxes in the engine
    for (const auto& ins : insertions_)
    {
        if (ins.approach)
        {
            polydem::ApproachRegion a;
            a.name = ins.name;
            a.min = ins.approachMin;
            a.max = ins.approachMax;
            a.velocity = ins.velocity;
            config_.approaches.push_back(a);
        }
    }
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

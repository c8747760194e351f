/*---------------------------------------------------------------------------*\
  Hedra: CFD-DEM for OpenFOAM
-------------------------------------------------------------------------------
Description
    demProperties 'materials' and 'interactions' (see demMaterialsReader.H).

\*---------------------------------------------------------------------------*/

#include "demMaterialsReader.H"
#include "demPropertiesErrors.H"
#include "IOstreams.H"
#include "wordList.H"

#include <cmath>
#include <vector>

// * * * * * * * * * * * * * * Static Functions  * * * * * * * * * * * * * * //

int Foam::demMaterialsReader::materialIndex
(
    const polydem::SimulationConfig& config,
    const dictionary& d,
    const word& key
)
{
    const word name(d.get<word>(key));
    for (size_t i = 0; i < config.materials.size(); ++i)
    {
        if (config.materials[i].name == name)
        {
            return int(i);
        }
    }
    wordList valid;
    for (const auto& m : config.materials)
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


void Foam::demMaterialsReader::readMaterials
(
    const dictionary& dict,
    polydem::SimulationConfig& config
)
{
    const dictionary& d = dict.subDict("materials");
    for (const entry& e : d)
    {
        if (!e.isDict())
        {
            FatalIOErrorInFunction(d)
                << "Entry 'materials/" << e.keyword()
                << "' must be a dictionary { youngsModulus ..; poissonsRatio ..; "
                << "density ..; } in " << dict.name() << nl
                << exit(FatalIOError);
        }
        const dictionary& md = e.dict();
        demPropertiesErrors::checkKeys
        (
            dict, md, "materials/" + e.keyword(),
            {"youngsModulus", "poissonsRatio", "density"}
        );
        polydem::Material m;
        m.name = e.keyword();
        m.youngsModulus = md.get<scalar>("youngsModulus");
        m.poissonsRatio = md.get<scalar>("poissonsRatio");
        m.density = md.get<scalar>("density");
        config.materials.push_back(m);
    }
    if (config.materials.empty())
    {
        FatalIOErrorInFunction(d)
            << "Entry 'materials' of " << dict.name()
            << " defines no material" << nl << exit(FatalIOError);
    }
}


void Foam::demMaterialsReader::readInteractions
(
    const dictionary& dict,
    polydem::SimulationConfig& config
)
{
    const dictionary& d = dict.subDict("interactions");
    const size_t nm = config.materials.size();
    config.pairs.assign(nm*nm, polydem::PairProperties());
    std::vector<bool> given(nm*nm, false);

    const bool rolling =
        config.contact.rolling != polydem::RollingModel::none;
    const bool twisting = config.contact.twisting;

    auto readPair = [&](const dictionary& pd, polydem::PairProperties& p)
    {
        static const wordList pairKeys
        ({
            "materials", "restitution", "friction", "rollingFriction",
            "rollingDamping", "twistingFriction"
        });
        demPropertiesErrors::checkKeys
        (
            dict, pd, "interactions/" + pd.dictName(), pairKeys
        );
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
        if (twisting)
        {
            p.twistingFriction = pd.get<scalar>("twistingFriction");
        }
        else
        {
            p.twistingFriction = pd.getOrDefault<scalar>("twistingFriction", 0);
        }
        // Ranges checked here, where the pair's own entry is known: the
        // engine's own check can only name "interactions/restitution"
        const std::string where = "interactions/" + pd.dictName();
        auto refuse = [&](const char* key, scalar value, const char* range)
        {
            FatalIOErrorInFunction(pd)
                << "Entry '" << where.c_str() << '/' << key << "' of "
                << dict.name() << " must be " << range << ", got " << value
                << nl << exit(FatalIOError);
        };
        if (!(p.restitution > 0 && p.restitution <= 1))
        {
            refuse("restitution", p.restitution, "in (0, 1]");
        }
        if (!(p.friction >= 0) || !std::isfinite(p.friction))
        {
            refuse("friction", p.friction, "a finite number >= 0");
        }
        if (!(p.rollingFriction >= 0) || !std::isfinite(p.rollingFriction))
        {
            refuse("rollingFriction", p.rollingFriction, "a finite number >= 0");
        }
        if (!(p.rollingDamping >= 0 && p.rollingDamping <= 1))
        {
            refuse
            (
                "rollingDamping", p.rollingDamping,
                "in [0, 1] (a fraction of the critical damping)"
            );
        }
        if (!(p.twistingFriction >= 0) || !std::isfinite(p.twistingFriction))
        {
            refuse
            (
                "twistingFriction", p.twistingFriction,
                "a finite number >= 0 (the twisting resistance coefficient"
                " mu_t, M = mu_t R* Fn)"
            );
        }
    };

    if (const dictionary* def = d.findDict("default"))
    {
        polydem::PairProperties p;
        readPair(*def, p);
        config.pairs.assign(nm*nm, p);
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
                << dict.name() << nl << exit(FatalIOError);
        }
        const dictionary& pd = e.dict();
        const wordList names(pd.get<wordList>("materials"));
        if (names.size() != 2)
        {
            FatalIOErrorInFunction(pd)
                << "Entry 'interactions/" << e.keyword()
                << "/materials' must name two materials, e.g. (glass steel), in "
                << dict.name() << nl << exit(FatalIOError);
        }
        int idx[2];
        for (int k = 0; k < 2; ++k)
        {
            dictionary one;
            one.add("material", names[k]);
            one.name() = pd.name() + "/materials";
            idx[k] = materialIndex(config, one, "material");
        }
        polydem::PairProperties p;
        readPair(pd, p);
        config.pairs[idx[0]*nm + idx[1]] = p;
        config.pairs[idx[1]*nm + idx[0]] = p;
        given[idx[0]*nm + idx[1]] = given[idx[1]*nm + idx[0]] = true;
    }

    for (size_t a = 0; a < nm; ++a)
    {
        for (size_t b = a; b < nm; ++b)
        {
            if (!given[a*nm + b])
            {
                FatalIOErrorInFunction(d)
                    << "Entry 'interactions' of " << dict.name()
                    << " gives no properties for the pair ("
                    << config.materials[a].name.c_str() << ' '
                    << config.materials[b].name.c_str()
                    << "): add a 'default' dictionary or one with "
                    << "materials (" << config.materials[a].name.c_str() << ' '
                    << config.materials[b].name.c_str() << ");" << nl
                    << exit(FatalIOError);
            }
        }
    }
}


// ************************************************************************* //

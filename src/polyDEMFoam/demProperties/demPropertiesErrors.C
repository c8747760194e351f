/*---------------------------------------------------------------------------*\
  Hedra: CFD-DEM for OpenFOAM
-------------------------------------------------------------------------------
Description
    FatalIOError helpers of the demProperties reader (see
    demPropertiesErrors.H).

\*---------------------------------------------------------------------------*/

#include "demPropertiesErrors.H"
#include <cmath>
#include "IOstreams.H"

#include <algorithm>
#include <cctype>
#include <vector>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- Levenshtein distance, case-insensitive (a hint for misspellings)
std::size_t editDistance(const std::string& a, const std::string& b)
{
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j)
    {
        row[j] = j;
    }
    for (std::size_t i = 1; i <= a.size(); ++i)
    {
        std::size_t diag = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j)
        {
            const std::size_t up = row[j];
            const bool same = std::tolower(a[i - 1]) == std::tolower(b[j - 1]);
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (same ? 0 : 1)});
            diag = up;
        }
    }
    return row[b.size()];
}

} // End anonymous namespace

// * * * * * * * * * * * * * * Static Functions  * * * * * * * * * * * * * * //

Foam::label Foam::demPropertiesErrors::selectName
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


Foam::label Foam::demPropertiesErrors::selectNameOrDefault
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


const Foam::scalar Foam::demPropertiesErrors::maxMagnitude = 1e6;


Foam::vector Foam::demPropertiesErrors::boundedVector
(
    const dictionary& top,
    const dictionary& d,
    const word& key,
    const std::string& path,
    const scalar limit,
    const char* what
)
{
    const vector v(d.get<vector>(key));
    for (label k = 0; k < 3; ++k)
    {
        if (!std::isfinite(v[k]) || mag(v[k]) > limit)
        {
            const entry* e = d.findEntry(key, keyType::LITERAL);
            FatalIOError
            (
                FUNCTION_NAME, __FILE__, __LINE__,
                top.name(), e ? e->startLineNumber() : -1
            )
                << "Entry '" << path.c_str() << "' of " << top.name()
                << " must be " << what << " with finite components of at"
                << " most " << limit << " in magnitude, got " << v << nl
                << exit(FatalIOError);
        }
    }
    return v;
}


Foam::vector Foam::demPropertiesErrors::unitDirection
(
    const dictionary& top,
    const dictionary& d,
    const word& key,
    const std::string& path
)
{
    const vector v
    (
        boundedVector(top, d, key, path, maxMagnitude, "a direction (x y z)")
    );
    const scalar m = cmptMax(cmptMag(v));
    if (!(m > 0))
    {
        const entry* e = d.findEntry(key, keyType::LITERAL);
        FatalIOError
        (
            FUNCTION_NAME, __FILE__, __LINE__,
            top.name(), e ? e->startLineNumber() : -1
        )
            << "Entry '" << path.c_str() << "' of " << top.name()
            << " must be a non-zero direction, got " << v << nl
            << exit(FatalIOError);
    }
    const vector u(v/m);
    return u/mag(u);
}


void Foam::demPropertiesErrors::checkKeys
(
    const dictionary& top,
    const dictionary& d,
    const std::string& where,
    const wordList& valid
)
{
    for (const entry& e : d)
    {
        const word& key = e.keyword();
        // OpenFOAM's own: the file header, #-directives and $-variables
        // kept as entries
        if (key == "FoamFile" || key.empty() || key[0] == '#')
        {
            continue;
        }
        if (valid.found(key))
        {
            continue;
        }
        word closest;
        std::size_t best = 3;
        for (const word& v : valid)
        {
            const std::size_t dist = editDistance(key, v);
            if (dist < best)
            {
                best = dist;
                closest = v;
            }
        }
        const std::string path = where.empty() ? std::string(key) : where + "/" + key;
        FatalIOError
        (
            FUNCTION_NAME, __FILE__, __LINE__,
            top.name(), e.startLineNumber()
        )
            << "Unknown entry '" << path.c_str() << "' in " << top.name()
            << nl;
        if (!closest.empty())
        {
            FatalIOError<< "    did you mean '" << closest << "'?" << nl;
        }
        FatalIOError
            << "Valid entries" << (where.empty() ? "" : " of '")
            << where.c_str() << (where.empty() ? "" : "'") << ": " << valid
            << nl << exit(FatalIOError);
    }
}


const Foam::entry* Foam::demPropertiesErrors::findPath
(
    const dictionary& top,
    const std::string& path
)
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


void Foam::demPropertiesErrors::reportError
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


// ************************************************************************* //

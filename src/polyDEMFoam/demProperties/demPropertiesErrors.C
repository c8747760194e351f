/*---------------------------------------------------------------------------*\
  Hedra: CFD-DEM for OpenFOAM
-------------------------------------------------------------------------------
Description
    FatalIOError helpers of the demProperties reader (see
    demPropertiesErrors.H).

\*---------------------------------------------------------------------------*/

#include "demPropertiesErrors.H"
#include "IOstreams.H"

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

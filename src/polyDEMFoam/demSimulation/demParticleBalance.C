/*---------------------------------------------------------------------------*\
  Hedra: CFD-DEM for OpenFOAM
-------------------------------------------------------------------------------
Description
    Particle-count bookkeeping of insertions and removals (see
    demParticleBalance.H).

\*---------------------------------------------------------------------------*/

#include "demParticleBalance.H"
#include "error.H"
#include "IOstreams.H"
#include "OSspecific.H"

#include "polyDEM/StateIO.hpp"

#include <cstdio>
#include <fstream>
#include <iterator>
#include <sstream>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::demParticleBalance::demParticleBalance
(
    const std::vector<std::string>& insertionNames,
    const std::vector<std::string>& outletNames
)
:
    insertions_(1, "initialState"),
    inserted_(),
    insertedMass_(),
    regions_(),
    removed_(),
    removedMass_(),
    log_()
{
    insertions_.insert(insertions_.end(), insertionNames.begin(), insertionNames.end());
    inserted_.assign(insertions_.size(), 0);
    insertedMass_.assign(insertions_.size(), 0);
    regions_.push_back("domain");
    regions_.insert(regions_.end(), outletNames.begin(), outletNames.end());
    removed_.assign(regions_.size(), 0);
    removedMass_.assign(regions_.size(), 0);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::demParticleBalance::addInserted
(
    const size_t k,
    const polydem::ParticleState& p
)
{
    inserted_[k + 1] += int64_t(p.size());
    for (const double m : p.mass)
    {
        insertedMass_[k + 1] += m;
    }
}


void Foam::demParticleBalance::addRemoved
(
    const std::vector<polydem::RemovedParticle>& r
)
{
    for (const auto& q : r)
    {
        const size_t k = size_t(q.region + 1);
        if (k >= removed_.size())
        {
            FatalErrorInFunction
                << "The engine removed particle " << label(q.id)
                << " in region " << q.region << ", but there are only "
                << label(removed_.size() - 1) << " outlets" << nl
                << exit(FatalError);
        }
        ++removed_[k];
        removedMass_[k] += q.mass;
    }
}


int64_t Foam::demParticleBalance::insertedTotal() const
{
    int64_t n = 0;
    for (const int64_t c : inserted_) n += c;
    return n;
}


int64_t Foam::demParticleBalance::removedTotal() const
{
    int64_t n = 0;
    for (const int64_t c : removed_) n += c;
    return n;
}


void Foam::demParticleBalance::check
(
    const int64_t present,
    const std::string& when
) const
{
    if (insertedTotal() - removedTotal() != present)
    {
        FatalErrorInFunction
            << "DEM particle bookkeeping broken " << when.c_str() << ": "
            << label(insertedTotal()) << " inserted - "
            << label(removedTotal()) << " removed != "
            << label(present) << " present" << nl << exit(FatalError);
    }
}


void Foam::demParticleBalance::write
(
    const fileName& file,
    const int64_t step,
    const int64_t present
) const
{
    std::ostringstream os;
    os.precision(17);
    os  << "# polyDEM particle balance: inserted per insertion and removed "
        << "per region (count, mass [kg])\n"
        << "step " << step << "\n"
        << "particles " << present << "\n";
    for (size_t k = 0; k < insertions_.size(); ++k)
    {
        os  << "inserted " << insertions_[k] << ' ' << inserted_[k] << ' '
            << insertedMass_[k] << "\n";
    }
    for (size_t k = 0; k < regions_.size(); ++k)
    {
        os  << "removed " << regions_[k] << ' ' << removed_[k] << ' '
            << removedMass_[k] << "\n";
    }
    const std::string body = os.str();
    char sum[40];
    std::snprintf
    (
        sum, sizeof(sum), "checksum %016llx\n",
        static_cast<unsigned long long>(polydem::fnv1a(body.data(), body.size()))
    );
    const std::string tmp = file + ".tmp";
    {
        std::ofstream out(tmp, std::ios::binary);
        out << body << sum;
        if (!out)
        {
            FatalErrorInFunction
                << "Cannot write " << tmp << nl << exit(FatalError);
        }
    }
    Foam::mv(tmp, file);
}


bool Foam::demParticleBalance::read
(
    const fileName& file,
    const int64_t step,
    const int64_t present
)
{
    if (!isFile(file))
    {
        WarningInFunction
            << "The DEM state has no particle balance (" << file
            << " is missing: written by an earlier Hedra): counting its "
            << label(present) << " particles as inserted, none removed"
            << endl;
        inserted_.assign(inserted_.size(), 0);
        insertedMass_.assign(insertedMass_.size(), 0);
        inserted_[0] = present;
        return false;
    }

    std::ifstream in(file, std::ios::binary);
    const std::string text
    (
        (std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>()
    );
    const size_t at = text.rfind("checksum ");
    auto fail = [&file](const std::string& why)
    {
        FatalIOErrorInFunction(file)
            << "The DEM particle balance " << file << " " << why.c_str()
            << nl << "It is written with the state (<time>/polyDEM/state) "
            << "and must belong to it: restore both from one write, or "
            << "remove it to count the state's particles as inserted." << nl
            << exit(FatalIOError);
    };
    if (at == std::string::npos || (at > 0 && text[at - 1] != '\n'))
    {
        fail("has no checksum line (truncated or edited)");
    }
    const std::string body = text.substr(0, at);
    unsigned long long stored = 0;
    if
    (
        std::sscanf(text.c_str() + at, "checksum %llx", &stored) != 1
     || stored != polydem::fnv1a(body.data(), body.size())
    )
    {
        fail("does not match its checksum (damaged or edited)");
    }

    std::istringstream is(body);
    std::string line;
    int64_t fileStep = -1, fileCount = -1;
    std::vector<bool> seenInsertion(insertions_.size(), false);
    while (std::getline(is, line))
    {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream ls(line);
        std::string key, name;
        ls >> key;
        if (key == "step") { ls >> fileStep; continue; }
        if (key == "particles") { ls >> fileCount; continue; }
        int64_t n = 0;
        double m = 0;
        ls >> name >> n >> m;
        if (!ls)
        {
            fail("has a malformed line: '" + line + "'");
        }
        if (key == "inserted")
        {
            bool found = false;
            for (size_t k = 0; k < insertions_.size(); ++k)
            {
                if (insertions_[k] == name)
                {
                    inserted_[k] = n;
                    insertedMass_[k] = m;
                    seenInsertion[k] = true;
                    found = true;
                }
            }
            if (!found && n != 0)
            {
                fail
                (
                    "counts " + std::to_string(n) + " particles of insertion '"
                  + name + "', which is no longer in demProperties"
                );
            }
        }
        else if (key == "removed")
        {
            bool found = false;
            for (size_t k = 0; k < regions_.size(); ++k)
            {
                if (regions_[k] == name)
                {
                    removed_[k] = n;
                    removedMass_[k] = m;
                    found = true;
                }
            }
            if (!found)
            {
                // An outlet removed since: its particles are gone all the same
                removed_[0] += n;
                removedMass_[0] += m;
            }
        }
        else
        {
            fail("has an unknown line: '" + line + "'");
        }
    }
    if (fileStep != step || fileCount != present)
    {
        fail
        (
            "is for step " + std::to_string(fileStep) + " with "
          + std::to_string(fileCount) + " particles, the state for step "
          + std::to_string(step) + " with " + std::to_string(present)
        );
    }
    if (insertedTotal() - removedTotal() != present)
    {
        fail
        (
            "counts " + std::to_string(insertedTotal()) + " inserted - "
          + std::to_string(removedTotal()) + " removed, not the state's "
          + std::to_string(present) + " particles"
        );
    }
    return true;
}


void Foam::demParticleBalance::openLog(const fileName& dir)
{
    mkDir(dir);
    log_.reset(new OFstream(dir/"particleBalance.dat"));
    OFstream& os = log_();
    os.precision(10);
    os  << "# DEM particle balance: balance = inserted - removed - particles "
        << "(zero); counts cumulative over the run including before a "
        << "restart; masses [kg]" << nl
        << "# time step particles inserted removed balance";
    for (const auto& n : insertions_)
    {
        os  << " inserted_" << n.c_str();
    }
    for (const auto& n : regions_)
    {
        os  << " removed_" << n.c_str();
    }
    for (const auto& n : insertions_)
    {
        os  << " insertedMass_" << n.c_str();
    }
    for (const auto& n : regions_)
    {
        os  << " removedMass_" << n.c_str();
    }
    os  << endl;
}


void Foam::demParticleBalance::sample
(
    const double time,
    const int64_t step,
    const int64_t present
)
{
    if (!log_.valid())
    {
        return;
    }
    OFstream& os = log_();
    os  << time << ' ' << label(step) << ' ' << label(present) << ' '
        << label(insertedTotal()) << ' ' << label(removedTotal()) << ' '
        << label(insertedTotal() - removedTotal() - present);
    for (const int64_t n : inserted_) os << ' ' << label(n);
    for (const int64_t n : removed_) os << ' ' << label(n);
    for (const double m : insertedMass_) os << ' ' << m;
    for (const double m : removedMass_) os << ' ' << m;
    os  << endl;
}


// ************************************************************************* //

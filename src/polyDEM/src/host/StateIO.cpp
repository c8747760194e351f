#include "polyDEM/StateIO.hpp"

#include "polyDEM/Error.hpp"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace polydem
{

namespace
{

const char* magic = "polyDEMState";
// 3: a pair's contact normal after its springs (PairHistory::normal)
const int version = 3;

//- The last line of a version-2 file: "checksum " + 16 hex digits + newline
const std::size_t checksumKeyLength = 9;
const std::size_t checksumLineLength = checksumKeyLength + 16 + 1;

// The per-particle record: the order of the columns in both formats
template<class Visit>
void visitParticle(ParticleState& p, std::size_t i, Visit&& v)
{
    double idd = 0, typed = 0;
    (void)idd;
    (void)typed;
    v(p.radius[i]); v(p.mass[i]);
    v(p.inertia[i].x); v(p.inertia[i].y); v(p.inertia[i].z);
    v(p.position[i].x); v(p.position[i].y); v(p.position[i].z);
    v(p.orientation[i].w); v(p.orientation[i].x); v(p.orientation[i].y); v(p.orientation[i].z);
    v(p.velocity[i].x); v(p.velocity[i].y); v(p.velocity[i].z);
    v(p.omega[i].x); v(p.omega[i].y); v(p.omega[i].z);
    v(p.force[i].x); v(p.force[i].y); v(p.force[i].z);
    v(p.torque[i].x); v(p.torque[i].y); v(p.torque[i].z);
}

void writeDouble(std::ostream& os, double x, bool binary)
{
    if (binary)
    {
        os.write(reinterpret_cast<const char*>(&x), sizeof x);
    }
    else
    {
        char buf[32];
        std::snprintf(buf, sizeof buf, " %.17g", x);
        os << buf;
    }
}

void writeInt(std::ostream& os, std::int64_t x, bool binary)
{
    if (binary) os.write(reinterpret_cast<const char*>(&x), sizeof x);
    else os << ' ' << x;
}

void writeVec(std::ostream& os, const Vec3& v, bool binary)
{
    writeDouble(os, v.x, binary);
    writeDouble(os, v.y, binary);
    writeDouble(os, v.z, binary);
}

class Reader
{
public:
    Reader(std::istream& is, const std::string& path, bool binary)
        : is_(is), path_(path), binary_(binary)
    {}

    double real(const char* what)
    {
        double x;
        if (binary_) is_.read(reinterpret_cast<char*>(&x), sizeof x);
        else is_ >> x;
        if (!is_) fail(what);
        return x;
    }

    std::int64_t integer(const char* what)
    {
        std::int64_t x;
        if (binary_) is_.read(reinterpret_cast<char*>(&x), sizeof x);
        else is_ >> x;
        if (!is_) fail(what);
        return x;
    }

    Vec3 vec(const char* what)
    {
        Vec3 v;
        v.x = real(what);
        v.y = real(what);
        v.z = real(what);
        return v;
    }

    void keyword(const std::string& expected)
    {
        std::string word;
        is_ >> word;
        if (word != expected) fail(("'" + expected + "' (found '" + word + "')").c_str());
    }

    [[noreturn]] void fail(const char* what)
    {
        throw Error(std::string("truncated or malformed state file: expected ") + what, path_);
    }

private:
    std::istream& is_;
    std::string path_;
    bool binary_;
};

} // namespace


std::uint64_t fnv1a(const char* data, std::size_t n, std::uint64_t h)
{
    for (std::size_t i = 0; i < n; ++i)
    {
        h ^= static_cast<unsigned char>(data[i]);
        h *= 1099511628211ull;
    }
    return h;
}


std::uint64_t shapeChecksum(const SimulationConfig& config, int t)
{
    const ParticleType& type = config.types.at(std::size_t(t));
    std::string text = type.shape == ShapeKind::polyhedron ? "polyhedron" : "sphere";
    if (type.shape == ShapeKind::polyhedron && type.shapeIndex >= 0
        && std::size_t(type.shapeIndex) < config.shapes.size())
    {
        const ConvexShape& c = config.shapes[std::size_t(type.shapeIndex)];
        char buf[96];
        for (const Vec3& v : c.vertices)
        {
            std::snprintf(buf, sizeof buf, " %.12g %.12g %.12g", v.x, v.y, v.z);
            text += buf;
        }
        text += " |";
        for (int k : c.faceStart) text += ' ' + std::to_string(k);
        text += " |";
        for (int k : c.faceVertex) text += ' ' + std::to_string(k);
    }
    return fnv1a(text.data(), text.size());
}


std::vector<StateTypeRecord> stateTypeRecords(const SimulationConfig& config)
{
    std::vector<StateTypeRecord> records(config.types.size());
    for (std::size_t t = 0; t < records.size(); ++t)
    {
        records[t].name = config.types[t].name;
        records[t].shapeChecksum = shapeChecksum(config, int(t));
    }
    return records;
}


void writeSnapshot
(
    const std::string& path,
    const Snapshot& s,
    StateFormat format,
    const std::vector<StateTypeRecord>& types
)
{
    const bool binary = format == StateFormat::binary;
    std::ostringstream os(std::ios::binary);
    // The header is text in both formats
    os << magic << ' ' << version << ' ' << (binary ? "binary" : "ascii") << '\n';
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.17g", s.time);
    os << "time " << buf << "\nstep " << s.step << "\nforcesValid " << int(s.forcesValid)
       << "\nparticles " << s.particles.size() << "\npairs " << s.pairs.size()
       << "\nwalls " << s.walls.size()
       << "\nexternal " << (s.externalForce.empty() ? 0 : 1) << ' ' << (s.externalTorque.empty() ? 0 : 1)
       << "\ntypes " << types.size() << '\n';
    for (const StateTypeRecord& t : types)
    {
        if (t.name.empty() || t.name.find_first_of(" \t\n") != std::string::npos)
        {
            throw Error("particle type name '" + t.name + "' is empty or has white space", path);
        }
        std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(t.shapeChecksum));
        os << "type " << t.name << ' ' << buf << '\n';
    }
    os << "data\n";

    ParticleState& p = const_cast<ParticleState&>(s.particles);
    for (std::size_t i = 0; i < p.size(); ++i)
    {
        writeInt(os, p.id[i], binary);
        writeInt(os, p.type[i], binary);
        visitParticle(p, i, [&](double& x) { writeDouble(os, x, binary); });
        writeVec(os, i < s.referencePosition.size() ? s.referencePosition[i] : p.position[i], binary);
        if (!binary) os << '\n';
    }
    for (const auto& h : s.pairs)
    {
        writeInt(os, h.idA, binary);
        writeInt(os, h.idB, binary);
        writeVec(os, h.tangential, binary);
        writeVec(os, h.rolling, binary);
        writeVec(os, h.normal, binary);
        if (!binary) os << '\n';
    }
    for (const auto& h : s.walls)
    {
        writeInt(os, h.id, binary);
        writeInt(os, h.wall, binary);
        writeInt(os, h.triangle, binary);
        writeVec(os, h.normal, binary);
        writeVec(os, h.tangential, binary);
        writeVec(os, h.rolling, binary);
        if (!binary) os << '\n';
    }
    for (const Vec3& f : s.externalForce)
    {
        writeVec(os, f, binary);
        if (!binary) os << '\n';
    }
    for (const Vec3& t : s.externalTorque)
    {
        writeVec(os, t, binary);
        if (!binary) os << '\n';
    }

    std::string content = os.str();
    std::snprintf
    (
        buf, sizeof buf, "checksum %016llx\n",
        static_cast<unsigned long long>(fnv1a(content.data(), content.size()))
    );
    content += buf;

    const std::string tmp = path + ".tmp";
    {
        std::ofstream file(tmp, std::ios::binary | std::ios::trunc);
        if (!file)
        {
            throw Error("cannot open for writing", tmp);
        }
        file.write(content.data(), std::streamsize(content.size()));
        file.flush();
        if (!file)
        {
            std::remove(tmp.c_str());
            throw Error("write failed (disk full?)", tmp);
        }
    }
    if (std::rename(tmp.c_str(), path.c_str()) != 0)
    {
        std::remove(tmp.c_str());
        throw Error("cannot rename " + tmp + " to the state file", path);
    }
}


Snapshot readSnapshot(const std::string& path, StateFileInfo* info)
{
    std::string content;
    {
        std::ifstream file(path, std::ios::binary);
        if (!file)
        {
            throw Error("cannot open state file", path);
        }
        std::ostringstream all;
        all << file.rdbuf();
        content = all.str();
    }

    StateFileInfo found;
    {
        std::istringstream head(content.substr(0, 64));
        std::string m, fmt;
        head >> m >> found.version >> fmt;
        if (m != magic || found.version < 1 || found.version > version || (fmt != "ascii" && fmt != "binary"))
        {
            throw Error("not a polyDEM state file (versions 1-3, ascii or binary)", path);
        }
    }

    // The checksum line, when there is one, covers every byte before it
    if (found.version >= 2 && content.size() >= checksumLineLength
        && content.compare(content.size() - checksumLineLength, checksumKeyLength, "checksum ") == 0
        && content.back() == '\n')
    {
        const std::size_t body = content.size() - checksumLineLength;
        const std::string stored = content.substr(body + checksumKeyLength, 16);
        char computed[32];
        std::snprintf
        (
            computed, sizeof computed, "%016llx",
            static_cast<unsigned long long>(fnv1a(content.data(), body))
        );
        if (stored != computed)
        {
            throw Error
            (
                "checksum mismatch (stored " + stored + ", contents give " + computed
                    + "): the state file was changed or damaged after it was written. "
                    "Restart from another time, or, for a state edited on purpose, "
                    "delete its last line (checksum) to have it read unchecked",
                path
            );
        }
        content.resize(body);
        found.checksummed = true;
    }

    std::istringstream is(content, std::ios::binary);
    std::string m, fmt;
    int ver = 0;
    is >> m >> ver >> fmt;
    const bool binary = fmt == "binary";
    Reader text(is, path, false);
    Snapshot s;
    text.keyword("time");
    s.time = text.real("time value");
    text.keyword("step");
    s.step = text.integer("step value");
    text.keyword("forcesValid");
    s.forcesValid = text.integer("forcesValid value") != 0;
    text.keyword("particles");
    const std::int64_t np = text.integer("particle count");
    text.keyword("pairs");
    const std::int64_t npair = text.integer("pair count");
    text.keyword("walls");
    const std::int64_t nwall = text.integer("wall-contact count");
    text.keyword("external");
    const bool hasForce = text.integer("external force flag") != 0;
    const bool hasTorque = text.integer("external torque flag") != 0;
    if (ver >= 2)
    {
        text.keyword("types");
        const std::int64_t ntype = text.integer("type count");
        if (ntype < 0 || ntype > 1000000)
        {
            text.fail("a type count of 0 to 1000000");
        }
        found.types.resize(std::size_t(ntype));
        for (StateTypeRecord& t : found.types)
        {
            text.keyword("type");
            std::string hex;
            is >> t.name >> hex;
            char* end = nullptr;
            t.shapeChecksum = std::strtoull(hex.c_str(), &end, 16);
            if (!is || hex.size() != 16 || !end || *end != '\0')
            {
                text.fail("'type <name> <16 hex digits>'");
            }
        }
    }
    text.keyword("data");
    is.get(); // the newline after 'data'
    if (np < 0 || npair < 0 || nwall < 0)
    {
        throw Error("negative counts in the header", path);
    }

    Reader r(is, path, binary);
    ParticleState& p = s.particles;
    p.resize(std::size_t(np));
    s.referencePosition.resize(std::size_t(np));
    for (std::size_t i = 0; i < p.size(); ++i)
    {
        p.id[i] = r.integer("particle id");
        p.type[i] = int(r.integer("particle type"));
        visitParticle(p, i, [&](double& x) { x = r.real("particle data"); });
        s.referencePosition[i] = r.vec("reference position");
    }
    s.pairs.resize(std::size_t(npair));
    for (auto& h : s.pairs)
    {
        h.idA = r.integer("pair id");
        h.idB = r.integer("pair id");
        h.tangential = r.vec("pair spring");
        h.rolling = r.vec("pair rolling spring");
        if (ver >= 3) h.normal = r.vec("pair contact normal");
    }
    s.walls.resize(std::size_t(nwall));
    for (auto& h : s.walls)
    {
        h.id = r.integer("wall-contact particle id");
        h.wall = int(r.integer("wall index"));
        h.triangle = int(r.integer("triangle index"));
        h.normal = r.vec("wall-contact normal");
        h.tangential = r.vec("wall spring");
        h.rolling = r.vec("wall rolling spring");
    }
    if (hasForce)
    {
        s.externalForce.resize(p.size());
        for (Vec3& f : s.externalForce) f = r.vec("external force");
    }
    if (hasTorque)
    {
        s.externalTorque.resize(p.size());
        for (Vec3& t : s.externalTorque) t = r.vec("external torque");
    }

    // Nothing may follow the records but white space (a damaged checksum
    // line, or records the header does not count)
    is >> std::ws;
    if (is.peek() != std::char_traits<char>::eof())
    {
        std::string rest;
        std::getline(is, rest);
        throw Error
        (
            "unexpected content after the records the header counts ('" + rest.substr(0, 40)
                + "'): a damaged or foreign state file",
            path
        );
    }

    for (std::size_t i = 0; i < p.size(); ++i)
    {
        if (p.type[i] < 0 || (!found.types.empty() && std::size_t(p.type[i]) >= found.types.size()))
        {
            throw Error
            (
                "particle id " + std::to_string(p.id[i]) + " has type index " + std::to_string(p.type[i])
                    + ", outside the " + std::to_string(found.types.size()) + " types of the header",
                path
            );
        }
    }

    if (info)
    {
        *info = std::move(found);
    }
    return s;
}

} // namespace polydem

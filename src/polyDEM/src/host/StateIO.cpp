#include "polyDEM/StateIO.hpp"

#include "polyDEM/Error.hpp"

#include <cstdio>
#include <fstream>
#include <sstream>

namespace polydem
{

namespace
{

const char* magic = "polyDEMState";
const int version = 1;

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


void writeSnapshot(const std::string& path, const Snapshot& s, StateFormat format)
{
    const bool binary = format == StateFormat::binary;
    std::ofstream os(path, std::ios::binary);
    if (!os)
    {
        throw Error("cannot open for writing", path);
    }
    // The header is text in both formats
    os << magic << ' ' << version << ' ' << (binary ? "binary" : "ascii") << '\n';
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.17g", s.time);
    os << "time " << buf << "\nstep " << s.step << "\nforcesValid " << int(s.forcesValid)
       << "\nparticles " << s.particles.size() << "\npairs " << s.pairs.size()
       << "\nwalls " << s.walls.size()
       << "\nexternal " << (s.externalForce.empty() ? 0 : 1) << ' ' << (s.externalTorque.empty() ? 0 : 1)
       << "\ndata\n";

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
    if (!os)
    {
        throw Error("write failed (disk full?)", path);
    }
}


Snapshot readSnapshot(const std::string& path)
{
    std::ifstream is(path, std::ios::binary);
    if (!is)
    {
        throw Error("cannot open state file", path);
    }
    std::string m, fmt;
    int ver = 0;
    is >> m >> ver >> fmt;
    if (m != magic || ver != version || (fmt != "ascii" && fmt != "binary"))
    {
        throw Error("not a polyDEM state file (version 1, ascii or binary)", path);
    }
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
    return s;
}

} // namespace polydem

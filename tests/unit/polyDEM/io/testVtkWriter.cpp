// Tests of the VTK PolyData writers and of .pvd collections across restarts.

#include "TestMeshes.hpp"

#include "polyDEM/Error.hpp"
#include "polyDEM/VtkWriter.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <map>
#include <sstream>
#include <vector>

using namespace polydem;
using namespace polydem::test;

namespace
{

// Minimal XML check: tags balanced and properly nested; returns the element
// name -> text content of each DataArray by Name (unnamed: "<unnamed k>")
struct XmlSummary
{
    bool balanced = true;
    std::string error;
    std::map<std::string, std::string> attributes; // first Piece's attributes
    std::map<std::string, std::string> arrays;     // DataArray Name -> text
    std::vector<std::string> arrayOrder;
};

std::string attributeOf(const std::string& tag, const std::string& name)
{
    const std::string key = " " + name + "=\"";
    const std::size_t p = tag.find(key);
    if (p == std::string::npos)
    {
        return "";
    }
    const std::size_t s = p + key.size();
    return tag.substr(s, tag.find('"', s) - s);
}

XmlSummary parseXml(const std::string& text)
{
    XmlSummary r;
    std::vector<std::string> stack;
    std::size_t pos = 0;
    std::string openArray;
    std::size_t arrayStart = 0;
    int unnamed = 0;
    while ((pos = text.find('<', pos)) != std::string::npos)
    {
        const std::size_t end = text.find('>', pos);
        if (end == std::string::npos)
        {
            r.balanced = false;
            r.error = "unterminated tag";
            return r;
        }
        const std::string tag = text.substr(pos, end - pos + 1);
        if (tag.rfind("<?", 0) == 0)
        {
            pos = end;
            continue;
        }
        const bool closing = tag[1] == '/';
        const bool selfClosing = tag[tag.size() - 2] == '/';
        std::string name = tag.substr(closing ? 2 : 1);
        name = name.substr(0, name.find_first_of(" />"));
        if (closing)
        {
            if (stack.empty() || stack.back() != name)
            {
                r.balanced = false;
                r.error = "unexpected </" + name + ">";
                return r;
            }
            stack.pop_back();
            if (name == "DataArray")
            {
                r.arrays[openArray] = text.substr(arrayStart, pos - arrayStart);
            }
        }
        else if (!selfClosing)
        {
            stack.push_back(name);
            if (name == "DataArray")
            {
                openArray = attributeOf(tag, "Name");
                if (openArray.empty())
                {
                    openArray = "<unnamed " + std::to_string(unnamed++) + ">";
                }
                r.arrayOrder.push_back(openArray);
                arrayStart = end + 1;
            }
            if (name == "Piece")
            {
                for (const char* a : {"NumberOfPoints", "NumberOfVerts", "NumberOfPolys"})
                {
                    r.attributes[a] = attributeOf(tag, a);
                }
            }
        }
        pos = end;
    }
    if (!stack.empty())
    {
        r.balanced = false;
        r.error = "unclosed <" + stack.back() + ">";
    }
    return r;
}

std::vector<double> numbers(const std::string& text)
{
    std::istringstream is(text);
    std::vector<double> v;
    double x;
    while (is >> x)
    {
        v.push_back(x);
    }
    return v;
}

ParticleState threeParticles()
{
    ParticleState s;
    s.resize(3);
    for (int i = 0; i < 3; ++i)
    {
        s.id[i] = 1000000000000LL + i;
        s.type[i] = i % 2;
        s.radius[i] = 0.001 * (i + 1);
        s.mass[i] = 1e-6 * (i + 1);
        s.position[i] = {0.1 + 0.2 * i, 1.0 / 3.0, -1e-17 * i};
        s.velocity[i] = {1, 2, 3.5};
        s.omega[i] = {0, 0, 100};
        s.force[i] = {0, 0, -9.81e-6};
        s.orientation[i] = normalised(Quaternion{1, 0.1 * i, 0, 0});
    }
    return s;
}

} // namespace


TEST(VtkWriter, particlesParseAndRoundTrip)
{
    const std::string path = tempPath("particles.vtp");
    const ParticleState s = threeParticles();
    writeParticlesVtp(path, s);
    const XmlSummary x = parseXml(slurp(path));
    ASSERT_TRUE(x.balanced) << x.error;
    EXPECT_EQ(x.attributes.at("NumberOfPoints"), "3");
    EXPECT_EQ(x.attributes.at("NumberOfVerts"), "3");

    const std::map<std::string, std::size_t> components = {
        {"id", 1}, {"type", 1}, {"radius", 1}, {"diameter", 1}, {"mass", 1}, {"velocity", 3},
        {"omega", 3}, {"force", 3}, {"torque", 3}, {"orientation", 4}, {"position", 3},
        {"connectivity", 1}, {"offsets", 1}};
    for (const auto& [name, nc] : components)
    {
        ASSERT_TRUE(x.arrays.count(name)) << name;
        EXPECT_EQ(numbers(x.arrays.at(name)).size(), 3 * nc) << name;
    }
    // Full precision: positions read back bit for bit
    const auto pos = numbers(x.arrays.at("position"));
    for (int i = 0; i < 3; ++i)
    {
        EXPECT_EQ(pos[3 * i], s.position[i].x);
        EXPECT_EQ(pos[3 * i + 1], s.position[i].y);
        EXPECT_EQ(pos[3 * i + 2], s.position[i].z);
    }
    EXPECT_EQ(numbers(x.arrays.at("diameter"))[2], 0.006);
    EXPECT_NE(x.arrays.at("id").find("1000000000002"), std::string::npos);
    std::remove(path.c_str());
}

TEST(VtkWriter, emptyAndInconsistentState)
{
    const std::string path = tempPath("none.vtp");
    writeParticlesVtp(path, ParticleState{});
    const XmlSummary x = parseXml(slurp(path));
    EXPECT_TRUE(x.balanced) << x.error;
    EXPECT_EQ(x.attributes.at("NumberOfPoints"), "0");

    ParticleState s = threeParticles();
    s.velocity.pop_back();
    try
    {
        writeParticlesVtp(path, s);
        FAIL();
    }
    catch (const Error& e)
    {
        EXPECT_EQ(e.entry(), "velocity");
    }
    std::remove(path.c_str());
}

TEST(VtkWriter, surfaceWithIds)
{
    const std::string path = tempPath("surface.vtp");
    const TriangleMesh cube = unitCube();
    std::vector<int> ids(cube.triangles.size());
    for (std::size_t i = 0; i < ids.size(); ++i)
    {
        ids[i] = int(i / 2);
    }
    writeSurfaceVtp(path, cube, ids, "patch");
    XmlSummary x = parseXml(slurp(path));
    ASSERT_TRUE(x.balanced) << x.error;
    EXPECT_EQ(x.attributes.at("NumberOfPoints"), "8");
    EXPECT_EQ(x.attributes.at("NumberOfPolys"), "12");
    EXPECT_EQ(numbers(x.arrays.at("points")).size(), 24u);
    EXPECT_EQ(numbers(x.arrays.at("connectivity")).size(), 36u);
    EXPECT_EQ(numbers(x.arrays.at("offsets")).back(), 36);
    EXPECT_EQ(numbers(x.arrays.at("patch")).size(), 12u);

    // Mixed polygons (a polyhedron's faces), no ids
    const std::vector<Vec3> pts = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 0.5, 1}};
    const std::vector<std::vector<int>> faces = {
        {0, 3, 2, 1}, {0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}};
    writeSurfaceVtp(path, pts, faces);
    x = parseXml(slurp(path));
    ASSERT_TRUE(x.balanced) << x.error;
    EXPECT_EQ(numbers(x.arrays.at("offsets")), (std::vector<double>{4, 7, 10, 13, 16}));

    EXPECT_THROW(writeSurfaceVtp(path, pts, {{0, 1, 5}}), Error);
    EXPECT_THROW(writeSurfaceVtp(path, pts, {{0, 1}}), Error);
    EXPECT_THROW(writeSurfaceVtp(path, pts, faces, {1, 2}), Error);
    std::remove(path.c_str());
}

TEST(VtkWriter, particleFacesCarryTheParticleFields)
{
    // A pyramid (5 faces) for particle 2 and a triangle for particle 0: each
    // face carries its particle's fields, and the volume-equivalent diameter
    const std::string path = tempPath("faces.vtp");
    const ParticleState s = threeParticles();
    const std::vector<Vec3> pts = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 0.5, 1}};
    const std::vector<std::vector<int>> faces = {
        {0, 3, 2, 1}, {0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}, {0, 1, 2}};
    const std::vector<std::size_t> owner = {2, 2, 2, 2, 2, 0};
    const std::vector<double> dv = {1e-3, 2e-3, 3e-3};
    writeParticleFacesVtp(path, pts, faces, owner, s, dv);
    const XmlSummary x = parseXml(slurp(path));
    ASSERT_TRUE(x.balanced) << x.error;
    EXPECT_EQ(x.attributes.at("NumberOfPolys"), "6");
    const std::map<std::string, std::size_t> components = {
        {"id", 1}, {"particleId", 1}, {"type", 1}, {"radius", 1}, {"diameter", 1},
        {"volumeEquivalentDiameter", 1}, {"mass", 1}, {"velocity", 3}, {"omega", 3},
        {"force", 3}, {"torque", 3}, {"orientation", 4}};
    for (const auto& [name, nc] : components)
    {
        ASSERT_TRUE(x.arrays.count(name)) << name;
        EXPECT_EQ(numbers(x.arrays.at(name)).size(), 6 * nc) << name;
    }
    const auto mass = numbers(x.arrays.at("mass"));
    const auto d = numbers(x.arrays.at("volumeEquivalentDiameter"));
    const auto q = numbers(x.arrays.at("orientation"));
    for (std::size_t f = 0; f < 6; ++f)
    {
        EXPECT_EQ(mass[f], s.mass[owner[f]]);
        EXPECT_EQ(d[f], dv[owner[f]]);
        EXPECT_EQ(q[4 * f + 1], s.orientation[owner[f]].x);
    }
    EXPECT_NE(x.arrays.at("particleId").find("1000000000002"), std::string::npos);

    // A face of no particle, an owner list of the wrong length, a diameter
    // list of the wrong length
    EXPECT_THROW(writeParticleFacesVtp(path, pts, faces, {2, 2, 2, 2, 2, 3}, s), Error);
    EXPECT_THROW(writeParticleFacesVtp(path, pts, faces, {2, 2}, s), Error);
    EXPECT_THROW(writeParticleFacesVtp(path, pts, faces, owner, s, {1e-3}), Error);
    std::remove(path.c_str());
}

TEST(PvdCollection, appendAfterRestart)
{
    const std::string path = tempPath("particles.pvd");
    std::remove(path.c_str());

    PvdCollection first;
    EXPECT_FALSE(first.read(path)); // fresh start
    for (int i = 0; i < 5; ++i)
    {
        first.add(0.1 * i, "VTK/particles_" + std::to_string(i) + ".vtp");
        first.add(0.1 * i, "VTK/walls_" + std::to_string(i) + ".vtp", 1);
        first.write(path);
    }
    ASSERT_TRUE(parseXml(slurp(path)).balanced);

    // Restart from t = 0.2: entries at 0.2 and later are rewritten by the new run
    PvdCollection restarted;
    ASSERT_TRUE(restarted.read(path, 0.2 - 1e-12));
    ASSERT_EQ(restarted.entries().size(), 4u);
    EXPECT_EQ(restarted.entries()[0].file, "VTK/particles_0.vtp");
    EXPECT_EQ(restarted.entries()[3].part, 1);
    EXPECT_EQ(restarted.entries()[3].time, 0.1);
    restarted.add(0.2, "VTK/particles_2b.vtp");
    restarted.add(0.3, "VTK/particles_3b.vtp");
    restarted.write(path);

    PvdCollection all;
    ASSERT_TRUE(all.read(path));
    ASSERT_EQ(all.entries().size(), 6u);
    EXPECT_EQ(all.entries().back().file, "VTK/particles_3b.vtp");
    EXPECT_EQ(all.entries().back().time, 0.3);

    // Same time and part replaces; going back in time drops later entries
    all.add(0.3, "VTK/particles_3c.vtp");
    EXPECT_EQ(all.entries().size(), 6u);
    all.add(0.15, "VTK/x.vtp");
    EXPECT_EQ(all.entries().size(), 5u);

    spit(path, "<html>not a collection</html>");
    EXPECT_THROW(all.read(path), Error);
    spit(path, "<VTKFile type=\"Collection\"><Collection><DataSet file=\"a.vtp\"/>"
               "</Collection></VTKFile>");
    EXPECT_THROW(all.read(path), Error);
    std::remove(path.c_str());
}

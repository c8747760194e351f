// State file checks (polyDEM/StateIO.hpp): the type table round-trips, the
// checksum catches one changed digit (ASCII) and one flipped bit (binary) and
// names the file, a damaged checksum line is not taken for the end of the
// file, version-1 files (no types, no checksum) are still read, and the write
// leaves no temporary file behind.
#include "polyDEM/Error.hpp"
#include "polyDEM/StateIO.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <sstream>

using namespace polydem;

namespace
{

Snapshot smallState()
{
    Snapshot s;
    s.time = 0.125;
    s.step = 6250;
    s.forcesValid = true;
    s.particles.resize(3);
    for (std::size_t i = 0; i < 3; ++i)
    {
        s.particles.id[i] = std::int64_t(10 + i);
        s.particles.type[i] = int(i % 2);
        s.particles.radius[i] = 1e-3*(1 + 0.1*double(i));
        s.particles.mass[i] = 1.0/3.0 + double(i);
        s.particles.position[i] = Vec3(0.1*double(i), -0.2, 0.3 + 1e-17);
        s.particles.velocity[i] = Vec3(1e-300, -2.5, 3.0/7.0);
    }
    s.referencePosition = {Vec3(0, 0, 0), Vec3(1, 1, 1), Vec3(2, 2, 2)};
    PairHistory h;
    h.idA = 10;
    h.idB = 11;
    h.tangential = Vec3(1e-7, 2e-7, -3e-7);
    h.normal = Vec3(0.6, -0.8, 1e-17);
    s.pairs.push_back(h);
    return s;
}

std::vector<StateTypeRecord> twoTypes()
{
    return {{"beads", 0x0123456789abcdefull}, {"rocks_0", 42}};
}

std::string slurp(const std::string& f)
{
    std::ifstream is(f, std::ios::binary);
    std::ostringstream os;
    os << is.rdbuf();
    return os.str();
}

void spit(const std::string& f, const std::string& text)
{
    std::ofstream os(f, std::ios::binary | std::ios::trunc);
    os << text;
}

//- An ASCII state of smallState() as versions 1-2 wrote it: the pair record
//  without its last three numbers (the normal 0.6 -0.8 1e-17)
void dropPairNormal(std::string& text)
{
    const std::string normal = " 0.59999999999999998 -0.80000000000000004 1.0000000000000001e-17";
    const std::size_t at = text.find(normal);
    ASSERT_NE(at, std::string::npos) << "no pair normal in\n" << text;
    text.erase(at, normal.size());
}

//- readSnapshot throws a polydem::Error naming file whose message has what
void expectRefused(const std::string& file, const std::string& what)
{
    try
    {
        readSnapshot(file);
        FAIL() << "a damaged state was read: " << file;
    }
    catch (const Error& e)
    {
        EXPECT_EQ(e.file(), file);
        EXPECT_NE(e.message().find(what), std::string::npos) << e.message();
    }
}

} // namespace


TEST(StateIO, typesRoundTrip)
{
    const std::string file = ::testing::TempDir() + "polydem_stateio_types";
    for (StateFormat fmt : {StateFormat::ascii, StateFormat::binary})
    {
        writeSnapshot(file, smallState(), fmt, twoTypes());
        StateFileInfo info;
        const Snapshot s = readSnapshot(file, &info);
        EXPECT_EQ(info.version, 3);
        EXPECT_TRUE(info.checksummed);
        ASSERT_EQ(info.types.size(), 2u);
        EXPECT_EQ(info.types[0].name, "beads");
        EXPECT_EQ(info.types[0].shapeChecksum, 0x0123456789abcdefull);
        EXPECT_EQ(info.types[1].name, "rocks_0");
        EXPECT_EQ(info.types[1].shapeChecksum, 42u);
        ASSERT_EQ(s.particles.size(), 3u);
        EXPECT_EQ(s.particles.position[2].z, 0.3 + 1e-17);
        EXPECT_EQ(s.particles.mass[0], 1.0/3.0);
        ASSERT_EQ(s.pairs.size(), 1u);
        EXPECT_EQ(s.pairs[0].tangential.z, -3e-7);
        EXPECT_EQ(s.pairs[0].normal.x, 0.6);
        EXPECT_EQ(s.pairs[0].normal.z, 1e-17);
        EXPECT_FALSE(std::ifstream(file + ".tmp").good()) << "temporary file left behind";
    }
    std::remove(file.c_str());
}


TEST(StateIO, oneChangedDigitIsRefused)
{
    const std::string file = ::testing::TempDir() + "polydem_stateio_digit";
    writeSnapshot(file, smallState(), StateFormat::ascii, twoTypes());
    std::string text = slurp(file);
    // A digit of the data section: the first particle's mass 0.33333333333333331
    const std::size_t at = text.find("0.33333333333333331");
    ASSERT_NE(at, std::string::npos);
    text[at + 5] = '4';
    spit(file, text);
    expectRefused(file, "checksum mismatch");
    std::remove(file.c_str());
}


TEST(StateIO, oneFlippedBitIsRefused)
{
    const std::string file = ::testing::TempDir() + "polydem_stateio_bit";
    writeSnapshot(file, smallState(), StateFormat::binary, twoTypes());
    std::string text = slurp(file);
    const std::size_t data = text.find("data\n");
    ASSERT_NE(data, std::string::npos);
    // The lowest mantissa bit of a double of the first record
    text[data + 5 + 16 + 8] ^= 0x01;
    spit(file, text);
    expectRefused(file, "checksum mismatch");
    std::remove(file.c_str());
}


TEST(StateIO, damagedChecksumLineIsRefused)
{
    const std::string file = ::testing::TempDir() + "polydem_stateio_line";
    writeSnapshot(file, smallState(), StateFormat::ascii, twoTypes());
    std::string text = slurp(file);
    const std::size_t at = text.rfind("checksum ");
    ASSERT_NE(at, std::string::npos);
    text[at + 1] = 'x';   // "cxecksum": no longer a checksum line
    spit(file, text);
    expectRefused(file, "unexpected content");
    std::remove(file.c_str());
}


TEST(StateIO, versionOneIsReadUnchecked)
{
    const std::string file = ::testing::TempDir() + "polydem_stateio_v1";
    writeSnapshot(file, smallState(), StateFormat::ascii, twoTypes());
    std::string text = slurp(file);
    // What version 1 wrote: no type table, no checksum line, no pair normal
    text.replace(text.find("polyDEMState 3"), 14, "polyDEMState 1");
    dropPairNormal(text);
    const std::size_t t0 = text.find("types ");
    const std::size_t t1 = text.find("data\n");
    text.erase(t0, t1 - t0);
    text.erase(text.rfind("checksum "));
    spit(file, text);
    StateFileInfo info;
    const Snapshot s = readSnapshot(file, &info);
    EXPECT_EQ(info.version, 1);
    EXPECT_FALSE(info.checksummed);
    EXPECT_TRUE(info.types.empty());
    EXPECT_EQ(s.particles.size(), 3u);
    ASSERT_EQ(s.pairs.size(), 1u);
    EXPECT_EQ(s.pairs[0].tangential.y, 2e-7);
    EXPECT_EQ(normSqr(s.pairs[0].normal), 0.0);
    std::remove(file.c_str());
}


// Version 2 (types and checksum, no pair normal) is read, checksum included;
// the pairs come without their normal (a restart from it continues at
// round-off, not bit for bit, for polyhedra)
TEST(StateIO, versionTwoIsRead)
{
    const std::string file = ::testing::TempDir() + "polydem_stateio_v2";
    writeSnapshot(file, smallState(), StateFormat::ascii, twoTypes());
    std::string text = slurp(file);
    text.replace(text.find("polyDEMState 3"), 14, "polyDEMState 2");
    dropPairNormal(text);
    // the checksum of what version 2 would have written
    text.erase(text.rfind("checksum "));
    char line[64];
    std::snprintf(line, sizeof line, "checksum %016llx\n",
                  static_cast<unsigned long long>(fnv1a(text.data(), text.size())));
    spit(file, text + line);
    StateFileInfo info;
    const Snapshot s = readSnapshot(file, &info);
    EXPECT_EQ(info.version, 2);
    EXPECT_TRUE(info.checksummed);
    EXPECT_EQ(info.types.size(), 2u);
    ASSERT_EQ(s.pairs.size(), 1u);
    EXPECT_EQ(s.pairs[0].idB, 11);
    EXPECT_EQ(s.pairs[0].tangential.x, 1e-7);
    EXPECT_EQ(normSqr(s.pairs[0].normal), 0.0);
    std::remove(file.c_str());
}


TEST(StateIO, typeIndexBeyondTheTableIsRefused)
{
    const std::string file = ::testing::TempDir() + "polydem_stateio_index";
    Snapshot s = smallState();
    s.particles.type[2] = 2;
    writeSnapshot(file, s, StateFormat::ascii, twoTypes());
    expectRefused(file, "type index 2");
    std::remove(file.c_str());
}

// polyDEM: reading and writing a Snapshot (particles + contact springs) so that
// a run restarts from any written time and continues bit for bit.
// ASCII writes every double with 17 significant digits (round-trips exactly);
// binary writes the raw little-endian values (large systems).
//
// Version 2 of the file also carries, in its text header, the
// particle types the indices refer to (name and a checksum of the shape) and
// ends with a checksum of every byte before it, so that a restart can refuse
// a state whose types no longer match the input, and a damaged file is found
// before it is run. Version 3 adds each pair's contact normal after its
// springs (PairHistory::normal). Version 1 files (no types, no checksum) and
// version 2 files (no normal) are still read; StateFileInfo says what could be
// checked.
#pragma once

#include "polyDEM/Config.hpp"
#include "polyDEM/Snapshot.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace polydem
{

enum class StateFormat
{
    ascii,
    binary
};

//- A particle type as the state file records it
struct StateTypeRecord
{
    std::string name;
    //- shapeChecksum() of the type
    std::uint64_t shapeChecksum = 0;
};

//- What readSnapshot found besides the snapshot
struct StateFileInfo
{
    int version = 0;
    //- The file ends with a checksum line, and it matched
    bool checksummed = false;
    //- The types the particle type indices refer to (empty: not recorded)
    std::vector<StateTypeRecord> types;
};

//- 64-bit FNV-1a hash of bytes (the state file's checksum)
std::uint64_t fnv1a(const char* data, std::size_t n, std::uint64_t h = 14695981039346656037ull);

//- Checksum of the shape of type t: its kind and, for a polyhedron, the
//  body-frame vertices and face lists (coordinates to 12 significant digits,
//  so that an equal shape rebuilt by another compiler still matches)
std::uint64_t shapeChecksum(const SimulationConfig& config, int t);

//- The records of every type of config, by type index
std::vector<StateTypeRecord> stateTypeRecords(const SimulationConfig& config);

//- Writes path.tmp and renames it to path, so that a run killed while
//  writing leaves the previous file or none, never a part of one
void writeSnapshot
(
    const std::string& path,
    const Snapshot& s,
    StateFormat format = StateFormat::ascii,
    const std::vector<StateTypeRecord>& types = {}
);

//- Throws polydem::Error naming the file when malformed, truncated, or when
//  the checksum does not match its contents
Snapshot readSnapshot(const std::string& path, StateFileInfo* info = nullptr);

} // namespace polydem

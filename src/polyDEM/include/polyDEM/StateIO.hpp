// polyDEM: reading and writing a Snapshot (particles + contact springs) so that
// a run restarts from any written time and continues bit for bit.
// ASCII writes every double with 17 significant digits (round-trips exactly);
// binary writes the raw little-endian values (large systems).
#pragma once

#include "polyDEM/Snapshot.hpp"

#include <string>

namespace polydem
{

enum class StateFormat
{
    ascii,
    binary
};

void writeSnapshot(const std::string& path, const Snapshot& s, StateFormat format = StateFormat::ascii);

//- Throws polydem::Error naming the file (and the line, for ASCII) when malformed
Snapshot readSnapshot(const std::string& path);

} // namespace polydem

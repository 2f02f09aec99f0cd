// Checkpoints of a dynamic run: a binary file of named arrays (step, time, u, v, bond
// factors alpha, energy accumulators, solver state), one text block (the time series
// so far) and the identity of the run that wrote it, written atomically so a stopped
// run loses at most one interval.
//
// Format "PDCKPT02": the magic, a uint32 0x01020304 in the writer's byte order (a
// reader on a machine of the other order refuses the file instead of reading garbage),
// the identity block [int64 bytes]["key=value\n" lines], int64 step, then records
// [int32 name length][name][int64 count][count doubles] until a record named "end"
// (the text block is the record "text" holding bytes), and last a uint64 FNV-1a hash
// of every byte before it. Doubles are stored bit for bit, so a restart continues
// exactly where the uninterrupted run was.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "input/yaml_keys.hpp"

namespace pd {

// A checkpoint that cannot be used: foreign, damaged, of another machine, or of
// another run. Bad input like a bad scene (a SceneError: `pd run` exits 2).
class CheckpointError : public SceneError {
 public:
  using SceneError::SceneError;
};

struct Checkpoint {
  std::int64_t step = 0;
  std::map<std::string, std::string> identity;        // what determines the state (checkpoint_identity.hpp)
  std::map<std::string, std::vector<double>> arrays;  // "u", "v", "alpha", "scalars", ...
  std::string text;                                   // the time-series CSV rows so far
};

void write_checkpoint(const std::string& path, const Checkpoint& c);
// Throws CheckpointError naming the file on a missing, truncated, foreign, corrupted
// (checksum) or other-endian file.
Checkpoint read_checkpoint(const std::string& path);
// The same from the file's bytes; `path` names it in messages.
Checkpoint parse_checkpoint(const std::string& bytes, const std::string& path);

// FNV-1a, 64 bits: every single-byte change changes the hash (each step is a bijection
// of the state), which is what a checksum against bit flips needs.
std::uint64_t fnv1a(const void* data, std::size_t bytes, std::uint64_t hash = 0xcbf29ce484222325ull);

}  // namespace pd

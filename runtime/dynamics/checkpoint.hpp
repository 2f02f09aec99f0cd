// Checkpoints of a dynamic run: a binary file of named arrays (step, time, u, v, bond
// factors alpha, energy accumulators, solver state) and one text block (the time
// series so far), written atomically so a stopped run loses at most one interval.
//
// Format (little-endian, as the machine writes it): "PDCKPT01", int64 step, then
// records [int32 name length][name][int64 count][count doubles] until a record named
// "end"; the text block is the record "series" holding bytes in a string record
// [int32 4]["text"][int64 bytes][bytes]. Doubles are stored bit for bit, so a restart
// continues exactly where the uninterrupted run was.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace pd {

struct Checkpoint {
  std::int64_t step = 0;
  std::map<std::string, std::vector<double>> arrays;  // "u", "v", "alpha", "scalars", ...
  std::string text;                                   // the time-series CSV rows so far
};

void write_checkpoint(const std::string& path, const Checkpoint& c);
// Throws std::runtime_error naming the file on a missing, truncated or foreign file.
Checkpoint read_checkpoint(const std::string& path);

}  // namespace pd

// A ParaView collection (.pvd) of .vtu snapshots with their times: opening it in
// ParaView plays the animation. Written atomically; rewritten as snapshots are added.
// The root carries the run_id that its snapshots and summary.json carry too.
#pragma once

#include <string>
#include <vector>

namespace pd {

struct PvdEntry {
  double time = 0;
  std::string file;  // relative to the .pvd file
};

std::string pvd_document(const std::vector<PvdEntry>& entries);
void write_pvd_file(const std::string& path, const std::vector<PvdEntry>& entries);

}  // namespace pd

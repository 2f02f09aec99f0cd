// Before discretising: a lower bound on the memory a scene needs (its particles and
// bonds alone), refused with the estimate and the machine's memory when it cannot fit,
// instead of allocating until bad_alloc (count: 99999 in 2D is 1e10 particles).
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "input/scene.hpp"

namespace pd::cli {

struct MemoryEstimate {
  double particles = 0;         // the domain box's cells (holes not subtracted)
  double bonds = 0;             // directed bonds: particles x the lattice sites within delta
  double bytes = 0;             // particles' and bonds' arrays: a lower bound on the run's peak
  double tangent_nonzeros = 0;  // of the assembled tangent, if a static solve assembles one
};

MemoryEstimate estimate_memory(const Scene& scene);

// MemAvailable of /proc/meminfo in bytes; nothing when it cannot be read.
std::optional<double> available_memory();

// The message refusing the scene, or nothing when it fits (or the memory is unknown).
std::optional<std::string> memory_refusal(const Scene& scene, std::optional<double> available);

}  // namespace pd::cli

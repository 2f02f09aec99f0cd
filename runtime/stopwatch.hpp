// Wall-clock seconds for the timings the logs and summaries report.
#pragma once

#include <chrono>

namespace pd {

inline double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace pd

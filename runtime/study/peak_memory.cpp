// VmHWM from /proc/self/status, reset by writing 5 to /proc/self/clear_refs (Linux >= 4.0),
// so each study point reports its own peak rather than the largest so far.
#include "study/peak_memory.hpp"

#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>

namespace pd {

bool reset_peak_memory() {
  std::ofstream out("/proc/self/clear_refs");
  out << "5";
  out.flush();
  return static_cast<bool>(out);
}

double peak_memory_mb() {
  std::ifstream in("/proc/self/status");
  std::string line;
  while (std::getline(in, line))
    if (line.compare(0, 6, "VmHWM:") == 0) return std::atof(line.c_str() + 6) / 1024.0;  // kB
  return -1;
}

}  // namespace pd

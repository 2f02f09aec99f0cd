// The .pvd XML.
#include "dynamics/pvd_writer.hpp"

#include <fmt/format.h>

#include "output/atomic_file.hpp"
#include "output/run_id.hpp"

namespace pd {

std::string pvd_document(const std::vector<PvdEntry>& entries) {
  std::string s = fmt::format(
      "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\" "
      "run_id=\"{}\">\n"
      "  <Collection>\n",
      run_id());
  for (const PvdEntry& e : entries)
    s += fmt::format("    <DataSet timestep=\"{:.17g}\" group=\"\" part=\"0\" file=\"{}\"/>\n", e.time,
                     e.file);
  s += "  </Collection>\n</VTKFile>\n";
  return s;
}

void write_pvd_file(const std::string& path, const std::vector<PvdEntry>& entries) {
  write_file_atomically(path, pvd_document(entries));
}

}  // namespace pd

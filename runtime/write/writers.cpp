// VTU and CSV writers with atomic replacement.
#include "write/writers.hpp"

#include <cstdio>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <stdexcept>

namespace pd {

void write_text_atomically(const std::string& path, const std::string& content) {
  const std::filesystem::path target(path);
  if (target.has_parent_path()) std::filesystem::create_directories(target.parent_path());
  const std::string tmp = path + ".partial";
  {
    std::ofstream out(tmp, std::ios::binary);
    out << content;
    out.flush();
    if (!out) {
      std::remove(tmp.c_str());
      throw std::runtime_error("cannot write " + path);
    }
  }
  std::filesystem::rename(tmp, target);
}

void write_vtu(const std::string& path, const Particles& p, const std::vector<PointField>& fields) {
  const int n = p.size(), d = p.dim;
  fmt::memory_buffer b;
  auto out = std::back_inserter(b);
  fmt::format_to(out, "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
                      "<UnstructuredGrid>\n<Piece NumberOfPoints=\"{}\" NumberOfCells=\"{}\">\n<Points>\n"
                      "<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n", n, n);
  for (int i = 0; i < n; ++i)
    fmt::format_to(out, "{:.17g} {:.17g} {:.17g}\n", p.x[i * d], p.x[i * d + 1], d == 3 ? p.x[i * d + 2] : 0.0);
  fmt::format_to(out, "</DataArray>\n</Points>\n<Cells>\n<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n");
  for (int i = 0; i < n; ++i) fmt::format_to(out, "{}\n", i);
  fmt::format_to(out, "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n");
  for (int i = 0; i < n; ++i) fmt::format_to(out, "{}\n", i + 1);
  fmt::format_to(out, "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n");
  for (int i = 0; i < n; ++i) fmt::format_to(out, "1\n");
  fmt::format_to(out, "</DataArray>\n</Cells>\n<PointData>\n");
  for (const PointField& f : fields) {
    const int nc = f.components == 1 ? 1 : 3;
    fmt::format_to(out, "<DataArray type=\"Float64\" Name=\"{}\" NumberOfComponents=\"{}\" format=\"ascii\">\n", f.name, nc);
    for (int i = 0; i < n; ++i) {
      for (int c = 0; c < nc; ++c) {
        const double v = c < f.components ? f.values[static_cast<std::size_t>(i) * f.components + c] : 0.0;
        if (c) fmt::format_to(out, " ");
        fmt::format_to(out, "{:.17g}", v);
      }
      fmt::format_to(out, "\n");
    }
    fmt::format_to(out, "</DataArray>\n");
  }
  fmt::format_to(out, "</PointData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n");
  write_text_atomically(path, fmt::to_string(b));
}

void write_csv(const std::string& path, const Particles& p, const std::vector<PointField>& fields) {
  const int n = p.size(), d = p.dim;
  const char* axes = "xyz";
  fmt::memory_buffer b;
  auto out = std::back_inserter(b);
  fmt::format_to(out, "id");
  for (int c = 0; c < d; ++c) fmt::format_to(out, ",{}", axes[c]);
  for (const PointField& f : fields)
    for (int c = 0; c < f.components; ++c)
      if (f.components == 1)
        fmt::format_to(out, ",{}", f.name);
      else
        fmt::format_to(out, ",{}_{}", f.name, axes[c]);
  fmt::format_to(out, "\n");
  for (int i = 0; i < n; ++i) {
    fmt::format_to(out, "{}", i);
    for (int c = 0; c < d; ++c) fmt::format_to(out, ",{:.17g}", p.x[i * d + c]);
    for (const PointField& f : fields)
      for (int c = 0; c < f.components; ++c) fmt::format_to(out, ",{:.17g}", f.values[static_cast<std::size_t>(i) * f.components + c]);
    fmt::format_to(out, "\n");
  }
  write_text_atomically(path, fmt::to_string(b));
}

}  // namespace pd

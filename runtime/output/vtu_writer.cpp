// VTU XML, ASCII data arrays.
#include "output/vtu_writer.hpp"

#include <fmt/format.h>

#include <stdexcept>

#include "output/atomic_file.hpp"

namespace pd {

namespace {
std::string xml_escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '&': out += "&amp;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

// Components written: scalars stay scalars; vectors of 2 or 3 become 3 (VTK vectors);
// anything else (a 2x2 tensor, say) is written as it is.
int vtk_components(int c) { return c == 2 ? 3 : c; }

void data_array(fmt::memory_buffer& b, const std::string& name, int components, int n, const double* v, int stride) {
  const int nc = vtk_components(components);
  fmt::format_to(std::back_inserter(b), "        <DataArray type=\"Float64\" Name=\"{}\" NumberOfComponents=\"{}\" format=\"ascii\">\n",
                 xml_escape(name), nc);
  for (int i = 0; i < n; ++i) {
    b.append(std::string_view("         "));
    for (int c = 0; c < nc; ++c)
      fmt::format_to(std::back_inserter(b), " {:.17g}", c < components ? v[static_cast<std::size_t>(i) * stride + c] : 0.0);
    b.push_back('\n');
  }
  b.append(std::string_view("        </DataArray>\n"));
}
}  // namespace

std::string vtu_document(const Particles& P, std::span<const double> u, std::span<const OutputField> fields) {
  const int n = P.size(), d = P.dim;
  check_output_fields(fields, n);
  if (!u.empty() && u.size() != static_cast<std::size_t>(n) * d)
    throw std::invalid_argument("vtu: displacement has " + std::to_string(u.size()) + " values for " + std::to_string(n) +
                                " particles in " + std::to_string(d) + "D");
  fmt::memory_buffer b;
  auto out = std::back_inserter(b);
  fmt::format_to(out,
                 "<?xml version=\"1.0\"?>\n"
                 "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
                 "  <UnstructuredGrid>\n"
                 "    <Piece NumberOfPoints=\"{}\" NumberOfCells=\"{}\">\n"
                 "      <Points>\n",
                 n, n);
  data_array(b, "position", d, n, P.x.data(), d);
  fmt::format_to(out, "      </Points>\n      <Cells>\n");
  fmt::format_to(out, "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n");
  for (int i = 0; i < n; ++i) fmt::format_to(out, "{}{}", i, (i % 20 == 19 || i == n - 1) ? "\n" : " ");
  fmt::format_to(out, "        </DataArray>\n        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n");
  for (int i = 0; i < n; ++i) fmt::format_to(out, "{}{}", i + 1, (i % 20 == 19 || i == n - 1) ? "\n" : " ");
  // Cell type 1 = VTK_VERTEX.
  fmt::format_to(out, "        </DataArray>\n        <DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n");
  for (int i = 0; i < n; ++i) fmt::format_to(out, "1{}", (i % 40 == 39 || i == n - 1) ? "\n" : " ");
  fmt::format_to(out, "        </DataArray>\n      </Cells>\n      <PointData{}>\n",
                 u.empty() ? std::string() : std::string(" Vectors=\"displacement\""));
  if (!u.empty()) data_array(b, "displacement", d, n, u.data(), d);
  for (const OutputField& f : fields) data_array(b, f.name, f.components, n, f.values.data(), f.components);
  fmt::format_to(out, "      </PointData>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n");
  return fmt::to_string(b);
}

void write_vtu_file(const std::string& path, const Particles& particles, std::span<const double> u,
                    std::span<const OutputField> fields) {
  write_file_atomically(path, vtu_document(particles, u, fields));
}

}  // namespace pd

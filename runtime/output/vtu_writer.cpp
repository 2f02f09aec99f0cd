// VTU XML with the data arrays appended as raw binary (VTK's "appended" format).
#include "output/vtu_writer.hpp"

#include <fmt/format.h>

#include <bit>
#include <cstdint>
#include <cstring>
#include <stdexcept>

#include "output/atomic_file.hpp"
#include "output/run_id.hpp"

namespace pd {

namespace {
std::string xml_escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '&':
        out += "&amp;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

// Components written: scalars stay scalars; vectors of 2 or 3 become 3 (VTK vectors);
// anything else (a 2x2 tensor, say) is written as it is.
int vtk_components(int c) { return c == 2 ? 3 : c; }

// The XML head (one DataArray per array, each naming its offset into the appended
// section) and the appended bytes, built side by side. Each block is a UInt64 byte
// count followed by the values in the machine's byte order (the head says which).
class AppendedArrays {
 public:
  explicit AppendedArrays(fmt::memory_buffer& xml) : xml_(xml) {}

  template <class T>
  void add(const char* type, const std::string& name, int components, const std::vector<T>& values) {
    fmt::format_to(std::back_inserter(xml_),
                   "        <DataArray type=\"{}\" Name=\"{}\" NumberOfComponents=\"{}\" format=\"appended\" "
                   "offset=\"{}\"/>\n",
                   type, xml_escape(name), components, data_.size());
    const std::uint64_t bytes = values.size() * sizeof(T);
    append(&bytes, sizeof bytes);
    append(values.data(), bytes);
  }
  // Point values [n * stride], the first `components` of each written, padded to VTK's count.
  void add_points(const std::string& name, int components, int n, const double* v, int stride) {
    const int nc = vtk_components(components);
    std::vector<double> out(static_cast<std::size_t>(n) * nc, 0.0);
    for (int i = 0; i < n; ++i)
      for (int c = 0; c < components; ++c)
        out[static_cast<std::size_t>(i) * nc + c] = v[static_cast<std::size_t>(i) * stride + c];
    add("Float64", name, nc, out);
  }
  const std::string& data() const { return data_; }

 private:
  void append(const void* p, std::size_t n) {
    if (n > 0) data_.append(static_cast<const char*>(p), n);
  }
  fmt::memory_buffer& xml_;
  std::string data_;
};
}  // namespace

std::string vtu_document(const Particles& P, std::span<const double> u, std::span<const OutputField> fields) {
  const int n = P.size(), d = P.dim;
  check_output_fields(fields, n);
  if (!u.empty() && u.size() != static_cast<std::size_t>(n) * d)
    throw std::invalid_argument("vtu: displacement has " + std::to_string(u.size()) + " values for " +
                                std::to_string(n) + " particles in " + std::to_string(d) + "D");
  static_assert(std::endian::native == std::endian::little || std::endian::native == std::endian::big);
  const char* byte_order = std::endian::native == std::endian::little ? "LittleEndian" : "BigEndian";
  fmt::memory_buffer b;
  auto out = std::back_inserter(b);
  fmt::format_to(out,
                 "<?xml version=\"1.0\"?>\n"
                 "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"{}\" "
                 "header_type=\"UInt64\" run_id=\"{}\">\n"
                 "  <UnstructuredGrid>\n"
                 "    <Piece NumberOfPoints=\"{}\" NumberOfCells=\"{}\">\n"
                 "      <Points>\n",
                 byte_order, run_id(), n, n);
  AppendedArrays arrays(b);
  arrays.add_points("position", d, n, P.x.data(), d);
  fmt::format_to(out, "      </Points>\n      <Cells>\n");
  std::vector<std::int64_t> connectivity(static_cast<std::size_t>(n)), offsets(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) connectivity[i] = i, offsets[i] = i + 1;
  arrays.add("Int64", "connectivity", 1, connectivity);
  arrays.add("Int64", "offsets", 1, offsets);
  arrays.add("UInt8", "types", 1,
             std::vector<std::uint8_t>(static_cast<std::size_t>(n), 1));  // 1 = VTK_VERTEX
  fmt::format_to(out, "      </Cells>\n      <PointData{}>\n",
                 u.empty() ? std::string() : std::string(" Vectors=\"displacement\""));
  if (!u.empty()) arrays.add_points("displacement", d, n, u.data(), d);
  for (const OutputField& f : fields)
    arrays.add_points(f.name, f.components, n, f.values.data(), f.components);
  fmt::format_to(
      out,
      "      </PointData>\n    </Piece>\n  </UnstructuredGrid>\n  <AppendedData encoding=\"raw\">\n   _");
  b.append(arrays.data());
  fmt::format_to(out, "\n  </AppendedData>\n</VTKFile>\n");
  return fmt::to_string(b);
}

void write_vtu_file(const std::string& path, const Particles& particles, std::span<const double> u,
                    std::span<const OutputField> fields) {
  write_file_atomically(path, vtu_document(particles, u, fields));
}

}  // namespace pd

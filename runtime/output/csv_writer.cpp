// CSV rows, one per particle.
#include "output/csv_writer.hpp"

#include <fmt/format.h>

#include <stdexcept>

#include "output/atomic_file.hpp"

namespace pd {

std::string csv_document(const Particles& P, std::span<const double> u, std::span<const OutputField> fields) {
  const int n = P.size(), d = P.dim;
  check_output_fields(fields, n);
  if (!u.empty() && u.size() != static_cast<std::size_t>(n) * d)
    throw std::invalid_argument("csv: displacement size does not match the particles");
  static const char* axis[] = {"x", "y", "z"};
  fmt::memory_buffer b;
  auto out = std::back_inserter(b);
  fmt::format_to(out, "id");
  for (int c = 0; c < d; ++c) fmt::format_to(out, ",{}", axis[c]);
  if (!u.empty())
    for (int c = 0; c < d; ++c) fmt::format_to(out, ",u_{}", axis[c]);
  for (const OutputField& f : fields)
    for (int c = 0; c < f.components; ++c) {
      if (f.components == 1)
        fmt::format_to(out, ",{}", f.name);
      else if (f.components == d)
        fmt::format_to(out, ",{}_{}", f.name, axis[c]);
      else if (f.components == d * d)
        fmt::format_to(out, ",{}_{}{}", f.name, axis[c / d], axis[c % d]);  // tensor, row-major
      else
        fmt::format_to(out, ",{}_{}", f.name, c);
    }
  b.push_back('\n');
  for (int i = 0; i < n; ++i) {
    fmt::format_to(out, "{}", i);
    for (int c = 0; c < d; ++c) fmt::format_to(out, ",{:.17g}", P.x[static_cast<std::size_t>(i) * d + c]);
    if (!u.empty())
      for (int c = 0; c < d; ++c) fmt::format_to(out, ",{:.17g}", u[static_cast<std::size_t>(i) * d + c]);
    for (const OutputField& f : fields)
      for (int c = 0; c < f.components; ++c)
        fmt::format_to(out, ",{:.17g}", f.values[static_cast<std::size_t>(i) * f.components + c]);
    b.push_back('\n');
  }
  return fmt::to_string(b);
}

void write_csv_file(const std::string& path, const Particles& particles, std::span<const double> u,
                    std::span<const OutputField> fields) {
  write_file_atomically(path, csv_document(particles, u, fields));
}

}  // namespace pd

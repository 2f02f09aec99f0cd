// Result files: VTK unstructured grid (.vtu, ASCII, one vertex cell per particle) for
// ParaView, and CSV. Both are written to a temporary file and renamed, so an
// interrupted run never leaves a half-written result.
#pragma once

#include <string>
#include <vector>

#include "particles.hpp"

namespace pd {

struct PointField {
  std::string name;
  int components = 1;          // 1 (scalar) or dim (vector; padded to 3 in .vtu)
  std::vector<double> values;  // [n * components]
};

void write_vtu(const std::string& path, const Particles& p, const std::vector<PointField>& fields);
void write_csv(const std::string& path, const Particles& p, const std::vector<PointField>& fields);
// Writes `content` to path atomically (temp file + rename).
void write_text_atomically(const std::string& path, const std::string& content);

}  // namespace pd

// Named per-particle fields handed to the writers.
#pragma once

#include <span>
#include <string>
#include <vector>

namespace pd {

// A scalar (components = 1) or vector (components = dim) value per particle,
// particle-major: [n * components].
struct OutputField {
  std::string name;
  int components = 1;
  std::vector<double> values;
};

// Throws std::invalid_argument when a field's size does not match n particles or its
// name is empty or repeated: a writer should fail before it writes anything.
void check_output_fields(std::span<const OutputField> fields, int n);

}  // namespace pd

// |a - b| / |b| in the 2-norm, for comparing two runs' fields; infinite when b is zero
// (nothing to compare against), so a test cannot pass on an empty reference.
#pragma once

#include <cmath>
#include <limits>
#include <vector>

namespace pd::test {

inline double relative_difference(const std::vector<double>& a, const std::vector<double>& b) {
  double diff = 0, norm = 0;
  for (std::size_t i = 0; i < a.size(); ++i) diff += (a[i] - b[i]) * (a[i] - b[i]), norm += b[i] * b[i];
  return norm > 0 ? std::sqrt(diff / norm) : std::numeric_limits<double>::infinity();
}

}  // namespace pd::test

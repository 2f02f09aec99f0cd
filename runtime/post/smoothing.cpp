// Influence-weighted averages over families (paper 000 eq. 49).
#include "post/smoothing.hpp"

#include <cmath>
#include <stdexcept>

namespace pd {

std::vector<double> smooth_field(const Particles& particles, const Bonds& bonds, InfluenceWeight w,
                                 const std::vector<double>& field, int components) {
  const int n = particles.size();
  if (field.size() != static_cast<std::size_t>(n) * components)
    throw std::invalid_argument("smooth_field: the field does not have one value per particle and component");
  if (!can_smooth_with(w))
    throw std::invalid_argument(
        "smooth_field: the influence function is singular at r = 0, and eq. (49) weights the particle itself "
        "by w(0)");
  std::vector<double> out(field.size(), 0.0);
#pragma omp parallel for schedule(static)
  for (int p = 0; p < n; ++p) {
    const double delta = bonds.delta[p];
    const double self = w(0.0, delta) * particles.volume[p];
    double total = self;
    double* o = out.data() + static_cast<std::ptrdiff_t>(p) * components;
    for (int c = 0; c < components; ++c) o[c] = self * field[static_cast<std::size_t>(p) * components + c];
    for (int b = bonds.offsets[p]; b < bonds.offsets[p + 1]; ++b) {
      if (bonds.alpha[b] == 0.0) continue;
      const int q = bonds.neighbor[b];
      const double weight = w(bonds.length[b], delta) * particles.volume[q];
      total += weight;
      for (int c = 0; c < components; ++c)
        o[c] += weight * field[static_cast<std::size_t>(q) * components + c];
    }
    for (int c = 0; c < components; ++c) o[c] /= total;
  }
  return out;
}

}  // namespace pd

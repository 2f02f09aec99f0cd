// Gershgorin row sums and the stable step they bound.
#include "effects/time_step.hpp"

#include <cmath>
#include <stdexcept>

namespace pd {

StableStep stable_time_step(const std::vector<double>& row_sums, const std::vector<double>& mass) {
  StableStep out;
  double worst = 0;
  for (std::size_t r = 0; r < row_sums.size(); ++r) {
    const double w = row_sums[r] / mass[r];
    if (w > worst) worst = w, out.dof = static_cast<int>(r);
  }
  if (!(worst > 0) || !std::isfinite(worst))
    throw std::runtime_error("stable time step: the stiffness has no nonzero row");
  out.dt = 2.0 / std::sqrt(worst);
  return out;
}

}  // namespace pd

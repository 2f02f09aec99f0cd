// Gershgorin row sums and the stable step they bound.
#include "effects/time_step.hpp"

#include <cmath>
#include <stdexcept>

namespace pd {

std::vector<double> stiffness_row_sums(const FamilyAssembler& assembler, const double* u) {
  SparseMatrix K = assembler.make_matrix();
  assembler.stiffness(u, K);
  std::vector<double> s(static_cast<std::size_t>(K.rows()), 0.0);
  // Column-major storage: add |K_rc| of each column to its rows.
  for (Eigen::Index c = 0; c < K.outerSize(); ++c)
    for (SparseMatrix::InnerIterator it(K, c); it; ++it)
      s[static_cast<std::size_t>(it.row())] += std::fabs(it.value());
  return s;
}

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

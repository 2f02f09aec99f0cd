// ADR iteration with the adaptive damping coefficient.
#include "dynamics/dynamic_relaxation.hpp"

#include <cmath>

namespace pd {

AdaptiveDynamicRelaxation::AdaptiveDynamicRelaxation(const std::vector<double>& density,
                                                     std::vector<int> free, Sum sum)
    : D_(density),
      free_(std::move(free)),
      sum_(std::move(sum)),
      v_(D_.size(), 0.0),
      f_prev_(D_.size(), 0.0) {}

void AdaptiveDynamicRelaxation::restore(int iterations, std::vector<double> v, std::vector<double> f_prev) {
  n_ = iterations, v_ = std::move(v), f_prev_ = std::move(f_prev);
}

void AdaptiveDynamicRelaxation::step(const std::vector<double>& F, std::vector<double>& u) {
  const double dt = 1.0;
  if (n_ == 0) {
    c_ = 0;
    for (int i : free_) v_[i] = 0.5 * dt * F[i] / D_[i];
  } else {
    double num = 0, den = 0;
    for (int i : free_) {
      den += u[i] * u[i];
      if (v_[i] != 0.0) num += u[i] * u[i] * (-(F[i] - f_prev_[i]) / (D_[i] * dt * v_[i]));
    }
    if (sum_) {
      double sums[2] = {num, den};
      sum_(sums, 2);
      num = sums[0], den = sums[1];
    }
    c_ = num > 0 && den > 0 ? std::min(2.0 * std::sqrt(num / den), 2.0 / dt) : 0.0;
    for (int i : free_) v_[i] = ((2 - c_ * dt) * v_[i] + 2 * dt * F[i] / D_[i]) / (2 + c_ * dt);
  }
  for (int i : free_) u[i] += dt * v_[i], f_prev_[i] = F[i];
  ++n_;
}

}  // namespace pd

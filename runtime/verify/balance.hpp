// Balance checks of one family's nodal forces f_0..f_L (kernel_abi.hpp): linear
// momentum, sum_a f_a = 0, and angular momentum, sum_a y_a x f_a = 0. With linear
// momentum balanced the torque is the same about every point; about the center it is
// sum_k Y_k x f_{k+1}.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "verify/random_family.hpp"

namespace pd::verify {

// max over components |sum_a f_a| / sum_a |f_a|.
inline double momentum_error(const TestFamily& f, const std::vector<double>& forces) {
  double worst = 0, total = 0;
  for (int comp = 0; comp < f.dim; ++comp) {
    double s = 0;
    for (int a = 0; a <= f.bonds(); ++a)
      s += forces[a * f.dim + comp], total += std::fabs(forces[a * f.dim + comp]);
    worst = std::max(worst, std::fabs(s));
  }
  return total > 0 ? worst / total : worst;
}

// |sum_k Y_k x f_{k+1}| (largest component) / sum_k |Y_k| |f_{k+1}|.
inline double angular_momentum_error(const TestFamily& f, const std::vector<double>& forces) {
  const int d = f.dim;
  double torque[3] = {0, 0, 0}, scale = 0;
  for (int k = 0; k < f.bonds(); ++k) {
    const double* Y = &f.Y[static_cast<std::size_t>(k * d)];
    const double* F = &forces[static_cast<std::size_t>((k + 1) * d)];
    double y2 = 0, f2 = 0;
    for (int c = 0; c < d; ++c) y2 += Y[c] * Y[c], f2 += F[c] * F[c];
    scale += std::sqrt(y2 * f2);
    if (d == 2) {
      torque[2] += Y[0] * F[1] - Y[1] * F[0];
    } else {
      torque[0] += Y[1] * F[2] - Y[2] * F[1];
      torque[1] += Y[2] * F[0] - Y[0] * F[2];
      torque[2] += Y[0] * F[1] - Y[1] * F[0];
    }
  }
  const double worst = std::max({std::fabs(torque[0]), std::fabs(torque[1]), std::fabs(torque[2])});
  return scale > 0 ? worst / scale : worst;
}

}  // namespace pd::verify

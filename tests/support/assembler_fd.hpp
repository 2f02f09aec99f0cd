// The assembled stiffness against central differences of the assembled forces, and the
// matrix-free product against the matrix: the check every bond-factor path (quadrature
// factors, surface correction) needs, in one place.
#pragma once

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <vector>

#include "assembly/assembler.hpp"

namespace pd::test {

// Largest |-(f(u + e_j eps) - f(u - e_j eps)) / (2 eps) - K_ij| over every `stride`-th
// column j, and the largest |K|, with K = a.stiffness(u).
struct TangentFdCheck {
  double worst = 0, scale = 0;
};
inline TangentFdCheck tangent_fd_check(const FamilyAssembler& a, const std::vector<double>& u, int stride = 3,
                                       double eps = 1e-6) {
  const int dofs = static_cast<int>(u.size());
  SparseMatrix K;
  a.stiffness(u.data(), K);
  const Eigen::MatrixXd Kd(K);
  TangentFdCheck out;
  out.scale = Kd.cwiseAbs().maxCoeff();
  std::vector<double> fp(dofs), fm(dofs);
  for (int j = 0; j < dofs; j += stride) {
    std::vector<double> up = u, um = u;
    up[j] += eps, um[j] -= eps;
    a.internal_forces(up.data(), fp.data());
    a.internal_forces(um.data(), fm.data());
    for (int i = 0; i < dofs; ++i)
      out.worst = std::max(out.worst, std::abs(-(fp[i] - fm[i]) / (2 * eps) - Kd(i, j)));
  }
  return out;
}

// Expects a.stiffness_product(u, v) == K(u) v to 1e-10 of the product's size.
inline void expect_product_equals_matrix(const FamilyAssembler& a, const std::vector<double>& u,
                                         const std::vector<double>& v) {
  const int dofs = static_cast<int>(u.size());
  SparseMatrix K;
  a.stiffness(u.data(), K);
  const Eigen::MatrixXd Kd(K);
  const double scale = Kd.cwiseAbs().maxCoeff();
  std::vector<double> Kv(dofs);
  a.stiffness_product(u.data(), v.data(), Kv.data());
  const Eigen::VectorXd expected = Kd * Eigen::Map<const Eigen::VectorXd>(v.data(), dofs);
  for (int i = 0; i < dofs; ++i)
    EXPECT_NEAR(Kv[i], expected[i], 1e-10 * expected.cwiseAbs().maxCoeff() + 1e-12 * scale);
}

}  // namespace pd::test

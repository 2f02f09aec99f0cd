// Dirichlet elimination: numbering, K_ff/K_fc extraction, and the reduced solution of
// an SPD system against the dense solution with the constrained values substituted.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <random>

#include "constraints/dof_map.hpp"

namespace {
pd::SparseMatrix random_spd(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> U(-1, 1);
  Eigen::MatrixXd B = Eigen::MatrixXd::Zero(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = std::max(0, i - 3); j <= std::min(n - 1, i + 3); ++j) B(i, j) = U(rng);
  Eigen::MatrixXd A = B * B.transpose() + 0.5 * Eigen::MatrixXd::Identity(n, n);
  pd::SparseMatrix S = A.sparseView();
  S.makeCompressed();
  return S;
}
}  // namespace

TEST(DofMap, NumbersFreeDofsInOrder) {
  const std::vector<int> c{5, 1};
  const std::vector<double> v{2.0, -1.0};
  const pd::DofMap m = pd::DofMap::from_list(7, c, v);
  EXPECT_EQ(m.free_count(), 5);
  EXPECT_EQ(m.constrained_dofs(), (std::vector<int>{1, 5}));
  EXPECT_EQ(m.prescribed(), (std::vector<double>{-1.0, 2.0}));
  EXPECT_EQ(m.free_dofs(), (std::vector<int>{0, 2, 3, 4, 6}));
  EXPECT_EQ(m.free_index(3), 2);
  EXPECT_EQ(m.free_index(5), -1);
  Eigen::VectorXd full = Eigen::VectorXd::Zero(7);
  m.apply_prescribed(full, 0.5);
  EXPECT_DOUBLE_EQ(full[1], -0.5);
  EXPECT_DOUBLE_EQ(full[5], 1.0);
  EXPECT_THROW(pd::DofMap::from_list(7, std::vector<int>{1, 1}, std::vector<double>{0, 0}),
               std::invalid_argument);
  EXPECT_THROW(pd::DofMap::from_list(7, std::vector<int>{7}, std::vector<double>{0}), std::out_of_range);
}

TEST(DofMap, EliminationMatchesDenseSolution) {
  const int n = 30;
  const pd::SparseMatrix K = random_spd(n, 11);
  const Eigen::MatrixXd Kd(K);
  Eigen::VectorXd f(n);
  for (int i = 0; i < n; ++i) f[i] = std::sin(1.0 + i);
  const std::vector<int> c{0, 7, 8, 29, 15};
  const std::vector<double> v{0.1, -0.3, 0.0, 1.2, 0.5};
  const pd::DofMap m = pd::DofMap::from_list(n, c, v);
  pd::ReducedSystem red(m, K);
  red.update(K);
  // Symmetry is kept.
  const Eigen::MatrixXd Kff(red.Kff());
  EXPECT_LT((Kff - Kff.transpose()).cwiseAbs().maxCoeff(), 1e-15);
  const Eigen::VectorXd uc = Eigen::Map<const Eigen::VectorXd>(m.prescribed().data(), m.constrained_count());
  const Eigen::VectorXd rhs = red.rhs(f, uc);
  const Eigen::VectorXd uf = Kff.ldlt().solve(rhs);
  Eigen::VectorXd u(n);
  m.apply_prescribed(u);
  m.expand_free(uf, u);
  // Dense reference: build K_ff and K_fc by index loops, solve.
  const auto& F = m.free_dofs();
  const auto& C = m.constrained_dofs();
  Eigen::MatrixXd A(F.size(), F.size());
  Eigen::VectorXd b(F.size());
  for (std::size_t i = 0; i < F.size(); ++i) {
    b[i] = f[F[i]];
    for (std::size_t j = 0; j < F.size(); ++j) A(i, j) = Kd(F[i], F[j]);
    for (std::size_t j = 0; j < C.size(); ++j) b[i] -= Kd(F[i], C[j]) * m.prescribed()[j];
  }
  const Eigen::VectorXd ref = A.lu().solve(b);
  for (std::size_t i = 0; i < F.size(); ++i) EXPECT_NEAR(u[F[i]], ref[i], 1e-12);
  for (std::size_t j = 0; j < C.size(); ++j) EXPECT_EQ(u[C[j]], m.prescribed()[j]);
  // And the free rows of the full system hold.
  const Eigen::VectorXd res = Kd * u - f;
  for (int i : F) EXPECT_NEAR(res[i], 0.0, 1e-12);
  // update() follows new values in the same pattern.
  pd::SparseMatrix K2 = K;
  for (int k = 0; k < K2.nonZeros(); ++k) K2.valuePtr()[k] *= 2.0;
  red.update(K2);
  EXPECT_NEAR(Eigen::MatrixXd(red.Kff()).norm(), 2.0 * Kff.norm(), 1e-12 * Kff.norm());
}

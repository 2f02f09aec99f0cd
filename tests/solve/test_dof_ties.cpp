// Multipoint constraints in the DofMap (DofMap::tie): the reduced blocks are S K P (free
// rows, columns through the ties), built entry by entry here with dense matrices; the
// tied values follow their masters with the load-scaled offset; bad ties are refused.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <random>

#include "constraints/dof_map.hpp"

namespace {
pd::SparseMatrix random_banded(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> U(-1, 1);
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = std::max(0, i - 4); j <= std::min(n - 1, i + 4); ++j) A(i, j) = U(rng);
  pd::SparseMatrix S = A.sparseView();
  S.makeCompressed();
  return S;
}

// dofs 3 and 10 tied: u3 = -u5 + 0.5 u1 + 2 load, u10 = 2 u0 (0 is constrained) - u7 + u7 (repeated master).
pd::DofMap tied_map(int n) {
  pd::DofMap m = pd::DofMap::from_list(n, std::vector<int>{0, 12}, std::vector<double>{0.25, -1.0});
  m.tie({pd::TiedDof{3, {5, 1}, {-1.0, 0.5}, 2.0}, pd::TiedDof{10, {0, 7, 7}, {2.0, -1.0, 1.5}, 0.0}});
  return m;
}
}  // namespace

TEST(DofTies, ReducedBlocksAreFreeRowsOfKTimesP) {
  const int n = 16;
  const pd::SparseMatrix K = random_banded(n, 5);
  const Eigen::MatrixXd Kd(K);
  const pd::DofMap m = tied_map(n);
  EXPECT_EQ(m.free_count(), n - 4);
  EXPECT_EQ(m.tied_count(), 2);
  EXPECT_EQ(m.free_index(3), -1);
  EXPECT_EQ(m.free_index(10), -1);
  EXPECT_FALSE(m.keeps_symmetry());
  // P (n x nf) and the constrained columns' Pc (n x nc), by hand from the ties above.
  const auto& F = m.free_dofs();
  const auto& C = m.constrained_dofs();
  Eigen::MatrixXd P = Eigen::MatrixXd::Zero(n, F.size()), Pc = Eigen::MatrixXd::Zero(n, C.size());
  for (std::size_t j = 0; j < F.size(); ++j) P(F[j], j) = 1;
  for (std::size_t j = 0; j < C.size(); ++j) Pc(C[j], j) = 1;
  P(3, m.free_index(5)) = -1;
  P(3, m.free_index(1)) = 0.5;
  Pc(10, 0) = 2;                 // constrained dof 0 is the first constrained one
  P(10, m.free_index(7)) = 0.5;  // -1 + 1.5
  Eigen::MatrixXd S = Eigen::MatrixXd::Zero(F.size(), n);
  for (std::size_t i = 0; i < F.size(); ++i) S(i, F[i]) = 1;
  pd::ReducedSystem red(m, K);
  red.update(K);
  const Eigen::MatrixXd Kff(red.Kff()), Kfc(red.Kfc());
  EXPECT_LT((Kff - S * Kd * P).cwiseAbs().maxCoeff(), 1e-14);
  EXPECT_LT((Kfc - S * Kd * Pc).cwiseAbs().maxCoeff(), 1e-14);
  // update() follows new values.
  pd::SparseMatrix K2 = K;
  for (int k = 0; k < K2.nonZeros(); ++k) K2.valuePtr()[k] = std::cos(1.0 + k);
  red.update(K2);
  EXPECT_LT((Eigen::MatrixXd(red.Kff()) - S * Eigen::MatrixXd(K2) * P).cwiseAbs().maxCoeff(), 1e-14);
}

TEST(DofTies, TiedValuesFollowMastersAndLoad) {
  const int n = 16;
  const pd::DofMap m = tied_map(n);
  Eigen::VectorXd u = Eigen::VectorXd::LinSpaced(n, 1.0, 2.5);
  m.apply_prescribed(u, 0.5);
  EXPECT_DOUBLE_EQ(u[0], 0.125);
  EXPECT_DOUBLE_EQ(u[12], -0.5);
  EXPECT_DOUBLE_EQ(u[3], -u[5] + 0.5 * u[1] + 1.0);
  EXPECT_DOUBLE_EQ(u[10], 2 * 0.125 + 0.5 * u[7]);
  // An increment: expand_free gives P dx (no offset, constrained entries untouched at 0).
  Eigen::VectorXd dx = Eigen::VectorXd::LinSpaced(m.free_count(), -1.0, 1.0), du = Eigen::VectorXd::Zero(n);
  m.expand_free(dx, du);
  EXPECT_DOUBLE_EQ(du[3], -du[5] + 0.5 * du[1]);
  EXPECT_DOUBLE_EQ(du[10], 0.5 * du[7]);
  EXPECT_EQ(du[0], 0.0);
}

TEST(DofTies, RefusesBadTies) {
  pd::DofMap m = pd::DofMap::from_list(8, std::vector<int>{0}, std::vector<double>{0.0});
  EXPECT_THROW(m.tie({pd::TiedDof{0, {1}, {1.0}, 0.0}}), std::invalid_argument);           // constrained
  EXPECT_THROW(m.tie({pd::TiedDof{2, {3}, {1.0}, 0.0}, pd::TiedDof{3, {4}, {1.0}, 0.0}}),  // chained
               std::invalid_argument);
  EXPECT_THROW(m.tie({pd::TiedDof{2, {3}, {1.0}, 0.0}, pd::TiedDof{2, {4}, {1.0}, 0.0}}),  // twice
               std::invalid_argument);
  EXPECT_THROW(m.tie({pd::TiedDof{2, {9}, {1.0}, 0.0}}), std::out_of_range);
  EXPECT_THROW(m.tie({pd::TiedDof{2, {3, 4}, {1.0}, 0.0}}), std::invalid_argument);  // sizes
}

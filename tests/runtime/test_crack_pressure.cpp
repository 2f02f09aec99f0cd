// Crack pressure on a perturbed cloud: the total normal load on each crack face is
// p x crack length, whatever the perturbation (on the paper's lattice it is by construction).
#include <gtest/gtest.h>

#include <Eigen/Sparse>
#include <cmath>

#include "assembly/sparsity_pattern.hpp"
#include "discretize/discretization.hpp"
#include "effects/loads.hpp"

namespace {
// A square [-half, half]^2 of spacing h, perturbed, with one pressurised crack a-b.
pd::Scene crack_scene(double half, double h, double perturbation, pd::Point a, pd::Point b, double pressure) {
  pd::Scene s;
  s.dim = 2;
  s.lo = {-half, -half, 0};
  s.hi = {half, half, 0};
  s.h = h;
  s.perturbation = perturbation;
  s.seed = 11;
  s.materials.resize(1);
  pd::Crack c;
  c.points = {a, b};
  c.pressure = pressure;
  s.cracks = {c};
  return s;
}
}  // namespace

TEST(CrackPressure, TotalNormalLoadOnEachFaceIsPressureTimesLength) {
  for (double amplitude : {0.0, 0.2, 0.4}) {
    const pd::Scene s = crack_scene(1, 0.05, amplitude, {-0.4, 0, 0}, {0.4, 0, 0}, 0.1);
    const pd::Particles p = pd::discretize(s);
    pd::Bonds b = pd::find_bonds(p, 3 * s.h, [](double, double) { return 1.0; });
    pd::cut_bonds(s.cracks, p, b);
    const auto effect = pd::make_crack_pressure(s, p, b);
    ASSERT_NE(effect, nullptr);
    std::vector<double> u(p.x.size(), 0.0), r(p.x.size(), 0.0);
    effect->add_forces(u.data(), 1.0, r.data());
    double up = 0, down = 0, sum_x = 0;
    for (int i = 0; i < p.size(); ++i) {
      (p.x[2 * i + 1] > 0 ? up : down) += r[2 * i + 1];
      sum_x += r[2 * i];
    }
    EXPECT_NEAR(up, 0.1 * 0.8, 1e-12) << "amplitude " << amplitude;
    EXPECT_NEAR(down, -0.1 * 0.8, 1e-12) << "amplitude " << amplitude;
    EXPECT_NEAR(sum_x, 0.0, 1e-12);
  }
}

// The pressure follows the deformed bond, so it has a stiffness: the assembled blocks,
// the matrix-free product and the diagonal must all be -d(forces)/du (central differences).
TEST(CrackPressure, StiffnessProductAndDiagonalAreMinusTheForceDerivative) {
  const pd::Scene s = crack_scene(0.5, 0.1, 0.2, {-0.25, 0.01, 0}, {0.25, -0.01, 0}, 0.3);
  const pd::Particles p = pd::discretize(s);
  pd::Bonds b = pd::find_bonds(p, 3 * s.h, [](double, double) { return 1.0; });
  pd::cut_bonds(s.cracks, p, b);
  const auto effect = pd::make_crack_pressure(s, p, b);
  ASSERT_NE(effect, nullptr);
  const pd::SparsityPattern pattern(b, 2);
  const std::size_t n = p.x.size();
  std::vector<double> u(n), v(n);
  for (std::size_t i = 0; i < n; ++i) u[i] = 0.02 * std::sin(1.7 * i), v[i] = std::cos(0.9 * i);
  const double load = 0.7;
  pd::SparseMatrix K = pattern.matrix();
  effect->add_stiffness(u.data(), load, pattern, K);
  // -d r / du v by central differences along v.
  const double eps = 1e-6;
  std::vector<double> up(u), um(u), rp(n, 0.0), rm(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) up[i] += eps * v[i], um[i] -= eps * v[i];
  effect->add_forces(up.data(), load, rp.data());
  effect->add_forces(um.data(), load, rm.data());
  const Eigen::Map<const Eigen::VectorXd> V(v.data(), n);
  const Eigen::VectorXd KV = K * V;
  std::vector<double> Kv(n, 0.0), diag(n, 0.0);
  effect->add_stiffness_product(u.data(), load, v.data(), Kv.data());
  effect->add_stiffness_diagonal(u.data(), load, diag.data());
  double scale = 0;
  for (std::size_t i = 0; i < n; ++i) scale = std::max(scale, std::fabs(KV[i]));
  ASSERT_GT(scale, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    const double fd = -(rp[i] - rm[i]) / (2 * eps);
    EXPECT_NEAR(KV[i], fd, 1e-6 * scale) << "dof " << i;
    EXPECT_NEAR(Kv[i], KV[i], 1e-13 * scale) << "dof " << i;
    EXPECT_NEAR(diag[i], K.coeff(static_cast<int>(i), static_cast<int>(i)), 1e-13 * scale) << "dof " << i;
  }
}

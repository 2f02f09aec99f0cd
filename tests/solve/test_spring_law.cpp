// The test-only laws themselves: hand-derived tangent factors and JVP against central
// differences of the residual kernel, forces against the energy, on random families.
#include <gtest/gtest.h>

#include <random>

#include "local_matrix.hpp"
#include "support_spring_law.hpp"

namespace {
struct RandomFamily {
  int dim, L;
  std::vector<double> xi, Y, w, alpha, V, params, moments;
  pd::abi::Family family(const pd::abi::LawDescriptor& law) {
    pd::abi::Family f;
    f.n_bonds = L;
    f.xi = xi.data();
    f.Y = Y.data();
    f.w = w.data();
    f.alpha = alpha.data();
    f.V = V.data();
    f.V0 = 0.013;
    f.delta = 0.3;
    f.params = params.data();
    moments.assign(static_cast<std::size_t>(law.n_moments) + 1, 0.0);
    f.moments = moments.data();
    if (law.n_moments) law.damaged.moments(f, moments.data());
    return f;
  }
  RandomFamily(int d, int n, unsigned seed) : dim(d), L(n) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> U(-1, 1);
    for (int k = 0; k < L; ++k) {
      for (int c = 0; c < dim; ++c) {
        xi.push_back(0.2 * U(rng));
        Y.push_back(xi.back() * (1.0 + 0.1 * U(rng)) + 0.02 * U(rng));
      }
      w.push_back(0.5 + 0.5 * U(rng) * U(rng));
      alpha.push_back(k % 4 == 3 ? 0.0 : 1.0);  // some broken bonds
      V.push_back(0.01 * (1.2 + U(rng)));
    }
    params = {2.3, 0.7};
  }
};

void check_law(const pd::abi::LawDescriptor& law, int dim) {
  RandomFamily rf(dim, 9, 3);
  const pd::abi::Family f = rf.family(law);
  const int n = (f.n_bonds + 1) * dim;
  pd::TangentScratch ts;
  const auto fac = ts.view(dim, law.n_states, f.n_bonds);
  std::vector<double> M(static_cast<std::size_t>(n * n)), f0(n), fp(n), fm(n), ft(n);
  law.damaged.tangent(f, ft.data(), fac);
  law.damaged.residual(f, f0.data());
  for (int i = 0; i < n; ++i) EXPECT_DOUBLE_EQ(ft[i], f0[i]) << "forces from the tangent kernel";
  pd::form_local_matrix(dim, law.n_states, f, fac, M.data());
  // Central differences over each local position: y_0 moves every Y_k, y_{k+1} moves Y_k.
  const double eps = 1e-6;
  std::vector<double> Y0 = rf.Y;
  double worst = 0, scale = 0;
  for (int j = 0; j < n; ++j) {
    const int a = j / dim, c = j % dim;
    for (double sgn : {1.0, -1.0}) {
      rf.Y = Y0;
      for (int k = 0; k < f.n_bonds; ++k)
        if (a == 0) rf.Y[k * dim + c] -= sgn * eps;
      if (a > 0) rf.Y[(a - 1) * dim + c] += sgn * eps;
      pd::abi::Family g = f;
      g.Y = rf.Y.data();
      law.damaged.residual(g, sgn > 0 ? fp.data() : fm.data());
    }
    for (int i = 0; i < n; ++i) {
      const double fd = (fp[i] - fm[i]) / (2 * eps);
      worst = std::max(worst, std::abs(fd - M[static_cast<std::size_t>(i) * n + j]));
      scale = std::max(scale, std::abs(fd));
    }
  }
  rf.Y = Y0;
  EXPECT_GT(scale, 0.0);
  EXPECT_LT(worst, 1e-7 * scale) << law.name;
  // JVP = M dy.
  std::vector<double> dy(n), df(n);
  for (int i = 0; i < n; ++i) dy[i] = std::sin(1.0 + 3.0 * i);
  law.damaged.jvp(f, dy.data(), df.data());
  for (int i = 0; i < n; ++i) {
    double ref = 0;
    for (int j = 0; j < n; ++j) ref += M[static_cast<std::size_t>(i) * n + j] * dy[j];
    EXPECT_NEAR(df[i], ref, 1e-12 * scale * n) << law.name << " jvp row " << i;
  }
  // Forces = -d(V0 W)/dy, by central differences of the energy.
  for (int j = 0; j < n; ++j) {
    const int a = j / dim, c = j % dim;
    double E[2];
    for (int s = 0; s < 2; ++s) {
      const double sgn = s == 0 ? 1.0 : -1.0;
      rf.Y = Y0;
      for (int k = 0; k < f.n_bonds; ++k)
        if (a == 0) rf.Y[k * dim + c] -= sgn * eps;
      if (a > 0) rf.Y[(a - 1) * dim + c] += sgn * eps;
      pd::abi::Family g = f;
      g.Y = rf.Y.data();
      E[s] = g.V0 * law.damaged.energy(g);
    }
    EXPECT_NEAR(f0[j], -(E[0] - E[1]) / (2 * eps), 1e-7 * (1 + std::abs(f0[j])))
        << law.name << " force " << j;
  }
}
}  // namespace

TEST(SpringLaw, LinearSpringTangentMatchesFiniteDifferences) { check_law(pd::test::linear_spring_2d(), 2); }
TEST(SpringLaw, ExactSpringTangentMatchesFiniteDifferences) { check_law(pd::test::spring_2d(), 2); }
TEST(SpringLaw, StateLawTangentMatchesFiniteDifferences2D) { check_law(pd::test::state_law_2d(), 2); }
TEST(SpringLaw, StateLawTangentMatchesFiniteDifferences3D) { check_law(pd::test::state_law_3d(), 3); }

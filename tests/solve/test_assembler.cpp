// Global assembly: K against central differences of the assembled forces, the
// matrix-free product and diagonal against K, rigid motions, thread independence,
// and the NaN check naming the particle.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <limits>

#include "assembly/assembler.hpp"
#include "support_grid.hpp"
#include "support_spring_law.hpp"

namespace {
struct Problem {
  pd::test::Body body;
  std::unique_ptr<pd::FamilyAssembler> a;
  std::vector<double> u;
  Problem(const pd::abi::LawDescriptor& law, std::vector<double> params, int break_every, int dim = 2,
          pd::AssemblerOptions opt = {}) {
    body = dim == 2 ? pd::test::make_grid(2, 7, 6, 1, 2.2, 0.25, break_every)
                    : pd::test::make_grid(3, 4, 3, 3, 1.8, 0.2, break_every);
    a = std::make_unique<pd::FamilyAssembler>(body.particles, body.bonds, law,
                                              std::vector<std::vector<double>>{std::move(params)}, opt);
    u.resize(body.particles.x.size());
    for (std::size_t i = 0; i < u.size(); ++i) u[i] = 0.02 * std::sin(3.1 * body.particles.x[i] + 0.7 * i);
  }
  int n() const { return static_cast<int>(u.size()); }
};

void expect_stiffness_matches_fd(Problem& s) {
  pd::SparseMatrix K;
  std::vector<double> f(s.n()), fp(s.n()), fm(s.n()), f_only(s.n());
  s.a->stiffness(s.u.data(), K, f.data());
  s.a->internal_forces(s.u.data(), f_only.data());
  for (int i = 0; i < s.n(); ++i) EXPECT_NEAR(f[i], f_only[i], 1e-14 * (1 + std::abs(f[i])));
  const Eigen::MatrixXd Kd(K);
  const double eps = 1e-7;
  double worst = 0;
  for (int j = 0; j < s.n(); ++j) {
    std::vector<double> up = s.u, um = s.u;
    up[j] += eps;
    um[j] -= eps;
    s.a->internal_forces(up.data(), fp.data());
    s.a->internal_forces(um.data(), fm.data());
    for (int i = 0; i < s.n(); ++i)
      worst = std::max(worst, std::abs(-(fp[i] - fm[i]) / (2 * eps) - Kd(i, j)));
  }
  EXPECT_LT(worst, 1e-6 * Kd.cwiseAbs().maxCoeff()) << s.a->law().name;
  EXPECT_GT(Kd.cwiseAbs().maxCoeff(), 0.0);
}
}  // namespace

TEST(Assembler, StiffnessIsMinusDerivativeOfForcesSpring) {
  Problem s(pd::test::spring_2d(), {1.7}, 5);
  expect_stiffness_matches_fd(s);
}

TEST(Assembler, StiffnessIsMinusDerivativeOfForcesStateLaw) {
  Problem s(pd::test::state_law_2d(), {2.0, 0.6}, 6);
  expect_stiffness_matches_fd(s);
}

TEST(Assembler, StiffnessIsMinusDerivativeOfForcesStateLaw3D) {
  Problem s(pd::test::state_law_3d(), {2.0, 0.6}, 7, 3);
  expect_stiffness_matches_fd(s);
}

TEST(Assembler, EnergyLawGivesSymmetricStiffness) {
  Problem s(pd::test::state_law_2d(), {2.0, 0.6}, 6);
  pd::SparseMatrix K;
  s.a->stiffness(s.u.data(), K);
  const Eigen::MatrixXd Kd(K);
  EXPECT_LT((Kd - Kd.transpose()).cwiseAbs().maxCoeff(), 1e-12 * Kd.cwiseAbs().maxCoeff());
}

TEST(Assembler, MatrixFreeProductAndDiagonalEqualTheMatrix) {
  for (const auto* law : {&pd::test::spring_2d(), &pd::test::state_law_2d()}) {
    Problem s(*law, law->n_params == 1 ? std::vector<double>{2.0} : std::vector<double>{2.0, 0.6}, 4);
    pd::SparseMatrix K;
    s.a->stiffness(s.u.data(), K);
    std::vector<double> v(s.n()), Kv(s.n()), diag(s.n());
    for (int i = 0; i < s.n(); ++i) v[i] = std::cos(0.3 + 1.7 * i);
    s.a->stiffness_product(s.u.data(), v.data(), Kv.data());
    const Eigen::VectorXd ref = K * Eigen::Map<const Eigen::VectorXd>(v.data(), s.n());
    const double scale = ref.cwiseAbs().maxCoeff();
    for (int i = 0; i < s.n(); ++i) EXPECT_NEAR(Kv[i], ref[i], 1e-12 * scale) << law->name;
    s.a->stiffness_diagonal(s.u.data(), diag.data());
    for (int i = 0; i < s.n(); ++i)
      EXPECT_NEAR(diag[i], K.coeff(i, i), 1e-12 * scale) << law->name << " diag " << i;
  }
}

TEST(Assembler, RigidMotionsGiveNoForce) {
  Problem s(pd::test::state_law_2d(), {2.0, 0.6}, 5);
  const int n = s.n() / 2;
  std::vector<double> u(s.n()), f(s.n());
  // Translation: exactly zero stretch, so zero force to rounding.
  for (int p = 0; p < n; ++p) u[2 * p] = 0.3, u[2 * p + 1] = -0.2;
  s.a->internal_forces(u.data(), f.data());
  double fmax = 0;
  for (double x : f) fmax = std::max(fmax, std::abs(x));
  EXPECT_LT(fmax, 1e-15);
  // A finite rotation: the geometrically exact law feels no stretch either.
  const double c = std::cos(0.4), sn = std::sin(0.4);
  for (int p = 0; p < n; ++p) {
    const double x = s.body.particles.x[2 * p], y = s.body.particles.x[2 * p + 1];
    u[2 * p] = c * x - sn * y - x;
    u[2 * p + 1] = sn * x + c * y - y;
  }
  s.a->internal_forces(u.data(), f.data());
  fmax = 0;
  for (double x : f) fmax = std::max(fmax, std::abs(x));
  EXPECT_LT(fmax, 1e-12);
  // A stretch does produce forces (the check above can fail).
  for (int p = 0; p < n; ++p) u[2 * p] = 0.01 * s.body.particles.x[2 * p], u[2 * p + 1] = 0;
  s.a->internal_forces(u.data(), f.data());
  fmax = 0;
  for (double x : f) fmax = std::max(fmax, std::abs(x));
  EXPECT_GT(fmax, 1e-8);
}

TEST(Assembler, ForcesBalance) {
  Problem s(pd::test::state_law_2d(), {2.0, 0.6}, 5);
  std::vector<double> f(s.n());
  s.a->internal_forces(s.u.data(), f.data());
  double sx = 0, sy = 0, mag = 0;
  for (int p = 0; p < s.n() / 2; ++p) sx += f[2 * p], sy += f[2 * p + 1], mag += std::abs(f[2 * p]);
  EXPECT_GT(mag, 0.0);
  EXPECT_LT(std::abs(sx) + std::abs(sy), 1e-13 * mag);
}

TEST(Assembler, OneAndTwoThreadsGiveIdenticalResults) {
  for (int chunk : {1, 3, 0}) {
    pd::AssemblerOptions opt;
    opt.chunk_size = chunk;
    Problem s(pd::test::state_law_2d(), {2.0, 0.6}, 5, 2, opt);
    std::vector<double> f1(s.n()), f2(s.n()), v(s.n()), p1(s.n()), p2(s.n());
    for (int i = 0; i < s.n(); ++i) v[i] = std::cos(0.3 + 1.7 * i);
    pd::SparseMatrix K1, K2;
    s.a->set_threads(1);
    s.a->stiffness(s.u.data(), K1, f1.data());
    s.a->stiffness_product(s.u.data(), v.data(), p1.data());
    s.a->set_threads(2);
    s.a->stiffness(s.u.data(), K2, f2.data());
    s.a->stiffness_product(s.u.data(), v.data(), p2.data());
    EXPECT_EQ(f1, f2);
    EXPECT_EQ(p1, p2);
    ASSERT_EQ(K1.nonZeros(), K2.nonZeros());
    EXPECT_TRUE(std::equal(K1.valuePtr(), K1.valuePtr() + K1.nonZeros(), K2.valuePtr()));
  }
}

TEST(Assembler, IntactVariantEqualsDamagedWithoutBrokenBonds) {
  pd::AssemblerOptions opt;
  opt.intact = true;
  Problem a(pd::test::state_law_2d(), {2.0, 0.6}, 0, 2, opt), b(pd::test::state_law_2d(), {2.0, 0.6}, 0);
  std::vector<double> fa(a.n()), fb(b.n());
  a.a->internal_forces(a.u.data(), fa.data());
  b.a->internal_forces(b.u.data(), fb.data());
  for (int i = 0; i < a.n(); ++i) EXPECT_NEAR(fa[i], fb[i], 1e-14);
}

TEST(Assembler, NonFiniteValueNamesStageAndParticle) {
  Problem s(pd::test::spring_2d(), {1.0}, 0);
  std::vector<double> u = s.u, f(s.n());
  u[2 * 17] = std::numeric_limits<double>::quiet_NaN();  // particle 17 and its neighbours go bad
  try {
    s.a->internal_forces(u.data(), f.data());
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("force assembly"), std::string::npos) << msg;
    EXPECT_NE(msg.find("particle"), std::string::npos) << msg;
    EXPECT_NE(msg.find("test_spring_2d"), std::string::npos) << msg;
  }
  pd::SparseMatrix K;
  EXPECT_THROW(s.a->stiffness(u.data(), K), std::runtime_error);
}

TEST(Assembler, MomentsFollowBrokenBonds) {
  Problem s(pd::test::state_law_2d(), {2.0, 0.6}, 0);
  const double m0 = s.a->inputs().moments[10];
  auto& bonds = const_cast<pd::Bonds&>(s.body.bonds);
  for (int e = bonds.offsets[10]; e < bonds.offsets[11]; ++e) bonds.alpha[e] = 0.5;
  s.a->update_moments();
  EXPECT_NEAR(s.a->inputs().moments[10], 0.5 * m0, 1e-15 * m0);
}

// Damage can cut a particle free (every bond of its family broken). LPS divides by the
// weighted volume over intact bonds, which is then 0: before has_intact_bond the moments
// update threw and the forces were 0/0. The particle must carry no force and no stiffness,
// and the rest of the body must assemble as before.
TEST(Assembler, AParticleCutFreeByDamageCarriesNoForceAndNoStiffness) {
  const pd::abi::LawDescriptor* lps = pd::abi::find_law("lps_plane_strain");
  ASSERT_NE(lps, nullptr);
  Problem s(*lps, {1.3, 0.8}, 0);
  auto& bonds = const_cast<pd::Bonds&>(s.body.bonds);
  const int cut = 17;
  for (int p = 0; p < s.body.particles.size(); ++p)
    for (int e = bonds.offsets[p]; e < bonds.offsets[p + 1]; ++e)
      if (p == cut || bonds.neighbor[e] == cut) bonds.alpha[e] = 0.0;
  ASSERT_NO_THROW(s.a->update_moments());
  std::vector<double> f(s.n());
  ASSERT_NO_THROW(s.a->internal_forces(s.u.data(), f.data()));
  for (int c = 0; c < 2; ++c) EXPECT_EQ(f[2 * cut + c], 0.0);
  double others = 0;
  for (double v : f) others = std::max(others, std::abs(v));
  EXPECT_GT(others, 0.0);
  pd::SparseMatrix K;
  s.a->stiffness(s.u.data(), K);
  const Eigen::MatrixXd Kd(K);
  EXPECT_TRUE(Kd.allFinite());
  EXPECT_EQ(Kd.row(2 * cut).cwiseAbs().sum() + Kd.col(2 * cut).cwiseAbs().sum(), 0.0);
  expect_stiffness_matches_fd(s);
  EXPECT_TRUE(std::isfinite(s.a->strain_energy(s.u.data())));
  for (double v : s.a->particle_outputs(s.u.data())) EXPECT_TRUE(std::isfinite(v));
}

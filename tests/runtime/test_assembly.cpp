// Global assembly: the sparsity slots, the stiffness against central differences of the
// assembled forces (with broken bonds and a perturbed cloud), the matrix-free product,
// symmetry, thread independence, and the linear solvers on the assembled system.
#include <gtest/gtest.h>

#include <omp.h>

#include <Eigen/Dense>

#include <cmath>
#include <set>

#include "assemble/assembler.hpp"
#include "discretize/discretization.hpp"
#include "material/elastic_constants.hpp"
#include "solvers/linear_solver.hpp"

namespace {
struct Fixture {
  pd::Scene scene;
  pd::Particles p;
  pd::Bonds b;
  std::unique_ptr<pd::Assembler> a;
  std::vector<double> u;

  explicit Fixture(bool crack) {
    scene.dim = 2;
    scene.lo = {0, 0, 0};
    scene.hi = {1.2, 0.9, 0};
    scene.h = 0.15;
    scene.perturbation = 0.2;
    scene.materials.resize(1);
    p = pd::discretize(scene);
    const auto* law = pd::abi::find_law("silling_plane_strain");
    b = pd::find_bonds(p, 3 * scene.h, pd::abi::find_influence("cubic")->weight);
    if (crack) {
      pd::Crack c;
      c.points = {pd::Point{0.3, 0.46, 0}, pd::Point{0.8, 0.44, 0}};
      EXPECT_GT(pd::cut_bonds({c}, p, b), 0);
    }
    const auto m = pd::IsotropicElastic::from_E_nu(1.0, 0.3);
    a = std::make_unique<pd::Assembler>(p, b, *law, std::vector<std::vector<double>>{pd::law_parameters(*law, m, pd::PlaneAssumption::Strain, {})},
                                        !crack);
    u.resize(p.x.size());
    for (std::size_t i = 0; i < u.size(); ++i) u[i] = 0.01 * std::sin(3.1 * p.x[i] + 0.7 * i);
  }
};
}  // namespace

TEST(Assembly, SlotsAddressTheRightEntries) {
  Fixture f(false);
  pd::SparseMatrix K = f.a->sparsity().zero_matrix();
  std::set<int> seen;
  for (int a = 0; a < f.p.size(); ++a)
    for (int e = f.b.offsets[a]; e < f.b.offsets[a + 1]; ++e) {
      const int b = f.b.neighbor[e];
      for (int r = 0; r < 2; ++r)
        for (int q = 0; q < 2; ++q) {
          const int s = f.a->sparsity().slot(a, b, r, q);
          ASSERT_GE(s, K.outerIndexPtr()[b * 2 + q]);
          ASSERT_LT(s, K.outerIndexPtr()[b * 2 + q + 1]);
          EXPECT_EQ(K.innerIndexPtr()[s], a * 2 + r);
          seen.insert(s);
        }
    }
  EXPECT_EQ(static_cast<long long>(f.a->sparsity().nonzeros()), K.nonZeros());
}

TEST(Assembly, StiffnessIsMinusTheDerivativeOfTheForces) {
  for (bool crack : {false, true}) {
    Fixture f(crack);
    pd::SparseMatrix K;
    std::vector<double> forces;
    f.a->stiffness(f.u, K, &forces);
    const Eigen::MatrixXd Kd = Eigen::MatrixXd(K);
    const int n = static_cast<int>(f.u.size());
    double scale = Kd.cwiseAbs().maxCoeff(), worst = 0;
    for (int j = 0; j < n; ++j) {
      std::vector<double> up = f.u, um = f.u, fp, fm;
      const double step = 1e-6;
      up[j] += step;
      um[j] -= step;
      f.a->forces(up, fp);
      f.a->forces(um, fm);
      for (int i = 0; i < n; ++i) worst = std::max(worst, std::fabs(Kd(i, j) + (fp[i] - fm[i]) / (2 * step)));
    }
    EXPECT_LE(worst / scale, 1e-6) << (crack ? "with crack" : "intact");
    std::vector<double> f2;
    f.a->forces(f.u, f2);
    for (int i = 0; i < n; ++i) EXPECT_NEAR(forces[i], f2[i], 1e-12 * scale);
  }
}

TEST(Assembly, StiffnessOfAnEnergyLawIsSymmetricAndMatrixFreeProductAgrees) {
  Fixture f(true);
  pd::SparseMatrix K;
  f.a->stiffness(f.u, K, nullptr);
  const Eigen::MatrixXd Kd = Eigen::MatrixXd(K);
  const double scale = Kd.cwiseAbs().maxCoeff();
  EXPECT_LE((Kd - Kd.transpose()).cwiseAbs().maxCoeff(), 1e-12 * scale);
  std::vector<double> v(f.u.size()), Kv;
  for (std::size_t i = 0; i < v.size(); ++i) v[i] = std::cos(0.37 * i);
  f.a->apply_stiffness(f.u, v, Kv);
  const Eigen::VectorXd expected = Kd * Eigen::Map<Eigen::VectorXd>(v.data(), static_cast<Eigen::Index>(v.size()));
  for (std::size_t i = 0; i < v.size(); ++i) EXPECT_NEAR(Kv[i], expected[i], 1e-11 * scale);
}

TEST(Assembly, OneAndTwoThreadsAgree) {
  Fixture f(true);
  pd::SparseMatrix K1, K2;
  std::vector<double> f1, f2;
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  f.a->stiffness(f.u, K1, &f1);
  omp_set_num_threads(2);
  f.a->stiffness(f.u, K2, &f2);
  omp_set_num_threads(threads);
  const double scale = Eigen::MatrixXd(K1).cwiseAbs().maxCoeff();
  EXPECT_LE((Eigen::MatrixXd(K1) - Eigen::MatrixXd(K2)).cwiseAbs().maxCoeff(), 1e-13 * scale);
  for (std::size_t i = 0; i < f1.size(); ++i) EXPECT_NEAR(f1[i], f2[i], 1e-13 * scale);
}

TEST(LinearSolvers, AllMethodsSolveTheConstrainedStiffness) {
  Fixture f(false);
  pd::SparseMatrix K;
  f.a->stiffness(std::vector<double>(f.u.size(), 0.0), K, nullptr);
  // Clamp the first row of particles (y < h) by keeping only the other dofs.
  std::vector<int> keep;
  for (int i = 0; i < f.p.size(); ++i)
    if (f.p.x[2 * i + 1] > f.scene.h) keep.push_back(2 * i), keep.push_back(2 * i + 1);
  const Eigen::MatrixXd Kd = Eigen::MatrixXd(K);
  Eigen::MatrixXd Kr(keep.size(), keep.size());
  for (std::size_t i = 0; i < keep.size(); ++i)
    for (std::size_t j = 0; j < keep.size(); ++j) Kr(i, j) = Kd(keep[i], keep[j]);
  const pd::SparseMatrix A = Kr.sparseView();
  Eigen::VectorXd b(keep.size());
  for (Eigen::Index i = 0; i < b.size(); ++i) b[i] = std::sin(0.3 * i);
  const Eigen::VectorXd exact = Kr.ldlt().solve(b);
  for (const char* name : {"cholmod", "umfpack", "cg", "bicgstab"}) {
    std::string why;
    auto s = pd::make_linear_solver(name, static_cast<long long>(keep.size()), true, 1e-13, why);
    s->factor(A);
    pd::LinearSolveReport r;
    const Eigen::VectorXd x = s->solve(b, r);
    EXPECT_LE((x - exact).norm(), 1e-8 * exact.norm()) << name;
    EXPECT_EQ(r.method, name);
  }
  std::string why;
  EXPECT_EQ(pd::make_linear_solver("auto", 1000, true, 1e-12, why)->name(), "cholmod");
  EXPECT_EQ(pd::make_linear_solver("auto", 1000, false, 1e-12, why)->name(), "umfpack");
  EXPECT_EQ(pd::make_linear_solver("auto", 10000000, true, 1e-12, why)->name(), "cg");
}

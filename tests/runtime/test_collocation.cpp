// Collocation assembly (paper 001 eq. 2.13) with OBQ weights on a perturbed cloud: the
// forces equal the paper's sum written out by hand, and the assembled tangent, its
// diagonal and the tangent-vector product agree with finite differences of the forces.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "assembly/assembler.hpp"
#include "obq_cloud.hpp"

namespace {
const double kLambda = 0.7, kMu = 0.4;

std::vector<std::vector<double>> lps_params(const pd::abi::LawDescriptor& law) {
  std::vector<double> p(law.n_params);
  for (int i = 0; i < law.n_params; ++i) p[i] = std::string(law.param_names[i]) == "lambda" ? kLambda : kMu;
  return {p};
}

std::vector<double> random_field(int n, double scale, unsigned seed) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> U(-scale, scale);
  std::vector<double> v(n);
  for (double& x : v) x = U(gen);
  return v;
}

// Paper 001 eqs. 2.13-2.14 written out, 2D (C_a = 2, C_b = 16), K = w: the nodal force
// V_i sum_j [C_a (lambda - mu) (theta_i + theta_j) xi + C_b mu (xi (x) xi / |xi|^2) eta]
// K_ij omega_{j,i} / m_i ... with each family's m and theta from its own weights; the
// t_j<i> term uses m_j (the law divides by the family's weighted volume).
std::vector<double> paper_forces(const obq_test::Cloud& c, const pd::Collocation& col,
                                 const std::vector<double>& u) {
  const pd::Bonds& B = c.bonds;
  const int n = c.particles.size();
  std::vector<double> m(n, 0.0), theta(n, 0.0), f(2 * n, 0.0);
  for (int p = 0; p < n; ++p) {
    for (int b = B.offsets[p]; b < B.offsets[p + 1]; ++b)
      m[p] += B.w[b] * B.length[b] * B.length[b] * col.weight[b];
    for (int b = B.offsets[p]; b < B.offsets[p + 1]; ++b) {
      const int q = B.neighbor[b];
      theta[p] += 2 / m[p] * B.w[b] * col.weight[b] *
                  (B.xi[2 * b] * (u[2 * q] - u[2 * p]) + B.xi[2 * b + 1] * (u[2 * q + 1] - u[2 * p + 1]));
    }
  }
  // t_p<q> for the bond b = (p -> q), force state along xi (small displacement).
  auto t = [&](int p, int b, int comp) {
    const int q = B.neighbor[b];
    const double* xi = &B.xi[2 * b];
    const double eta_dot = xi[0] * (u[2 * q] - u[2 * p]) + xi[1] * (u[2 * q + 1] - u[2 * p + 1]);
    const double r2 = B.length[b] * B.length[b];
    return B.w[b] / m[p] * (2 * (kLambda - kMu) * theta[p] * xi[comp] + 8 * kMu * eta_dot / r2 * xi[comp]);
  };
  for (int i = 0; i < n; ++i)
    for (int b = B.offsets[i]; b < B.offsets[i + 1]; ++b) {
      const int j = B.neighbor[b];
      int r = B.offsets[j];
      while (B.neighbor[r] != i) ++r;  // the reverse bond j -> i
      for (int comp = 0; comp < 2; ++comp)
        f[2 * i + comp] += c.particles.volume[i] * (t(i, b, comp) - t(j, r, comp)) * col.weight[b];
    }
  return f;
}
}  // namespace

TEST(Collocation, ForcesAreThePapersSumOverNonSymmetricWeights) {
  const obq_test::Cloud c = obq_test::unit_square_cloud(1.0 / 16);
  const pd::Collocation col = obq_test::paper001_collocation(c);
  const auto* law = pd::abi::find_law("lps_plane_strain");
  ASSERT_NE(law, nullptr);
  pd::AssemblerOptions opt;
  opt.collocation = &col;
  const pd::FamilyAssembler A(c.particles, c.bonds, *law, lps_params(*law), opt);
  const std::vector<double> u = random_field(2 * c.particles.size(), 1e-3, 5);
  std::vector<double> f(u.size());
  A.internal_forces(u.data(), f.data());
  const std::vector<double> expected = paper_forces(c, col, u);
  double scale = 0, worst = 0;
  for (size_t i = 0; i < f.size(); ++i) scale = std::max(scale, std::abs(expected[i]));
  for (size_t i = 0; i < f.size(); ++i) worst = std::max(worst, std::abs(f[i] - expected[i]));
  EXPECT_LT(worst, 1e-12 * scale);
  // The weights really are not symmetric (else this test would not test collocation).
  double asym = 0;
  for (int b = c.bonds.offsets[200]; b < c.bonds.offsets[201]; ++b)
    asym = std::max(asym, std::abs(col.row_scale[b] - 1));
  EXPECT_GT(asym, 1e-3);
}

TEST(Collocation, TangentProductAndDiagonalMatchFiniteDifferencesOnAPerturbedCloud) {
  const obq_test::Cloud c = obq_test::unit_square_cloud(1.0 / 12);
  const pd::Collocation col = obq_test::paper001_collocation(c);
  for (const char* name : {"lps_plane_strain", "lps_corrected_plane_strain"}) {
    const auto* law = pd::abi::find_law(name);
    ASSERT_NE(law, nullptr);
    pd::AssemblerOptions opt;
    opt.collocation = &col;
    const pd::FamilyAssembler A(c.particles, c.bonds, *law, lps_params(*law), opt);
    EXPECT_FALSE(A.symmetric());
    EXPECT_FALSE(A.has_energy());
    const int N = A.dofs();
    const std::vector<double> u = random_field(N, 1e-2, 7);
    pd::SparseMatrix K = A.make_matrix();
    A.stiffness(u.data(), K);
    const Eigen::MatrixXd Kd(K);
    // Central differences of the forces, column by column: K = -df/du.
    const double eps = 1e-6;
    std::vector<double> up = u, fp(N), fm(N);
    double worst = 0, scale = Kd.cwiseAbs().maxCoeff();
    for (int j = 0; j < N; ++j) {
      up[j] = u[j] + eps;
      A.internal_forces(up.data(), fp.data());
      up[j] = u[j] - eps;
      A.internal_forces(up.data(), fm.data());
      up[j] = u[j];
      for (int i = 0; i < N; ++i) worst = std::max(worst, std::abs(-(fp[i] - fm[i]) / (2 * eps) - Kd(i, j)));
    }
    EXPECT_LT(worst, 1e-7 * scale) << name;
    EXPECT_GT((Kd - Kd.transpose()).cwiseAbs().maxCoeff(), 1e-3 * scale)
        << name << ": expected a non-symmetric K";
    // The matrix-free product and the diagonal against the assembled matrix.
    const std::vector<double> v = random_field(N, 1.0, 9);
    std::vector<double> Kv(N), diag(N);
    A.stiffness_product(u.data(), v.data(), Kv.data());
    A.stiffness_diagonal(u.data(), diag.data());
    const Eigen::VectorXd ref = Kd * Eigen::Map<const Eigen::VectorXd>(v.data(), N);
    for (int i = 0; i < N; ++i) {
      EXPECT_NEAR(Kv[i], ref[i], 1e-12 * scale * N) << name << " row " << i;
      EXPECT_NEAR(diag[i], Kd(i, i), 1e-12 * scale) << name << " row " << i;
    }
  }
}

TEST(Collocation, SymmetricPairWeightsConserveMomentumAndKeepALatticeInterior) {
  // Perturbed cloud: V_p w'_{q,p} = V_q w'_{p,q} for every pair, so the pair forces of
  // eq. (2.13) are equal and opposite: the forces sum to zero for any displacement, and
  // the tangent of an energy law (LPS) is symmetric again.
  const obq_test::Cloud c = obq_test::unit_square_cloud(1.0 / 12);
  const pd::Collocation plain = obq_test::paper001_collocation(c);
  const std::vector<double> w = pd::symmetric_pair_weights(c.particles, c.bonds, plain.weight);
  const pd::Bonds& B = c.bonds;
  for (int p = 0; p < B.particle_count(); ++p)
    for (int b = B.offsets[p]; b < B.offsets[p + 1]; ++b) {
      const int q = B.neighbor[b];
      int r = B.offsets[q];
      while (B.neighbor[r] != p) ++r;
      EXPECT_NEAR(c.particles.volume[p] * w[b], c.particles.volume[q] * w[r], 1e-15) << p << " -> " << q;
    }
  const pd::Collocation col = pd::make_collocation(c.particles, c.bonds, w);
  const auto* law = pd::abi::find_law("lps_plane_strain");
  pd::AssemblerOptions opt;
  opt.collocation = &col;
  const pd::FamilyAssembler A(c.particles, c.bonds, *law, lps_params(*law), opt);
  const std::vector<double> u = random_field(A.dofs(), 1e-2, 3);
  std::vector<double> f(u.size());
  A.internal_forces(u.data(), f.data());
  double sum[2] = {0, 0}, size = 0;
  for (std::size_t i = 0; i < f.size(); ++i) sum[i % 2] += f[i], size = std::max(size, std::abs(f[i]));
  EXPECT_LT(std::abs(sum[0]) + std::abs(sum[1]), 1e-12 * size * c.particles.size());
  pd::SparseMatrix K = A.make_matrix();
  A.stiffness(u.data(), K);
  const Eigen::MatrixXd Kd(K);
  EXPECT_LT((Kd - Kd.transpose()).cwiseAbs().maxCoeff(), 1e-12 * Kd.cwiseAbs().maxCoeff());
  // With the paper's collocation weights the same forces do not sum to zero.
  pd::AssemblerOptions opt_plain;
  opt_plain.collocation = &plain;
  const pd::FamilyAssembler A_plain(c.particles, c.bonds, *law, lps_params(*law), opt_plain);
  A_plain.internal_forces(u.data(), f.data());
  double plain_sum = 0;
  for (std::size_t i = 0; i < f.size(); i += 2) plain_sum += f[i];
  EXPECT_GT(std::abs(plain_sum), 1e-6 * size);

  // Regular lattice: an interior family's OBQ weights equal its neighbours' mirrored
  // ones, so symmetrising leaves every family whose neighbours all have full balls as it was.
  const obq_test::Cloud lattice = obq_test::unit_box_cloud(2, 1.0 / 24, 3.5, 0.0);
  const std::vector<double> lw =
      pd::obq_weights(lattice.particles, lattice.bonds, pd::paper001_space(2), lattice.full_ball);
  const std::vector<double> ls = pd::symmetric_pair_weights(lattice.particles, lattice.bonds, lw);
  int checked = 0;
  for (int p = 0; p < lattice.particles.size(); ++p) {
    bool inner = lattice.full_ball[p];
    for (int b = lattice.bonds.offsets[p]; inner && b < lattice.bonds.offsets[p + 1]; ++b)
      inner = lattice.full_ball[lattice.bonds.neighbor[b]];
    if (!inner) continue;
    ++checked;
    for (int b = lattice.bonds.offsets[p]; b < lattice.bonds.offsets[p + 1]; ++b)
      EXPECT_NEAR(ls[b], lw[b], 1e-12 * lattice.particles.volume[p]) << "particle " << p;
  }
  EXPECT_GT(checked, 0);
}

TEST(Collocation, SymmetricPairWeightsGiveASymmetricSystemWithAnEnergy) {
  // With V_p w'_qp = V_q w'_pq the collocation is the energy assembly with w' as volumes:
  // the assembler says so (symmetric(), has_energy(): the solver plan then takes the
  // Cholesky path), its stiffness is symmetric to round-off and its forces are -dE/du.
  // The paper's unsymmetric weights on the same cloud keep the non-symmetric path.
  const obq_test::Cloud c = obq_test::unit_square_cloud(1.0 / 12);
  const pd::Collocation plain = obq_test::paper001_collocation(c);
  const pd::Collocation sym = pd::make_collocation(
      c.particles, c.bonds, pd::symmetric_pair_weights(c.particles, c.bonds, plain.weight));
  EXPECT_TRUE(sym.pair_symmetric);
  EXPECT_FALSE(plain.pair_symmetric);
  const auto* law = pd::abi::find_law("lps_plane_strain");
  pd::AssemblerOptions opt, opt_plain;
  opt.collocation = &sym;
  opt_plain.collocation = &plain;
  const pd::FamilyAssembler A(c.particles, c.bonds, *law, lps_params(*law), opt);
  const pd::FamilyAssembler A_plain(c.particles, c.bonds, *law, lps_params(*law), opt_plain);
  EXPECT_TRUE(A.symmetric());
  EXPECT_TRUE(A.has_energy());
  EXPECT_FALSE(A_plain.symmetric());
  EXPECT_FALSE(A_plain.has_energy());
  EXPECT_THROW(A_plain.strain_energy(std::vector<double>(A.dofs(), 0.0).data()), std::logic_error);

  const std::vector<double> u = random_field(A.dofs(), 1e-2, 5);
  pd::SparseMatrix K = A.make_matrix(), K_plain = A_plain.make_matrix();
  A.stiffness(u.data(), K);
  A_plain.stiffness(u.data(), K_plain);
  const Eigen::MatrixXd Kd(K), Kp(K_plain);
  const double scale = Kd.cwiseAbs().maxCoeff();
  EXPECT_LT((Kd - Kd.transpose()).cwiseAbs().maxCoeff(), 1e-13 * scale);
  EXPECT_GT((Kp - Kp.transpose()).cwiseAbs().maxCoeff(), 1e-3 * scale);

  // f = -dE/du by central differences of the energy, on a few dofs.
  std::vector<double> f(u.size()), v = u;
  A.internal_forces(u.data(), f.data());
  double fmax = 0;
  for (double x : f) fmax = std::max(fmax, std::abs(x));
  const double e = 1e-6;
  for (int i : {0, 7, 40, 101, static_cast<int>(u.size()) - 1}) {
    v[i] = u[i] + e;
    const double ep = A.strain_energy(v.data());
    v[i] = u[i] - e;
    const double em = A.strain_energy(v.data());
    v[i] = u[i];
    EXPECT_NEAR(-(ep - em) / (2 * e), f[i], 1e-6 * fmax) << "dof " << i;
  }
}

// Optimisation-based quadrature weights (paper 001, eq. 2.12): exactness for the
// reproducing space on perturbed interior and boundary families, least norm, the
// LPS integrands of eqs. 2.13-2.14 integrated exactly, and the named error when a
// family is not unisolvent.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <vector>

#include "discretize/ball_box_moments.hpp"
#include "obq_cloud.hpp"

namespace {
using obq_test::Cloud;
Cloud perturbed_cloud(int dim, double h) { return obq_test::unit_box_cloud(dim, h); }

// Largest violation of the constraints over the family, relative to delta^(|b| - s + d),
// the size of each moment.
double worst_constraint_error(const pd::ReproducingSpace& space, const pd::Bonds& bonds,
                              const std::vector<double>& w, int p) {
  double worst = 0;
  for (const pd::BondMonomial& f : space.terms) {
    double sum = 0;
    for (int b = bonds.offsets[p]; b < bonds.offsets[p + 1]; ++b)
      sum += f.value(bonds.dim, &bonds.xi[b * bonds.dim], bonds.length[b]) * w[b];
    const double scale = std::pow(bonds.delta[p], f.degree() - f.inverse_r_power + bonds.dim);
    worst = std::max(worst, std::abs(sum - pd::ball_moment(bonds.dim, f, bonds.delta[p])) / scale);
  }
  return worst;
}

// How many faces of the cloud's box lie within delta of particle p.
int faces_within_horizon(const Cloud& c, int p) {
  int count = 0;
  for (int k = 0; k < c.particles.dim; ++k) {
    const double x = c.particles.position(p)[k], hi = 1.0;
    count += (x < c.delta) + (x > hi - c.delta);
  }
  return count;
}

// The weights of family p alone, in a vector indexed like the bonds.
void family_weights(const Cloud& c, const pd::ReproducingSpace& space, int p, std::vector<double>& w) {
  const int begin = c.bonds.offsets[p];
  const std::vector<double> f = pd::obq_family_weights(
      space, &c.bonds.xi[begin * c.bonds.dim], c.bonds.family_size(p), c.delta, p, c.particles.position(p));
  std::copy(f.begin(), f.end(), w.begin() + begin);
}
}  // namespace

TEST(ObqWeights, ReproduceThePaperSpaceOnPerturbedInteriorAndBoundaryFamilies) {
  for (int dim : {2, 3}) {
    const Cloud c = perturbed_cloud(dim, dim == 2 ? 1.0 / 24 : 1.0 / 10);
    const pd::ReproducingSpace space = pd::paper001_space(dim);
    std::vector<double> w(c.bonds.bond_count(), 0.0);
    double interior = 0, boundary = 0;
    int n_interior = 0, n_boundary = 0;
    for (int p = 0; p < c.particles.size(); ++p) {
      const int faces = faces_within_horizon(c, p);
      if (faces > 1) continue;  // corners and edges: below
      family_weights(c, space, p, w);
      const double e = worst_constraint_error(space, c.bonds, w, p);
      // A family cut by one face still integrates the whole ball exactly (by
      // extrapolation, with larger weights): the constraints hold all the same.
      (faces == 0 ? interior : boundary) = std::max(faces == 0 ? interior : boundary, e);
      ++(faces == 0 ? n_interior : n_boundary);
    }
    EXPECT_GT(n_interior, 0);
    EXPECT_GT(n_boundary, 0);
    EXPECT_LT(interior, 1e-12) << dim << "D";
    EXPECT_LT(boundary, 1e-12) << dim << "D";
  }
}

TEST(ObqWeights, ACornerFamilyOfTheCloudIsNotUnisolventAndTheWholeBodyCallNamesIt) {
  // Particle 0 sits in the corner: about a quarter of its ball holds points, 12 bonds
  // for 15 functions. Paper 001 never asks for these weights (its Dirichlet layer of
  // width delta is not collocated).
  const Cloud c = perturbed_cloud(2, 1.0 / 24);
  try {
    pd::obq_weights(c.particles, c.bonds, pd::paper001_space(2));
    FAIL() << "expected NotUnisolventError";
  } catch (const pd::NotUnisolventError& e) {
    EXPECT_EQ(e.particle(), 0);
    EXPECT_NE(std::string(e.what()).find("particle 0 at"), std::string::npos) << e.what();
  }
}

TEST(ObqWeights, WhereUnisolventFallsBackToVolumesAndCountsTheFamilies) {
  const Cloud c = perturbed_cloud(2, 1.0 / 24);
  const pd::CloudWeights w = pd::obq_weights_where_unisolvent(c.particles, c.bonds, pd::paper001_space(2));
  EXPECT_EQ(w.first_volume_family, 0);  // the corner of the cloud
  EXPECT_GE(w.volume_families, 4);      // at least one per corner
  EXPECT_LT(w.volume_families, c.particles.size() / 20);
  for (int b = c.bonds.offsets[0]; b < c.bonds.offsets[1]; ++b)
    EXPECT_EQ(w.weights[b], c.particles.volume[c.bonds.neighbor[b]]);
  // Every other family is exact.
  std::vector<double> obq(c.bonds.bond_count());
  const int p = c.particles.size() / 2 + 7;
  family_weights(c, pd::paper001_space(2), p, obq);
  for (int b = c.bonds.offsets[p]; b < c.bonds.offsets[p + 1]; ++b) EXPECT_EQ(w.weights[b], obq[b]);
}

TEST(ObqWeights, AreTheLeastNormSolution) {
  // omega minimises |omega|^2 on {A omega = b} iff it is orthogonal to the null space of A.
  const Cloud c = perturbed_cloud(2, 1.0 / 16);
  const pd::ReproducingSpace space = pd::paper001_space(2);
  const int p = c.particles.size() / 2 + 8;
  const int n = c.bonds.family_size(p), begin = c.bonds.offsets[p];
  const std::vector<double> w =
      pd::obq_family_weights(space, &c.bonds.xi[begin * 2], n, c.delta, p, c.particles.position(p));
  Eigen::MatrixXd A(space.terms.size(), n);
  for (int t = 0; t < A.rows(); ++t)
    for (int j = 0; j < n; ++j)
      A(t, j) = space.terms[t].value(2, &c.bonds.xi[(begin + j) * 2], c.bonds.length[begin + j]);
  const Eigen::MatrixXd null = Eigen::FullPivLU<Eigen::MatrixXd>(A).kernel();
  ASSERT_EQ(null.cols(), n - A.rows());
  const Eigen::Map<const Eigen::VectorXd> omega(w.data(), n);
  EXPECT_LT((null.transpose() * omega).norm(), 1e-12 * omega.norm() * null.norm());
  // The weights are not the lattice volume and not symmetric in general.
  double total = omega.sum();
  EXPECT_NEAR(total, M_PI * c.delta * c.delta, 1e-12 * total);
}

TEST(ObqWeights, IntegrateTheLpsTensorKernelOfAQuadraticFieldExactly) {
  // int_B xi (x) xi / |xi|^3 . (p(x + xi) - p(x)) dxi for a quadratic vector field p:
  // with p(x+xi) - p(x) = G xi + (1/2) H[xi, xi], only the even part survives,
  // (1/2) int xi_a xi_b H_bcd xi_c xi_d / |xi|^3, evaluated here by polar quadrature.
  const Cloud c = perturbed_cloud(2, 1.0 / 20);
  const int p = c.particles.size() / 2 + 10;
  std::vector<double> w(c.bonds.bond_count(), 0.0);
  family_weights(c, pd::paper001_space(2), p, w);
  auto field = [](double x, double y) {
    return std::array<double, 2>{0.3 + x * x - 2 * x * y + 0.5 * y, 4 * y * y + x * y - x};
  };
  const double* x0 = c.particles.position(p);
  double discrete[2] = {0, 0};
  for (int b = c.bonds.offsets[p]; b < c.bonds.offsets[p + 1]; ++b) {
    const double* xi = &c.bonds.xi[b * 2];
    const double r = c.bonds.length[b];
    const auto u1 = field(x0[0] + xi[0], x0[1] + xi[1]), u0 = field(x0[0], x0[1]);
    const double proj = (xi[0] * (u1[0] - u0[0]) + xi[1] * (u1[1] - u0[1])) / (r * r * r);
    discrete[0] += xi[0] * proj * w[b];
    discrete[1] += xi[1] * proj * w[b];
  }
  // Reference: midpoint in angle (exact for trigonometric polynomials), exact in r
  // (the integrand is r^0 and r^1 times angular functions: int_0^delta r dr, r^2 dr).
  double exact[2] = {0, 0};
  const int n_phi = 64;
  for (int k = 0; k < n_phi; ++k) {
    const double phi = 2 * M_PI * (k + 0.5) / n_phi, nx = std::cos(phi), ny = std::sin(phi);
    const auto u0 = field(x0[0], x0[1]);
    // p(x + r n) - p(x) = r g(n) + r^2 q(n): fit g, q from two radii (exact for quadratics).
    const auto a = field(x0[0] + nx, x0[1] + ny), bm = field(x0[0] - nx, x0[1] - ny);
    const double g[2] = {0.5 * (a[0] - bm[0]), 0.5 * (a[1] - bm[1])};
    const double q[2] = {0.5 * (a[0] + bm[0]) - u0[0], 0.5 * (a[1] + bm[1]) - u0[1]};
    const double pg = nx * g[0] + ny * g[1], pq = nx * q[0] + ny * q[1];
    const double radial =
        pg * std::pow(c.delta, 2) / 2 + pq * std::pow(c.delta, 3) / 3;  // int r^(0|1) * r dr
    exact[0] += nx * radial * 2 * M_PI / n_phi;
    exact[1] += ny * radial * 2 * M_PI / n_phi;
  }
  const double scale = std::pow(c.delta, 2);
  EXPECT_NEAR(discrete[0], exact[0], 1e-12 * scale);
  EXPECT_NEAR(discrete[1], exact[1], 1e-12 * scale);
}

TEST(ObqWeights, NonUnisolventFamilyIsANamedError) {
  const pd::ReproducingSpace space = pd::paper001_space(2);
  const double center[2] = {0.5, 0.25};
  // Too few bonds: 8 < 15.
  std::vector<double> few;
  for (int k = 0; k < 8; ++k) few.insert(few.end(), {0.1 * std::cos(k), 0.1 * std::sin(k)});
  try {
    pd::obq_family_weights(space, few.data(), 8, 0.2, 7, center);
    FAIL() << "expected NotUnisolventError";
  } catch (const pd::NotUnisolventError& e) {
    EXPECT_EQ(e.particle(), 7);
    EXPECT_NE(std::string(e.what()).find("particle 7 at (0.5, 0.25)"), std::string::npos) << e.what();
  }
  // Enough bonds but all on one line: rank-deficient.
  std::vector<double> line;
  for (int k = 1; k <= 20; ++k)
    line.insert(line.end(), {0.009 * k * (k % 2 ? 1 : -1), 0.0045 * k * (k % 2 ? 1 : -1)});
  EXPECT_THROW(pd::obq_family_weights(space, line.data(), 20, 0.2, 3, center), pd::NotUnisolventError);
}

TEST(ObqWeights, FamiliesAtAFaceOfTheBodyIntegrateOverTheCutBall) {
  // domain.quadrature: obq_cut. The cloud's particles are cell centres of the unit
  // square, so the body they cover is the square itself.
  const Cloud c = perturbed_cloud(2, 1.0 / 24);
  const pd::ReproducingSpace space = pd::paper001_space(2);
  const pd::Box2 body{{0, 0}, {1, 1}};
  double worst = 0, total_weight_gap = 0;
  int cut = 0;
  for (int p = 0; p < c.particles.size(); ++p) {
    if (faces_within_horizon(c, p) != 1) continue;
    const double* x = c.particles.position(p);
    const int begin = c.bonds.offsets[p], n = c.bonds.family_size(p);
    std::vector<double> w;
    try {
      w = pd::obq_family_weights(space, &c.bonds.xi[begin * 2], n, c.delta, p, x, &body);
    } catch (const pd::NotUnisolventError&) {
      continue;  // a shallow half ball may hold too few bonds; counted below
    }
    ++cut;
    for (const pd::BondMonomial& f : space.terms) {
      double sum = 0;
      for (int k = 0; k < n; ++k)
        sum += f.value(2, &c.bonds.xi[(begin + k) * 2], c.bonds.length[begin + k]) * w[k];
      const double scale = std::pow(c.delta, f.degree() - f.inverse_r_power + 2);
      worst = std::max(worst, std::abs(sum - pd::ball_box_moment_2d(f, c.delta, x, body)) / scale);
    }
    // The weights sum to the cut area, not to the whole disc's.
    double sum = 0;
    for (double v : w) sum += v;
    total_weight_gap =
        std::max(total_weight_gap, std::abs(sum - pd::ball_box_moment_2d({}, c.delta, x, body)));
    const double depth = std::min({x[0], 1 - x[0], x[1], 1 - x[1]});
    if (depth < 0.5 * c.delta) {
      EXPECT_LT(sum, 0.9 * M_PI * c.delta * c.delta) << "particle " << p;
    }
  }
  EXPECT_GT(cut, 50);
  EXPECT_LT(worst, 1e-12);
  EXPECT_LT(total_weight_gap, 1e-12);
}

// Paper 001's LPS as written (laws/lps.cpp, lps_paper_*): the generated family forces
// against eq. (2.13)'s per-family half written out by hand here, with the kernel K = 1/r,
// the analytic weighted volume m(delta) of eq. (2.3) (2 pi delta^3 / 3, pi delta^4) for
// a family that lost bonds, and for the corrected variants M^-1 of eq. (3.5) in the
// dilatation only. Tangent = FD and JVP = K v are CheckLaw's, for every law.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "verify/random_family.hpp"

namespace {
// f[(L+1)*dim] of one family, the kernels' convention: the center gains V0 V_k t_k and
// neighbour k loses it (runtime/verify/reference_silling.hpp).
std::vector<double> paper_forces(const pd::verify::TestFamily& f, bool corrected) {
  const int d = f.dim, L = f.bonds();
  const double lambda = f.params[0], mu = f.params[1];
  const double Ca = d == 2 ? 2.0 : 3.0, Cb = d == 2 ? 16.0 : 30.0;
  const double m =
      d == 2 ? 2 * std::numbers::pi * std::pow(f.delta, 3) / 3 : std::numbers::pi * std::pow(f.delta, 4);
  std::vector<Eigen::VectorXd> xi(L), eta(L);
  std::vector<double> K(L);
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(d, d);
  for (int k = 0; k < L; ++k) {
    xi[k] = Eigen::Map<const Eigen::VectorXd>(&f.xi[k * d], d);
    eta[k] = Eigen::Map<const Eigen::VectorXd>(&f.Y[k * d], d) - xi[k];
    K[k] = f.alpha[k] / xi[k].norm();
    M += d / m * K[k] * f.V[k] * xi[k] * xi[k].transpose();
  }
  const Eigen::MatrixXd Minv = corrected ? Eigen::MatrixXd(M.inverse()) : Eigen::MatrixXd::Identity(d, d);
  double theta = 0;
  for (int k = 0; k < L; ++k) theta += d / m * K[k] * xi[k].dot(Minv * eta[k]) * f.V[k];
  std::vector<double> out(static_cast<std::size_t>((L + 1) * d), 0.0);
  for (int k = 0; k < L; ++k) {
    const Eigen::VectorXd t =
        K[k] / m *
        (Ca * (lambda - mu) * theta * xi[k] + Cb / 2 * mu * xi[k].dot(eta[k]) / xi[k].squaredNorm() * xi[k]);
    for (int c = 0; c < d; ++c) {
      out[c] += f.V0 * f.V[k] * t[c];
      out[(k + 1) * d + c] -= f.V0 * f.V[k] * t[c];
    }
  }
  return out;
}

double max_abs(const std::vector<double>& a) {
  double m = 0;
  for (double v : a) m = std::max(m, std::fabs(v));
  return m;
}
}  // namespace

// Edge and corner families with broken bonds under a random deformation: the generated
// force is the hand-written one, whose m is m(delta) whatever the family lost.
TEST(LpsPaper, FamilyForcesAreEq213WithTheAnalyticWeightedVolume) {
  for (const char* name : {"lps_paper_plane_strain", "lps_paper_3d", "lps_paper_corrected_plane_strain",
                           "lps_paper_corrected_3d"}) {
    const auto* law = pd::abi::find_law(name);
    ASSERT_NE(law, nullptr) << name;
    ASSERT_EQ(std::string(law->param_names[0]), "lambda");
    const bool corrected = std::string(name).find("corrected") != std::string::npos;
    for (auto t :
         {pd::verify::Truncation::Interior, pd::verify::Truncation::Edge, pd::verify::Truncation::Corner}) {
      pd::verify::FamilyOptions o;
      o.dim = law->dim;
      o.truncation = t;
      o.broken_bonds = true;
      o.horizon_ratio = law->dim == 2 ? 3.0 : 2.0;
      pd::verify::TestFamily f = pd::verify::make_family(*law, o);
      f.params[0] = 1.7;  // lambda != mu: the dilatation term counts
      f.params[1] = 0.6;
      f.update_moments(law->damaged);
      const auto expected = paper_forces(f, corrected);
      const auto got = f.forces(law->damaged);
      ASSERT_EQ(got.size(), expected.size());
      const double scale = max_abs(expected);
      ASSERT_GT(scale, 0.0);
      for (std::size_t i = 0; i < got.size(); ++i)
        EXPECT_NEAR(got[i], expected[i], 1e-12 * scale)
            << name << " truncation " << static_cast<int>(t) << " dof " << i;
    }
  }
}

// Not vacuous: on a family that lost bonds the discrete m of lps_* (influence w = delta/r,
// the paper's K up to the factor delta) gives other forces than m(delta), and the
// corrected variants differ from lps_paper_* only through M.
TEST(LpsPaper, DiffersFromTheDiscreteVolumeOnADamagedFamily) {
  const auto* paper = pd::abi::find_law("lps_paper_plane_strain");
  const auto* discrete = pd::abi::find_law("lps_plane_strain");
  ASSERT_NE(paper, nullptr);
  ASSERT_NE(discrete, nullptr);
  pd::verify::FamilyOptions o;
  o.truncation = pd::verify::Truncation::Edge;
  o.broken_bonds = true;
  pd::verify::TestFamily f = pd::verify::make_family(*paper, o);
  f.update_moments(paper->damaged);
  const auto a = f.forces(paper->damaged);
  pd::verify::TestFamily g = f;
  g.law = discrete;
  for (int k = 0; k < g.bonds(); ++k) {
    double r2 = 0;
    for (int c = 0; c < g.dim; ++c) r2 += g.xi[k * g.dim + c] * g.xi[k * g.dim + c];
    g.w[k] = g.delta / std::sqrt(r2);
  }
  g.update_moments(discrete->damaged);
  const auto b = g.forces(discrete->damaged);
  std::vector<double> diff(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) diff[i] = a[i] - b[i];
  EXPECT_GT(max_abs(diff), 0.1 * max_abs(a));
}

// The energy claims: the plain variant has the potential of lps_*, the corrected one
// (M^+ in the dilatation, xi in the force) has none.
TEST(LpsPaper, OnlyThePlainVariantDeclaresAnEnergy) {
  for (const char* name : {"lps_paper_plane_strain", "lps_paper_3d"})
    EXPECT_NE(pd::abi::find_law(name)->damaged.energy, nullptr) << name;
  for (const char* name : {"lps_paper_corrected_plane_strain", "lps_paper_corrected_3d"})
    EXPECT_EQ(pd::abi::find_law(name)->damaged.energy, nullptr) << name;
}

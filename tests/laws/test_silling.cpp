// The generated Silling kernels against a straightforward implementation written
// here from paper 000 eqs. (2)-(7) (energy-matched plane-strain form, papers/README.md).
#include <gtest/gtest.h>

#include <cmath>

#include "verify/random_family.hpp"

using pd::verify::FamilyOptions;
using pd::verify::make_family;
using pd::verify::TestFamily;
using pd::verify::Truncation;

namespace {
// Nodal forces of one family, bond by bond, with K = params[0], G = params[1].
std::vector<double> reference_forces(const TestFamily& f) {
  const int d = f.dim, L = f.bonds();
  const double K = f.params[0], G = f.params[1];
  auto len = [&](const std::vector<double>& v, int k) {
    double s = 0;
    for (int c = 0; c < d; ++c) s += v[k * d + c] * v[k * d + c];
    return std::sqrt(s);
  };
  double m = 0, theta = 0;
  for (int k = 0; k < L; ++k) m += f.w[k] * f.alpha[k] * len(f.xi, k) * len(f.xi, k) * f.V[k];
  for (int k = 0; k < L; ++k) theta += f.w[k] * f.alpha[k] * len(f.xi, k) * (len(f.Y, k) - len(f.xi, k)) * f.V[k];
  theta *= d / m;
  std::vector<double> forces(static_cast<std::size_t>((L + 1) * d), 0.0);
  for (int k = 0; k < L; ++k) {
    const double r = len(f.xi, k), l = len(f.Y, k), e = l - r, wa = f.w[k] * f.alpha[k];
    double t = 0;
    if (d == 2) {
      const double kappa2 = K + G / 3;  // plane-strain bulk modulus
      t = wa / m * (2 * kappa2 * theta * r + 8 * G * (e - theta * r / 2));
    } else {
      t = wa / m * (3 * K * theta * r + 15 * G * (e - theta * r / 3));
    }
    for (int c = 0; c < d; ++c) {
      const double fc = f.V0 * f.V[k] * t * f.Y[k * d + c] / l;
      forces[c] += fc;
      forces[(k + 1) * d + c] -= fc;
    }
  }
  return forces;
}

void expect_matches_reference(const char* law_name, int dim) {
  const auto* law = pd::abi::find_law(law_name);
  ASSERT_NE(law, nullptr) << law_name;
  ASSERT_EQ(law->dim, dim);
  ASSERT_EQ(law->n_params, 2);
  EXPECT_STREQ(law->param_names[0], "K");
  EXPECT_STREQ(law->param_names[1], "G");
  for (Truncation t : {Truncation::Interior, Truncation::Edge}) {
    for (bool broken : {false, true}) {
      for (unsigned seed = 1; seed <= 5; ++seed) {
        FamilyOptions o;
        o.dim = dim;
        o.truncation = t;
        o.broken_bonds = broken;
        o.seed = seed;
        o.horizon_ratio = dim == 2 ? 3.0 : 2.0;
        const TestFamily f = make_family(*law, o);
        const auto expected = reference_forces(f);
        const auto forces = f.forces(law->damaged);
        double scale = 0;
        for (double v : expected) scale = std::max(scale, std::fabs(v));
        ASSERT_GT(scale, 0.0);
        for (std::size_t i = 0; i < forces.size(); ++i) EXPECT_NEAR(forces[i], expected[i], 1e-12 * scale) << i;
      }
    }
  }
}
}  // namespace

TEST(Silling, PlaneStrainResidualMatchesIndependentImplementation) {
  expect_matches_reference("silling_plane_strain", 2);
}

TEST(Silling, ThreeDimensionalResidualMatchesIndependentImplementation) { expect_matches_reference("silling_3d", 3); }

TEST(Silling, DilatationOutputOfAUniformExpansion) {
  // y = (1 + s) x on an interior family: every bond stretches by s, so theta = dim * s exactly.
  for (const char* name : {"silling_plane_strain", "silling_3d"}) {
    const auto* law = pd::abi::find_law(name);
    FamilyOptions o;
    o.dim = law->dim;
    o.horizon_ratio = 2.0;
    TestFamily f = make_family(*law, o);
    const double s = 1e-3;
    std::vector<double> y = f.x;
    for (double& v : y) v *= 1 + s;
    f.set_positions(y);
    ASSERT_EQ(law->n_outputs, 1);
    EXPECT_STREQ(law->output_names[0], "dilatation");
    double theta = 0;
    law->damaged.outputs(f.view(), &theta);
    EXPECT_NEAR(theta, law->dim * s, 1e-12);
  }
}

TEST(Silling, RigidRotationGivesZeroForce) {
  const auto* law = pd::abi::find_law("silling_plane_strain");
  TestFamily f = make_family(*law, FamilyOptions{});
  const double a = 1.1, c = std::cos(a), s = std::sin(a);
  std::vector<double> y = f.x;
  for (int p = 0; p <= f.bonds(); ++p) {
    y[2 * p] = c * f.x[2 * p] - s * f.x[2 * p + 1] + 0.3;
    y[2 * p + 1] = s * f.x[2 * p] + c * f.x[2 * p + 1] - 0.2;
  }
  f.set_positions(y);
  for (double v : f.forces(law->damaged)) EXPECT_NEAR(v, 0.0, 1e-12);
}

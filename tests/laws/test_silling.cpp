// The generated Silling kernels against the straightforward implementation of
// runtime/verify/reference_silling.hpp, and its tangent against automatic differentiation.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <unsupported/Eigen/AutoDiff>

#include "verify/random_family.hpp"
#include "verify/reference_silling.hpp"

using pd::verify::FamilyOptions;
using pd::verify::make_family;
using pd::verify::TestFamily;
using pd::verify::Truncation;

namespace {
std::vector<double> reference_forces(const TestFamily& f) {
  std::vector<double> forces(static_cast<std::size_t>(f.dofs()));
  pd::verify::silling_forces<double>(f.dim, f.bonds(), f.xi.data(), f.w.data(), f.alpha.data(), f.V.data(),
                                     f.V0, f.params[0], f.params[1], f.y.data(), forces.data());
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
        for (std::size_t i = 0; i < forces.size(); ++i)
          EXPECT_NEAR(forces[i], expected[i], 1e-12 * scale) << i;
      }
    }
  }
}
}  // namespace

TEST(Silling, PlaneStrainResidualMatchesIndependentImplementation) {
  expect_matches_reference("silling_plane_strain", 2);
}

TEST(Silling, ThreeDimensionalResidualMatchesIndependentImplementation) {
  expect_matches_reference("silling_3d", 3);
}

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

TEST(Silling, TangentEqualsForwardAutomaticDifferentiation) {
  for (const char* name : {"silling_plane_strain", "silling_3d"}) {
    const auto* law = pd::abi::find_law(name);
    FamilyOptions o;
    o.dim = law->dim;
    o.broken_bonds = true;
    o.truncation = Truncation::Edge;
    o.horizon_ratio = law->dim == 2 ? 3.0 : 2.0;
    const TestFamily f = make_family(*law, o);
    const int n = f.dofs();
    using AD = Eigen::AutoDiffScalar<Eigen::VectorXd>;
    std::vector<AD> y(static_cast<std::size_t>(n)), forces(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) y[i] = AD(f.y[i], n, i);
    pd::verify::silling_forces<AD>(f.dim, f.bonds(), f.xi.data(), f.w.data(), f.alpha.data(), f.V.data(),
                                   f.V0, f.params[0], f.params[1], y.data(), forces.data());
    const auto M = f.tangent_matrix(law->damaged);
    double scale = 0;
    for (double v : M) scale = std::max(scale, std::fabs(v));
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j)
        EXPECT_NEAR(M[i * n + j], forces[i].derivatives()[j], 1e-12 * scale) << name;
  }
}

// Mitchell's viscoelastic law (laws/viscoelastic.cpp, issue 29): a ramp and hold against the
// closed-form relaxation of the standard linear solid, the glassy response against the
// elastic part of Mitchell's plastic law (tested in test_history.cpp against a hand-written
// return map), and the algorithmic tangent against central differences of the incremental
// residual with the committed history held fixed, for short and long steps.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "kernel_abi.hpp"
#include "verify/random_family.hpp"
#include "verify/tangent_check.hpp"

namespace {
using pd::verify::FamilyOptions;
using pd::verify::TestFamily;
using pd::verify::Truncation;

constexpr int kLambda = 2, kTau = 3;  // parameter indices: K, G, lambda_i, tau_b

struct Case {
  const char* law;
  Truncation truncation;
};
std::string case_name(const testing::TestParamInfo<Case>& info) {
  const char* t[] = {"Interior", "Edge", "Corner"};
  return std::string(info.param.law) + "_" + t[static_cast<int>(info.param.truncation)];
}

double max_abs(const std::vector<double>& v) {
  double m = 0;
  for (double x : v) m = std::max(m, std::fabs(x));
  return m;
}

class Viscoelastic : public testing::TestWithParam<Case> {
 protected:
  const pd::abi::LawDescriptor& law() const { return *pd::abi::find_law(GetParam().law); }
  TestFamily family(unsigned seed) const {
    FamilyOptions o;
    o.dim = law().dim;
    o.horizon_ratio = o.dim == 2 ? 3.0 : 2.0;
    o.truncation = GetParam().truncation;
    o.seed = seed;
    return pd::verify::make_family(law(), o);
  }
};

// e_d ramps linearly from 0 to its final value over T, then is held. With de_b/dt = (e_d - e_b) / tau
// every bond's back extension is the same fraction g(t) of its e_d:
//   g(T) = 1 - (tau / T)(1 - exp(-T / tau)),   g(t > T) = 1 - (1 - g(T)) exp(-(t - T) / tau),
// and the force is the glassy one less lambda g(t) times the deviatoric force D of e_b = e_d.
TEST_P(Viscoelastic, RampAndHoldFollowsTheClosedFormRelaxation) {
  TestFamily f = family(3);
  const pd::abi::KernelVariant& k = law().damaged;
  const double lambda = f.params[kLambda], tau = f.params[kTau], ramp = 0.5;
  const int L = f.bonds();
  TestFamily glassy = f;  // lambda_i = 0: no Maxwell arm, the history does not enter
  glassy.params[kLambda] = 0.0;
  const std::vector<double> A = glassy.forces(k);
  // The ramp: from the virgin body (e_d,n = e_b,n = 0) to the family's deformation in one step.
  f.time_step = ramp;
  const std::vector<double> ramp_forces = f.forces(k);
  f.commit_update(k);
  std::vector<double> ed(L);
  for (int b = 0; b < L; ++b) ed[b] = f.history[2 * b + 1];
  ASSERT_GT(max_abs(ed), 1e-4) << "the random deformation must have a deviatoric part";
  // D: the glassy force less the force with the Maxwell arm fully relaxed (e_b = e_d,
  // lambda_i = 1, a step of length 0 that leaves e_b where it is).
  TestFamily relaxed = f;
  relaxed.params[kLambda] = 1.0;
  relaxed.time_step = 0.0;
  for (int b = 0; b < L; ++b) relaxed.history[2 * b] = ed[b];
  const std::vector<double> R = relaxed.forces(k);
  const double scale = max_abs(A);
  auto expect_forces = [&](const std::vector<double>& got, double g, const std::string& when) {
    for (std::size_t i = 0; i < A.size(); ++i)
      ASSERT_NEAR(got[i], A[i] - lambda * g * (A[i] - R[i]), 1e-12 * scale) << when << ", dof " << i;
  };
  const double g_ramp = 1 - tau / ramp * (1 - std::exp(-ramp / tau));
  expect_forces(ramp_forces, g_ramp, "end of the ramp");
  for (int b = 0; b < L; ++b) ASSERT_NEAR(f.history[2 * b], g_ramp * ed[b], 1e-14) << "bond " << b;
  // The hold, in steps of unequal length: the update is exact for a constant e_d.
  double t = ramp;
  for (double dt : {0.1, 0.4, 1.3, 2.0, 1e-7}) {
    f.time_step = dt;
    t += dt;
    const double g = 1 - (1 - g_ramp) * std::exp(-(t - ramp) / tau);
    expect_forces(f.forces(k), g, "t = " + std::to_string(t));
    f.commit_update(k);
    for (int b = 0; b < L; ++b) {
      ASSERT_NEAR(f.history[2 * b], g * ed[b], 1e-14) << "t = " << t << ", bond " << b;
      ASSERT_EQ(f.history[2 * b + 1], ed[b]) << "a hold keeps e_d to the bit";
    }
  }
}

// lambda_i = 0 leaves Mitchell's elastic part: the force of the elastic-plastic law far
// below yield.
TEST_P(Viscoelastic, WithoutTheMaxwellArmItIsMitchellsElasticLaw) {
  TestFamily f = family(7);
  f.params[kLambda] = 0.0;
  TestFamily plastic = f;
  plastic.law = pd::abi::find_law(law().dim == 2 ? "elastic_plastic_plane_strain" : "elastic_plastic_3d");
  ASSERT_NE(plastic.law, nullptr);
  plastic.params = {f.params[0], f.params[1], 1e6};
  plastic.history.assign(static_cast<std::size_t>(f.bonds()), 0.0);
  const std::vector<double> a = f.forces(law().damaged), b = plastic.forces(plastic.law->damaged);
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_NEAR(a[i], b[i], 1e-13 * max_abs(b)) << "dof " << i;
}

// The algorithmic tangent (deviatoric stiffness times 1 - lambda_i beta) against central
// differences of the incremental residual, from the virgin body and after a ramp, for a
// step short enough to take beta's series branch, a moderate one and a long one.
TEST_P(Viscoelastic, AlgorithmicTangentMatchesDifferences) {
  TestFamily f = family(11);
  const pd::abi::KernelVariant& k = law().damaged;
  const std::vector<double> y1 = f.y;
  auto check = [&](const std::string& state) {
    const auto M = f.tangent_matrix(k);
    const auto err = pd::verify::block_errors(f, M, f.fd_matrix(k, 1e-6 * f.delta));
    EXPECT_LT(err.worst(), 1e-6) << state << ": center " << err.center << ", on-diagonal " << err.on_diagonal
                                 << ", off-diagonal " << err.off_diagonal;
  };
  for (double dt : {1e-7, 0.3, 5.0}) {
    f.time_step = dt;
    check("virgin, dt " + std::to_string(dt));
  }
  f.time_step = 0.3;
  f.commit_update(k);
  std::vector<double> y(y1.size());
  for (std::size_t i = 0; i < y.size(); ++i) y[i] = f.x[i] - 0.7 * (y1[i] - f.x[i]);  // reversed
  f.set_positions(y);
  for (double dt : {1e-7, 0.3, 5.0}) {
    f.time_step = dt;
    check("after a ramp, reversed, dt " + std::to_string(dt));
  }
}

std::vector<Case> cases() {
  std::vector<Case> out;
  for (const char* law : {"viscoelastic_plane_strain", "viscoelastic_3d"})
    for (Truncation t : {Truncation::Interior, Truncation::Edge, Truncation::Corner}) out.push_back({law, t});
  return out;
}
INSTANTIATE_TEST_SUITE_P(Mitchell, Viscoelastic, testing::ValuesIn(cases()), case_name);

// Only the viscoelastic laws read the time step, and the descriptor says so.
TEST(TimeStep, TheDescriptorMarksTheLawsThatReadIt) {
  for (const pd::abi::LawDescriptor& law : pd::abi::all_laws())
    EXPECT_EQ(law.uses_time_step, std::string(law.name).rfind("viscoelastic", 0) == 0) << law.name;
}

}  // namespace

// Laws with memory (issue 29): the elastic-plastic laws' kernels, perfectly plastic and with
// linear hardening, against an independent, hand-written return map of Mitchell's model
// (laws/elastic_plastic.cpp and laws/elastic_plastic_hardening.cpp state the equations), the algorithmic
// tangent against central differences of the incremental residual on elastic, yielding and unloading states,
// an elastic step that leaves the history unchanged to the bit, and non-negative dissipation over a random
// load path.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "history_law_cases.hpp"
#include "kernel_abi.hpp"
#include "verify/random_family.hpp"
#include "verify/tangent_check.hpp"

namespace {
using pd::test::max_abs;
using pd::test::max_diff;
using pd::test::scale_deformation;
using pd::verify::FamilyOptions;
using pd::verify::TestFamily;
using pd::verify::Truncation;

// Mitchell's return map, written from the equations (not from the generated code).
struct ReturnMap {
  std::vector<double> forces;            // [(L+1)*dim] nodal forces
  std::vector<double> history;           // [L] the plastic extension at the end of the step
  double equivalent_plastic_strain = 0;  // lambda at the end of the step (hardening laws)
  std::vector<double> deviatoric_force;  // [L] t_d per bond
  double scale = 1.0;                    // s: 1 elastic, < 1 yielding
  bool on_or_beyond_yield = false;       // the output "yielding": within 1e-8 of the surface or past it
};

ReturnMap return_map(const TestFamily& f) {
  const int d = f.dim, L = f.bonds();
  const double K = f.params[0], G = f.params[1], sigma_y = f.params[2];
  // The hardening laws' modulus and committed equivalent plastic strain; 0 for the others.
  const bool hardening = f.params.size() > 3;
  const double H = hardening ? f.params[3] : 0.0, lambda = hardening ? f.particle_history.at(0) : 0.0;
  std::vector<double> r(L), l(L), e(L);
  double m = 0, q = 0;
  for (int k = 0; k < L; ++k) {
    double rr = 0, yy = 0;
    for (int c = 0; c < d; ++c) {
      rr += f.xi[k * d + c] * f.xi[k * d + c];
      yy += f.Y[k * d + c] * f.Y[k * d + c];
    }
    r[k] = std::sqrt(rr);
    l[k] = std::sqrt(yy + 1e-16 * rr);  // Law::deformed_length
    e[k] = l[k] - r[k];
    m += f.w[k] * f.alpha[k] * rr * f.V[k];
    q += f.w[k] * f.w[k] * f.alpha[k] * rr * f.V[k];
  }
  double theta = 0;
  for (int k = 0; k < L; ++k) theta += d / m * f.w[k] * f.alpha[k] * r[k] * e[k] * f.V[k];
  const double c = d == 2 ? 8.0 : 15.0, kappa = d == 2 ? K + G / 3 : K;
  std::vector<double> ed(L), trial(L);
  double norm2 = 0;
  for (int k = 0; k < L; ++k) {
    ed[k] = e[k] - theta * r[k] / d;
    trial[k] = c * G / m * f.w[k] * f.alpha[k] * (ed[k] - f.history[k]);
    norm2 += trial[k] * trial[k] * f.V[k];
  }
  // The equivalent (von Mises) stress of the trial state: sqrt(||t_tr||^2) / beta, where
  // beta = c sqrt(q / 24) / m in 2D, c sqrt(q / 45) / m in 3D (Mitchell's psi0 = beta^2 sigma_y^2 / 2).
  const double beta = c * std::sqrt(q / (d == 2 ? 24.0 : 45.0)) / m;
  const double sigma_tr = std::sqrt(norm2) / beta, yield_n = sigma_y + H * lambda;
  ReturnMap out;
  out.equivalent_plastic_strain = lambda;
  if (norm2 >
      beta * beta * yield_n * yield_n) {  // radial return: the consistency condition of linear hardening
    const double d_lambda = (sigma_tr - yield_n) / (3 * G + H);
    out.scale = (yield_n + H * d_lambda) / sigma_tr;
    out.equivalent_plastic_strain = lambda + d_lambda;
  }
  out.on_or_beyond_yield = sigma_tr > (1 - 1e-8) * yield_n;
  out.forces.assign(static_cast<std::size_t>((L + 1) * d), 0.0);
  for (int k = 0; k < L; ++k) {
    out.deviatoric_force.push_back(out.scale * trial[k]);
    const double t = f.w[k] * f.alpha[k] / m * d * kappa * theta * r[k] + out.scale * trial[k];
    for (int cc = 0; cc < d; ++cc) {
      const double fk = f.V0 * f.V[k] * t * f.Y[k * d + cc] / l[k];
      out.forces[(k + 1) * d + cc] = -fk;
      out.forces[cc] += fk;
    }
    out.history.push_back(f.history[k] + (1 - out.scale) * (ed[k] - f.history[k]));
  }
  return out;
}

class PlasticLaw : public testing::TestWithParam<pd::test::HistoryCase> {
 protected:
  const pd::abi::LawDescriptor& law() const {
    const auto* d = pd::abi::find_law(GetParam().law);
    EXPECT_NE(d, nullptr);
    return *d;
  }
  bool hardening() const { return law().n_particle_history > 0; }
  TestFamily family(unsigned seed, double sigma_y) const {
    FamilyOptions o;
    o.dim = law().dim;
    o.horizon_ratio = o.dim == 2 ? 3.0 : 2.0;
    o.truncation = GetParam().truncation;
    o.broken_bonds = GetParam().broken;
    o.seed = seed;
    TestFamily f = pd::verify::make_family(law(), o);
    f.params[2] = sigma_y;
    return f;
  }
};

TEST_P(PlasticLaw, KernelsEqualAnIndependentReturnMap) {
  int yielding = 0, elastic = 0;
  for (unsigned seed = 1; seed <= 6; ++seed) {
    // Alternately a low and a high yield stress, from a committed random plastic history.
    TestFamily f = family(seed, seed % 2 ? 0.01 : 10.0);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-0.05, 0.05);
    for (double& h : f.history) h = u(rng);
    if (hardening()) f.particle_history[0] = 0.025 + 0.5 * u(rng);  // lambda in [0, 0.05]
    const ReturnMap ref = return_map(f);
    (ref.scale < 1 ? yielding : elastic) += 1;
    const auto forces = f.forces(law().damaged);
    EXPECT_LE(max_diff(forces, ref.forces), 1e-12 * max_abs(ref.forces)) << "seed " << seed;
    const auto [history, particle_history] = f.update(law().damaged);
    EXPECT_LE(max_diff(history, ref.history), 1e-12 * std::max(1e-3, max_abs(ref.history)))
        << "seed " << seed;
    if (hardening()) {
      ASSERT_EQ(particle_history.size(), 1u);
      EXPECT_NEAR(particle_history[0], ref.equivalent_plastic_strain, 1e-12 * ref.equivalent_plastic_strain)
          << "seed " << seed;
    }
    std::vector<double> out(static_cast<std::size_t>(law().n_outputs));
    law().damaged.outputs(f.view(), out.data());
    for (int i = 0; i < law().n_outputs; ++i)
      if (std::string(law().output_names[i]) == "yielding") {
        EXPECT_EQ(out[i], ref.on_or_beyond_yield ? 1.0 : 0.0);
      }
  }
  EXPECT_GT(yielding, 0);
  EXPECT_GT(elastic, 0);
}

TEST_P(PlasticLaw, AnElasticStepLeavesTheHistoryUnchangedToTheBit) {
  TestFamily f = family(3, 10.0);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-0.05, 0.05);
  for (double& h : f.history) h = u(rng);
  if (hardening()) f.particle_history[0] = 0.3;
  ASSERT_EQ(return_map(f).scale, 1.0);
  const auto [history, particle_history] = f.update(law().damaged);
  for (std::size_t k = 0; k < history.size(); ++k) EXPECT_EQ(history[k], f.history[k]) << "bond " << k;
  EXPECT_EQ(particle_history, f.particle_history);
}

// Load past yield from a virgin state, commit, then: unload elastically, unload far
// enough to yield in reverse, and reload past the committed state. The tangent is checked
// with the committed history fixed (the incremental residual), in each state.
TEST_P(PlasticLaw, AlgorithmicTangentMatchesDifferencesOnYieldingAndUnloadingStates) {
  TestFamily f = family(5, 0.01);
  pd::test::check_tangent_along_a_reversal(law(), f, [](const TestFamily& g) { return return_map(g).scale; });
}

// The plastic work of each step, sum over bonds of V0 V t_d (e_p,n+1 - e_p,n), is never
// negative over a random load path of loading, unloading and reversal.
TEST_P(PlasticLaw, DissipationIsNeverNegativeOverARandomPath) {
  TestFamily f = family(7, 0.01);
  const std::vector<double> y_ref = f.y;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  double total = 0;
  int plastic_steps = 0;
  for (int step = 0; step < 30; ++step) {
    scale_deformation(f, y_ref, u(rng));
    const ReturnMap ref = return_map(f);
    const auto updated = f.updated_history(law().damaged);
    double work = 0, scale = 0;
    for (int k = 0; k < f.bonds(); ++k) {
      const double dw = f.V0 * f.V[k] * ref.deviatoric_force[k] * (updated[k] - f.history[k]);
      work += dw;
      scale += std::fabs(dw);
    }
    EXPECT_GE(work, -1e-14 * scale) << "step " << step;
    total += work;
    plastic_steps += ref.scale < 1;
    f.commit_update(law().damaged);
  }
  EXPECT_GT(plastic_steps, 5);
  EXPECT_GT(total, 0.0);
}

std::vector<pd::test::HistoryCase> cases() {
  std::vector<pd::test::HistoryCase> out;
  for (const char* law : {"elastic_plastic_plane_strain", "elastic_plastic_3d",
                          "elastic_plastic_hardening_plane_strain", "elastic_plastic_hardening_3d"})
    for (Truncation t : {Truncation::Interior, Truncation::Corner})
      for (bool broken : {false, true}) out.push_back({law, t, broken});
  return out;
}
INSTANTIATE_TEST_SUITE_P(ElasticPlastic, PlasticLaw, testing::ValuesIn(cases()), pd::test::history_case_name);

// With H = 0 the hardening law is Mitchell's perfectly plastic law: the same forces and plastic
// extensions on a yielding step, whatever the equivalent plastic strain it carries.
TEST(HardeningLaw, WithoutHardeningItIsThePerfectlyPlasticLaw) {
  for (int dim : {2, 3}) {
    const std::string suffix = dim == 2 ? "plane_strain" : "3d";
    const auto* plastic = pd::abi::find_law("elastic_plastic_" + suffix);
    const auto* hardening = pd::abi::find_law("elastic_plastic_hardening_" + suffix);
    ASSERT_NE(plastic, nullptr);
    ASSERT_NE(hardening, nullptr);
    FamilyOptions o;
    o.dim = dim;
    o.seed = 11;
    TestFamily a = pd::verify::make_family(*plastic, o);
    a.params[2] = 0.01;  // sigma_y low enough to yield
    // The same family under the hardening law: its parameters with H = 0, and a lambda.
    TestFamily b = a;
    b.law = hardening;
    b.params.push_back(0.0);
    b.particle_history = {0.7};
    b.update_moments(hardening->damaged);
    ASSERT_LT(return_map(a).scale, 1.0) << "the step must yield";
    const auto fa = a.forces(plastic->damaged), fb = b.forces(hardening->damaged);
    EXPECT_LE(max_diff(fa, fb), 1e-13 * max_abs(fa)) << suffix;
    const auto ha = a.updated_history(plastic->damaged), hb = b.updated_history(hardening->damaged);
    EXPECT_LE(max_diff(ha, hb), 1e-13 * max_abs(ha)) << suffix;
  }
}

// Hardening raises the yield stress: the same yielding step, with H > 0, ends with a larger
// deviatoric force (scale), a smaller plastic extension and a positive lambda increment.
TEST(HardeningLaw, HardeningStiffensAYieldingStep) {
  const auto* law = pd::abi::find_law("elastic_plastic_hardening_3d");
  ASSERT_NE(law, nullptr);
  FamilyOptions o;
  o.dim = 3;
  o.seed = 13;
  TestFamily soft = pd::verify::make_family(*law, o), hard = soft;
  soft.params[2] = hard.params[2] = 0.01;  // sigma_y low enough to yield
  soft.params[3] = 0.0;
  hard.params[3] = 0.5;
  const ReturnMap s = return_map(soft), h = return_map(hard);
  ASSERT_LT(s.scale, 1.0);
  EXPECT_GT(h.scale, s.scale);
  const auto [ep_soft, lambda_soft] = soft.update(law->damaged);
  const auto [ep_hard, lambda_hard] = hard.update(law->damaged);
  EXPECT_LT(max_abs(ep_hard), max_abs(ep_soft));
  EXPECT_GT(lambda_hard[0], 0.0);
  EXPECT_LT(lambda_hard[0], lambda_soft[0]);
}

// Every law that declares history has an update kernel in both variants, names and
// initial values for each variable; a law without history has none.
TEST(LawHistory, TheDescriptorDescribesTheHistory) {
  int with_history = 0;
  for (const pd::abi::LawDescriptor& law : pd::abi::all_laws()) {
    if (!pd::abi::has_history(law)) {
      EXPECT_EQ(law.damaged.update, nullptr) << law.name;
      EXPECT_EQ(law.intact.update, nullptr) << law.name;
      continue;
    }
    ++with_history;
    EXPECT_NE(law.damaged.update, nullptr) << law.name;
    EXPECT_NE(law.intact.update, nullptr) << law.name;
    for (int i = 0; i < law.n_history; ++i) {
      EXPECT_NE(law.history_names[i], nullptr) << law.name;
      EXPECT_TRUE(std::isfinite(law.history_initial[i])) << law.name;
    }
    for (int i = 0; i < law.n_particle_history; ++i) {
      EXPECT_NE(law.particle_history_names[i], nullptr) << law.name;
      EXPECT_TRUE(std::isfinite(law.particle_history_initial[i])) << law.name;
    }
  }
  EXPECT_GE(with_history, 2);
}

}  // namespace

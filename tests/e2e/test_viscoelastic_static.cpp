// A rate-dependent law in the static driver (issue 29): Mitchell's viscoelastic law solved
// along a load path in physical time (solver.duration). The limits are exact, whatever the
// field does during a hold: a ramp far faster than tau_b meets the instantaneous (unrelaxed)
// body, Mitchell's elastic part with G; a long hold ends on the relaxed body, the same
// elastic law with the deviatoric modulus G (1 - lambda_i) and the same dilatation modulus
// (in plane strain kappa = K + G / 3 holds the glassy G: only the deviatoric arm relaxes, so
// the relaxed K is K + lambda_i G / 3). Between them the hold relaxes the reaction with time,
// and the answer converges as the hold is cut into more steps.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "input/scene.hpp"
#include "kernel_abi.hpp"
#include "relative_difference.hpp"
#include "right_reaction.hpp"
#include "run/simulation.hpp"

namespace {
constexpr double kBulk = 200.0 / 1.2, kShear = 200.0 / 2.6;  // E = 200, nu = 0.3
constexpr double kLambda = 0.6, kTau = 1.0;

// A bar pulled at its right end and held; lateral faces free, so the field changes as the
// deviatoric arm relaxes (the effective Poisson ratio moves).
const char* kBar = R"(dimension: 2
domain:
  box: {min: [0, 0], max: [4, 1]}
  count: 24
horizon: {ratio: 3.0}
law: viscoelastic_plane_strain
materials: [{E: 200, nu: 0.3, parameters: {lambda_i: 0.6, tau_b: 1.0}}]
boundary:
  - region: {side: left}
    fixed: [x, y]
  - region: {side: right}
    displacement: {x: 0.01}
solver: {tolerance: 1e-12, increment_tolerance: 0, duration: 1}
)";

using pd::test::right_reaction;

struct Answer {
  double reaction = 0;
  std::vector<double> u;
  double back_strain = 0;  // the largest of the law's output back_strain (0 for other laws)
};

Answer solve(pd::Scene s) {
  pd::Simulation sim(s, [](const std::string&) {});
  const pd::RunSummary r = sim.run(false);
  EXPECT_TRUE(r.newton.converged) << r.newton.message;
  Answer a{right_reaction(sim), sim.displacement(), 0.0};
  const pd::abi::LawDescriptor& law = *pd::abi::find_law(s.law);
  const std::vector<double> out = sim.assembler().particle_outputs(sim.displacement().data());
  for (int i = 0; i < law.n_outputs; ++i)
    if (std::string(law.output_names[i]) == "back_strain")
      for (std::size_t p = static_cast<std::size_t>(i); p < out.size();
           p += static_cast<std::size_t>(law.n_outputs))
        a.back_strain = std::max(a.back_strain, out[p]);
  return a;
}

// The ramp in one step of ramp_time, then `holds` steps sharing hold_time.
Answer ramp_and_hold(double ramp_time, int holds, double hold_time) {
  pd::Scene s = pd::parse_scene(kBar, "bar.yaml");
  s.solver.load_steps = holds + 1;
  s.solver.load_path = {0.0, 1.0};
  for (int k = 0; k < holds; ++k) s.solver.load_path.push_back(1.0);
  // Pseudo-time is evenly spread over the steps: every step lasts duration / load_steps.
  EXPECT_TRUE(holds == 0 || std::fabs(ramp_time - hold_time / holds) <= 1e-15 * ramp_time)
      << "the test builds equal steps only";
  s.solver.duration = ramp_time * (holds + 1);
  return solve(s);
}

// Mitchell's elastic part (the elastic-plastic law far below yield) with deviatoric modulus
// `shear` and the glassy body's dilatation modulus kappa = K + G / 3 (plane strain).
Answer elastic(double shear) {
  const double bulk = kBulk + (kShear - shear) / 3;
  pd::Scene s = pd::parse_scene(kBar, "bar.yaml");
  s.law = "elastic_plastic_plane_strain";
  s.solver.duration = 0;
  s.materials[0].parameters = {{"K", bulk}, {"G", shear}, {"sigma_y", 1e9}};
  return solve(s);
}

using pd::test::relative_difference;
}  // namespace

TEST(ViscoelasticStatic, AFastRampMeetsTheUnrelaxedBody) {
  // One step of 1e-9 tau: beta ~ dt / (2 tau) = 5e-10, so the viscous arm has not moved.
  const Answer fast = ramp_and_hold(1e-9 * kTau, 0, 0);
  const Answer unrelaxed = elastic(kShear);
  EXPECT_LT(relative_difference(fast.u, unrelaxed.u), 1e-8);
  EXPECT_NEAR(fast.reaction, unrelaxed.reaction, 1e-8 * unrelaxed.reaction);
  // The output back_strain: the viscous arm has barely moved (beta ~ 5e-10 of the strain).
  EXPECT_LT(fast.back_strain, 1e-8 * 0.01 / 4);
}

TEST(ViscoelasticStatic, ALongHoldEndsOnTheRelaxedBody) {
  // Steps of 1e4 tau: each hold step takes what the field moved in the step before down by
  // about tau / dt, so three of them leave ~1e-12 of the relaxation undone.
  const Answer held = ramp_and_hold(1e4 * kTau, 3, 3e4 * kTau);
  const Answer relaxed = elastic(kShear * (1 - kLambda));
  const Answer unrelaxed = elastic(kShear);
  ASSERT_LT(relaxed.reaction, 0.95 * unrelaxed.reaction) << "the test needs a visible relaxation";
  EXPECT_LT(relative_difference(held.u, relaxed.u), 1e-9);
  EXPECT_NEAR(held.reaction, relaxed.reaction, 1e-9 * relaxed.reaction);
  // Relaxed, the back extension is the deviatoric extension: a back strain of the order of
  // the bar's strain 0.01 / 4 (its deviatoric part, concentrated at the held ends).
  EXPECT_GT(held.back_strain, 0.1 * 0.01 / 4);
  EXPECT_LT(held.back_strain, 10 * 0.01 / 4);
}

// What the run reports is the state Newton converged on: read after the last commit, the
// internal forces on the free components are still in balance. (Read at the last step's
// duration, the committed back extension would relax one step more and unbalance them.)
TEST(ViscoelasticStatic, TheReportedStateIsTheConvergedOne) {
  pd::Scene s = pd::parse_scene(kBar, "bar.yaml");
  s.solver.load_steps = 2;
  s.solver.load_path = {0.0, 1.0, 1.0};
  s.solver.duration = 2 * kTau;  // a ramp over tau, a hold of tau
  pd::Simulation sim(s, [](const std::string&) {});
  ASSERT_TRUE(sim.run(false).newton.converged);
  const pd::Particles& P = sim.particles();
  std::vector<double> f(static_cast<std::size_t>(P.size() * P.dim));
  sim.assembler().assemble(sim.displacement().data(), f.data(), nullptr);
  double free_force = 0, x_max = -1e300;
  for (int p = 0; p < P.size(); ++p) x_max = std::max(x_max, P.x[static_cast<std::size_t>(p * P.dim)]);
  for (int p = 0; p < P.size(); ++p) {
    const double x = P.x[static_cast<std::size_t>(p * P.dim)];
    const bool left = x<0.1, right = x> x_max - 1e-9;
    for (int c = 0; c < 2; ++c)
      if (!left && !(right && c == 0))
        free_force = std::max(free_force, std::fabs(f[static_cast<std::size_t>(p * P.dim + c)]));
  }
  EXPECT_LT(free_force, 1e-9 * right_reaction(sim));
}

// Under a held end the lateral faces still move, so the body's relaxation times lie between
// tau and tau / (1 - lambda_i) = 2.5 tau (the creep time): 30 tau leaves at most exp(-12).
TEST(ViscoelasticStatic, AHoldRelaxesTheReactionWithTime) {
  const double unrelaxed = elastic(kShear).reaction, relaxed = elastic(kShear * (1 - kLambda)).reaction;
  double before = unrelaxed;
  for (double hold : {0.1, 0.5, 2.0, 30.0}) {
    // 64 equal steps: the ramp in the first, the hold in the other 63.
    pd::Scene s = pd::parse_scene(kBar, "bar.yaml");
    s.solver.load_steps = 64;
    s.solver.load_path.assign(65, 1.0);
    s.solver.load_path[0] = 0.0;
    s.solver.duration = hold * 64.0 / 63.0;
    const double reaction = solve(s).reaction;
    EXPECT_LT(reaction, before) << "hold " << hold;
    EXPECT_GT(reaction, relaxed) << "hold " << hold;
    before = reaction;
  }
  EXPECT_LT(before - relaxed, 1e-3 * (unrelaxed - relaxed)) << "30 tau relaxes all but exp(-12)";
}

// `body_force: {field: ...}` end to end (effects/body_force_field.cpp): paper 001's
// manufactured u2 imposed on a one-horizon Dirichlet layer of the perturbed unit square,
// its body force b = -div sigma on every particle, OBQ quadrature. The static run must
// give the same interior solution as the hand-written reduced solve of
// run/manufactured_solve.cpp (an independent path to the same discrete problem) and
// converge to the analytic u2 at second order.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "fields/manufactured.hpp"
#include "input/scene.hpp"
#include "run/manufactured_solve.hpp"
#include "run/simulation.hpp"

namespace {
// Paper 001 §4 at lambda = mu = 1/2 (E = 1.25, nu = 0.25): n per side, delta = 3.5 h.
std::string u2_scene(int n, const std::string& body_force) {
  const double layer = 3.5 / n;
  return "dimension: 2\n"
         "domain:\n"
         "  box: {min: [0, 0], max: [1, 1]}\n"
         "  count: " +
         std::to_string(n) +
         "\n"
         "  quadrature: obq\n"
         "  perturbation: {amplitude: 0.2, seed: 1}\n"
         "horizon: {ratio: 3.5}\n"
         "law: lps_plane_strain\n"
         "influence: inv\n"
         "materials:\n"
         "  - {E: 1.25, nu: 0.25}\n"
         "boundary:\n"
         "  - region: {outside: {min: [" +
         std::to_string(layer) + ", " + std::to_string(layer) + "], max: [" + std::to_string(1 - layer) +
         ", " + std::to_string(1 - layer) +
         "]}}\n"
         "    field: {solution: u2}\n" +
         body_force +
         "reference: {solution: u2}\n"
         "solver: {tolerance: 1.0e-13}\n";
}

struct Interior {
  double rms = 0;
  int particles = 0;
};

// The RMS error of paper 001 §4 over the particles inside the layer (the solved ones).
// `summary` (optional) gets the run's summary.
Interior interior_error(int n, const std::string& scene_text, double amplitude = 1,
                        pd::RunSummary* summary = nullptr) {
  pd::Simulation sim(pd::parse_scene(scene_text, "u2.yaml"), [](const std::string&) {});
  const pd::RunSummary s = sim.run(false);
  EXPECT_TRUE(s.newton.converged) << s.newton.message;
  if (summary) *summary = s;
  const double layer = 3.5 / n;
  const pd::ManufacturedField u2 = pd::paper001_u2();
  Interior out;
  double sum = 0;
  const pd::Particles& p = sim.particles();
  for (int i = 0; i < p.size(); ++i) {
    const double* x = p.position(i);
    if (x[0] < layer || x[0] > 1 - layer || x[1] < layer || x[1] > 1 - layer) continue;
    const auto exact = u2.displacement(x[0], x[1]);
    for (int c = 0; c < 2; ++c) sum += std::pow(sim.displacement()[2 * i + c] - amplitude * exact[c], 2);
    ++out.particles;
  }
  out.rms = std::sqrt(sum / out.particles);
  return out;
}
}  // namespace

TEST(BodyForceField, StaticU2SceneMatchesTheReducedSolveAndConverges) {
  const std::string bf = "body_force: {field: {solution: u2}}\n";
  const Interior coarse = interior_error(24, u2_scene(24, bf)), fine = interior_error(32, u2_scene(32, bf));
  pd::ManufacturedSetup setup;  // the same cloud, law, influence, layer and lambda = mu = 1/2
  setup.n = 24;
  const pd::ManufacturedResult reduced = pd::solve_manufactured(pd::paper001_u2(), setup);
  EXPECT_EQ(coarse.particles, reduced.solved);
  EXPECT_NEAR(coarse.rms, reduced.rms_error, 1e-6 * reduced.rms_error);
  const double order = std::log(coarse.rms / fine.rms) / std::log(32.0 / 24.0);
  EXPECT_GT(order, 1.5) << coarse.rms << " -> " << fine.rms;
  EXPECT_LT(fine.rms, 1e-4);
}

TEST(BodyForceField, WithoutTheBodyForceTheInteriorMissesU2) {
  // The control: the layer alone does not give u2 inside (b is what makes it an equilibrium).
  EXPECT_GT(interior_error(24, u2_scene(24, "")).rms, 1e-2);
}

TEST(BodyForceField, AmplitudeScalesTheFieldAndItsBodyForce) {
  const std::string bf = "body_force: {field: {solution: u2, amplitude: 0.001}}\n";
  std::string scene = u2_scene(24, bf);
  for (const std::string from : {"field: {solution: u2}\n", "reference: {solution: u2}\n"}) {
    const std::string to = from.substr(0, from.size() - 2) + ", amplitude: 0.001}\n";
    scene.replace(scene.find(from), from.size(), to);
  }
  pd::RunSummary s;
  const Interior small = interior_error(24, scene, 0.001, &s);
  // The law is linear: the error scales with the amplitude.
  const pd::ManufacturedResult reduced = pd::solve_manufactured(pd::paper001_u2(), pd::ManufacturedSetup{});
  EXPECT_NEAR(small.rms, 0.001 * reduced.rms_error, 1e-6 * 0.001 * reduced.rms_error);
  bool described = false;
  for (const std::string& e : s.effects)
    described = described || e.find("body force density of field u2") != std::string::npos;
  EXPECT_TRUE(described);
}

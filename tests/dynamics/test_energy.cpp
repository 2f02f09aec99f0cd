// Undamped explicit dynamics conserves energy: velocity Verlet is symplectic, so the
// total E = kinetic + strain - external work oscillates at O(dt^2) without drifting.
// A small free body (12 x 12 particles, Silling's law) released from a Gaussian bump
// of displacement; 10,000 steps at 0.8 of the Gershgorin stable step.
//
// The stated bound, derived for the linearised system (the strains here are 1e-3): per
// mode of frequency w, velocity Verlet conserves exactly H~ = v^2 / (2 (1 - a)) +
// w^2 x^2 / 2 with a = (w dt / 2)^2, so E = v^2/2 + w^2 x^2/2 stays in [(1 - a) H~, H~]
// and |E_n - E_0| / E_0 <= a / (1 - a). The Gershgorin estimate bounds w dt / 2 by the
// safety factor s, so |E_n - E_0| / E_0 <= s^2 / (1 - s^2) for every mix of modes:
// 1.78 at s = 0.8, 0.19 at s = 0.4. The measured error is far below (most of the energy
// is in slow modes); the sharper checks are the O(dt^2) ratio and the absence of drift.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "input/scene.hpp"
#include "run/dynamic_simulation.hpp"

namespace {
const char* kScene = R"(
dimension: 2
domain: {box: {min: [0, 0], max: [1.2, 1.2]}, spacing: 0.1}
horizon: {ratio: 3.0}
law: silling_plane_strain
influence: const
materials: [{E: 1.0, nu: 0.25, density: 1.0}]
dynamics:
  method: explicit
  steps: 10000
  safety_factor: 0.8
  output_every: 10
  threads: 1
  initial:
    - region: {all: true}
      displacement: [0.001, 0.0005]
      gaussian: {axis: x, center: 0.6, width: 0.2}
output: {directory: out/energy_test}
)";

// max_n |E_n - E_0| / E_0 over the series, and the drift: the mean of E over the last
// tenth minus the mean over the first tenth, relative to E_0.
struct EnergyError {
  double max_error = 0, drift = 0;
  int rows = 0;
};

EnergyError run(double safety, int steps) {
  pd::Scene s = pd::parse_scene(kScene, "energy.yaml");
  s.dynamics->safety_factor = safety;
  s.dynamics->steps = steps;
  pd::DynamicSimulation sim(s, [](const std::string&) {});
  const pd::RunSummary r = sim.run(false);
  EXPECT_TRUE(r.dynamics->strain_available);
  const auto& rows = sim.series();
  EnergyError e;
  e.rows = static_cast<int>(rows.size());
  const double e0 = rows.front().kinetic + rows.front().strain - rows.front().external_work;
  EXPECT_GT(e0, 0.0);
  const std::size_t tenth = rows.size() / 10;
  double first = 0, last = 0;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const double en = rows[i].kinetic + rows[i].strain - rows[i].external_work;
    e.max_error = std::max(e.max_error, std::fabs(en - e0) / e0);
    if (i < tenth) first += en / static_cast<double>(tenth);
    if (i >= rows.size() - tenth) last += en / static_cast<double>(tenth);
  }
  e.drift = (last - first) / e0;
  return e;
}
}  // namespace

TEST(Energy, UndampedVerletConservesEnergyOver10000Steps) {
  const EnergyError coarse = run(0.8, 10000);
  EXPECT_EQ(coarse.rows, 1001);
  const auto bound = [](double s) { return s * s / (1 - s * s); };
  EXPECT_LT(coarse.max_error, bound(0.8)) << coarse.max_error;
  // No secular drift: the mean energy of the last tenth of the run differs from that of
  // the first tenth by less than a tenth of the oscillation amplitude.
  EXPECT_LT(std::fabs(coarse.drift), 0.1 * coarse.max_error) << coarse.drift << " " << coarse.max_error;
  // Second order: halving dt (same simulated time) divides the error by about 4.
  const EnergyError fine = run(0.4, 20000);
  std::printf(
      "energy error over 10,000 steps at s = 0.8: max %.3e drift %.3e; at s = 0.4 (20,000 steps): max %.3e\n",
      coarse.max_error, coarse.drift, fine.max_error);
  EXPECT_LT(fine.max_error, bound(0.4)) << fine.max_error;
  EXPECT_LT(std::fabs(fine.drift), 0.1 * fine.max_error) << fine.drift << " " << fine.max_error;
  const double ratio = coarse.max_error / fine.max_error;
  EXPECT_GT(ratio, 3.0) << coarse.max_error << " " << fine.max_error;
  EXPECT_LT(ratio, 5.0) << coarse.max_error << " " << fine.max_error;
}

// The 3D cube in uniaxial tension converges to T/E with the directional surface
// correction (scenes/cube_tension_corrected.yaml; docs/paper003.md "The 3D cube"): the
// gauge strain between the cross-sections at z = 1/4 and 3/4 against the continuum's
// T/E, at count 10 (1000 particles; the docs' count 14 gives 0.986).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "input/scene.hpp"
#include "run/simulation.hpp"

namespace {
constexpr double kStrain = 0.1 / 200;  // T / E

// The gauge strain over T/E at count 10, with the scene's correction or none.
double gauge_strain(bool corrected) {
  pd::Scene s = pd::read_scene(std::string(PD_SOURCE_DIR) + "/scenes/cube_tension_corrected.yaml");
  s.h = 0.1;  // cell centres (i + 1/2)/10: the sections at 0.25 and 0.75 stay in the probes' slabs
  s.surface_correction = corrected;
  pd::Simulation sim(s, [](const std::string&) {});
  const pd::RunSummary r = sim.run(false);
  EXPECT_TRUE(r.newton.converged);
  EXPECT_EQ(r.probes.at(1).particles, 100);  // one whole cross-section each
  EXPECT_EQ(r.probes.at(2).particles, 100);
  return (r.probes.at(2).value - r.probes.at(1).value) / 0.5 / kStrain;
}
}  // namespace

TEST(CubeSurfaceCorrection, GaugeStrainComesWithinThreePercentOfTheContinuum) {
  const double off = gauge_strain(false), on = gauge_strain(true);
  // Measured: 0.902 without, 0.976 with. The cut families at the free faces are too stiff
  // under uniaxial stress; the correction must take out most of it, not overshoot.
  EXPECT_NEAR(on, 1.0, 0.03);
  EXPECT_LT(std::fabs(1 - on), std::fabs(1 - off) / 3);
  EXPECT_LT(off, 0.95);  // the skin's error is there to correct
}

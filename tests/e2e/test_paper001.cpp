// `domain.quadrature: obq` end to end (scenes/paper001_linear_patch.yaml): on paper 001's
// perturbed cloud the linear patch test is reproduced to rounding, the run takes the
// non-symmetric solver, and the volume quadrature of the same scene misses the field.
#include <gtest/gtest.h>

#include <string>

#include "input/scene.hpp"
#include "run/simulation.hpp"

namespace {
pd::RunSummary run_patch(pd::Quadrature q) {
  pd::Scene s = pd::read_scene(std::string(PD_SOURCE_DIR) + "/scenes/paper001_linear_patch.yaml");
  s.quadrature = q;
  pd::Simulation sim(s, [](const std::string&) {});
  return sim.run(false);
}
}  // namespace

TEST(Paper001Scene, ObqReproducesALinearFieldOnAPerturbedCloud) {
  const pd::RunSummary obq = run_patch(pd::Quadrature::Obq);
  ASSERT_TRUE(obq.newton.converged) << obq.newton.message;
  ASSERT_TRUE(obq.has_field_error);
  EXPECT_LT(obq.field_error, 1e-24);  // eq. (48) is a squared relative error: 1e-12 in u
  EXPECT_EQ(obq.newton.linear_solver, "umfpack");
  bool described = false;
  for (const std::string& e : obq.effects) described = described || e.rfind("quadrature: obq", 0) == 0;
  EXPECT_TRUE(described);

  const pd::RunSummary volume = run_patch(pd::Quadrature::Volume);
  EXPECT_GT(volume.field_error, 1e-8);
  EXPECT_EQ(volume.newton.linear_solver, "cholmod");
}

TEST(Paper001Scene, QuadratureKeyAcceptsObq) {
  EXPECT_EQ(pd::parse_quadrature("obq"), pd::Quadrature::Obq);
  EXPECT_EQ(pd::quadrature_name(pd::Quadrature::Obq), "obq");
}

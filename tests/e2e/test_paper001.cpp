// `domain.quadrature: obq` end to end (scenes/paper001_linear_patch.yaml): on paper 001's
// perturbed cloud the linear patch test is reproduced to rounding, the run takes the
// non-symmetric solver, and the volume quadrature of the same scene misses the field.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
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

namespace {
// Paper 000's constant-strain block `problem` (studies/constant_strain_obq/) with n
// particles along a side, Silling's law, cubic influence, delta = 3.5 h, the law's
// reproducing space: the largest probe error (biaxial has two probes).
double block_error(const std::string& problem, int n, bool symmetric) {
  pd::Scene s = pd::read_scene(std::string(PD_SOURCE_DIR) + "/studies/constant_strain_obq/" + problem + "_cut_law.yaml");
  s.h = (s.hi[0] - s.lo[0]) / n;
  s.horizon_ratio = 3.5;
  s.obq_symmetric = symmetric;
  pd::Simulation sim(s, [](const std::string&) {});
  const pd::RunSummary r = sim.run(false);
  EXPECT_TRUE(r.newton.converged) << problem << " n " << n;
  EXPECT_FALSE(r.probes.empty());
  double worst = 0;
  for (const pd::ProbeResult& p : r.probes) worst = std::max(worst, p.error);
  return r.probes.empty() ? 1.0 : worst;
}
}  // namespace

TEST(Paper001Scene, SymmetricPairWeightsMakeSillingConvergeOnTheConstantStrainBlocks) {
  // The law's space with momentum-conserving pair weights (domain.obq_symmetric): order
  // >= 0.9 from n = 10 to 20 on each block (measured 0.92, 0.93, 0.92; 0.98 by n = 40-80,
  // docs/paper001.md). Plain collocation falls faster here (1.12-1.17) but is not
  // asymptotic: by n = 160 its error grows, since its loaded face carries 0.9717 T.
  for (const char* problem : {"uniaxial", "biaxial", "shear"}) {
    const double coarse = block_error(problem, 10, true), fine = block_error(problem, 20, true);
    EXPECT_GT(std::log2(coarse / fine), 0.9) << problem << ": " << coarse << " -> " << fine;
  }
}

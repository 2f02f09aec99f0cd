// `domain.quadrature: obq` end to end (scenes/paper001_linear_patch.yaml): on paper 001's
// perturbed cloud the linear patch test is reproduced to rounding, the run takes the
// non-symmetric solver, and the volume quadrature of the same scene misses the field.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "fields/analytic.hpp"
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
  EXPECT_EQ(pd::parse_name<pd::Quadrature>("obq"), pd::Quadrature::Obq);
  EXPECT_EQ(pd::name_of(pd::Quadrature::Obq), "obq");
}

namespace {
// Paper 000's constant-strain block `problem` (studies/constant_strain_obq/) with n
// particles along a side, Silling's law, cubic influence, delta = 3.5 h, the law's
// reproducing space: the largest probe error (biaxial has two probes).
double block_error(const std::string& problem, int n, bool symmetric) {
  pd::Scene s = pd::read_scene(std::string(PD_SOURCE_DIR) + "/studies/constant_strain_obq/" + problem +
                               "_cut_law.yaml");
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

TEST(Paper001Scene, SymmetricPairWeightsTakeTheCholeskyPathAndPlainCollocationDoesNot) {
  // domain.obq_symmetric makes the stiffness symmetric (tests/runtime/test_collocation.cpp),
  // so `auto` factorises it with CHOLMOD; the answer is UMFPACK's on the same system.
  // Paper 000's uniaxial block, Silling, the law's space, n = 20, delta = 3.5 h.
  pd::Scene s =
      pd::read_scene(std::string(PD_SOURCE_DIR) + "/studies/constant_strain_obq/uniaxial_cut_law_sym.yaml");
  s.horizon_ratio = 3.5;
  pd::Simulation sym(s, [](const std::string&) {});
  const pd::RunSummary r = sym.run(false);
  ASSERT_TRUE(r.newton.converged) << r.newton.message;
  EXPECT_EQ(r.newton.linear_solver, "cholmod");
  EXPECT_EQ(r.newton.linear_choice.find("fell back"), std::string::npos) << r.newton.linear_choice;
  s.solver.linear = pd::LinearMethod::umfpack;
  pd::Simulation lu(s, [](const std::string&) {});
  EXPECT_EQ(lu.run(false).newton.linear_solver, "umfpack");
  double diff = 0, size = 0;
  for (std::size_t i = 0; i < sym.displacement().size(); ++i) {
    diff = std::max(diff, std::abs(sym.displacement()[i] - lu.displacement()[i]));
    size = std::max(size, std::abs(lu.displacement()[i]));
  }
  EXPECT_LT(diff, 1e-10 * size);
  // Plain collocation on the same scene: the non-symmetric path.
  s.obq_symmetric = false;
  s.solver.linear = pd::LinearMethod::automatic;
  pd::Simulation plain(s, [](const std::string&) {});
  EXPECT_EQ(plain.run(false).newton.linear_solver, "umfpack");
}

TEST(Paper001Scene, SymmetricPaper001WeightsOnAPerturbedCloudAreIndefiniteAndFallBackToUmfpack) {
  // Symmetric is not positive definite: with paper 001's space and `obq` (the families at
  // the faces extrapolate to the whole ball) CHOLMOD finds this scene's symmetrised
  // stiffness indefinite; the run says so and solves with UMFPACK (docs/paper001.md).
  pd::Scene s = pd::read_scene(std::string(PD_SOURCE_DIR) + "/scenes/paper001_linear_patch.yaml");
  s.obq_symmetric = true;
  pd::Simulation sim(s, [](const std::string&) {});
  const pd::RunSummary r = sim.run(false);
  ASSERT_TRUE(r.newton.converged) << r.newton.message;
  EXPECT_EQ(r.newton.linear_solver, "umfpack");
  EXPECT_NE(r.newton.linear_choice.find("fell back to umfpack"), std::string::npos) << r.newton.linear_choice;
}

TEST(Paper001Scene, RmsErrorOverTheFreeParticlesMatchesEquation48) {
  // The §4 RMS over the particles off the collar and eq. (48) over all particles see the
  // same errors (the collar's are exactly zero): eq48 * sum_all |u_ex|^2 = rms^2 * N_free.
  pd::Scene s = pd::read_scene(std::string(PD_SOURCE_DIR) + "/scenes/paper001_linear_patch.yaml");
  s.quadrature = pd::Quadrature::Volume;  // a visible error
  pd::Simulation sim(s, [](const std::string&) {});
  const pd::RunSummary r = sim.run(false);
  ASSERT_TRUE(r.has_field_error);
  const pd::AnalyticField field(*s.reference, s.materials[0].elastic);
  const pd::Particles& P = sim.particles();
  double norm = 0;
  for (int p = 0; p < P.size(); ++p) {
    const auto u = field.displacement(P.position(p));
    norm += u[0] * u[0] + u[1] * u[1];
  }
  EXPECT_GT(r.rms_particles, 0);
  EXPECT_LT(r.rms_particles, P.size());
  EXPECT_GT(r.rms_error, 0.0);
  EXPECT_NEAR(r.rms_error * r.rms_error * r.rms_particles, r.field_error * norm,
              1e-12 * r.field_error * norm);
}

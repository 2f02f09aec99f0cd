// The `linear: auto` rule for large problems: the nonzero estimate it decides on is
// checked against the real pattern, and each branch of the rule is taken when it should.
#include <gtest/gtest.h>

#include "assembly/sparsity_pattern.hpp"
#include "discretize/discretization.hpp"
#include "input/scene.hpp"
#include "solve/solver_plan.hpp"

namespace {
pd::Scene square(double ratio, int count) {
  pd::Scene s;
  s.dim = 2;
  s.lo = {0, 0, 0};
  s.hi = {1, 1, 0};
  s.h = 1.0 / count;
  s.horizon_ratio = ratio;
  s.materials.resize(1);
  return s;
}
}  // namespace

// The estimate must be close enough to decide on: within 35% of the real count (it
// ignores the truncated families at the edges, so it errs high on small grids).
TEST(SolverPath, NonzeroEstimateIsCloseToTheRealPattern) {
  for (double ratio : {1.5, 2.0, 3.0, 3.5}) {
    const pd::Scene s = square(ratio, 60);
    const pd::Particles p = pd::discretize(s);
    const pd::Bonds b = pd::find_bonds(p, s.delta(), [](double, double) { return 1.0; });
    const double mean_family = static_cast<double>(b.bond_count()) / p.size();
    const auto estimate = static_cast<double>(pd::estimated_tangent_nonzeros(p.size(), mean_family, 2));
    const auto real = static_cast<double>(pd::SparsityPattern(b, 2).nonzeros());
    EXPECT_GT(estimate, 0.95 * real) << "delta/h " << ratio;
    EXPECT_LT(estimate, 1.35 * real) << "delta/h " << ratio;
  }
}

TEST(SolverPath, AutoKeepsSmallProblemsAssembled) {
  pd::SolverSpec spec;
  const pd::SolverPlan path = pd::plan_solver(spec, {2500, 35.0, 2, 3.5});  // 50^2: about 1.4e6 nonzeros
  EXPECT_EQ(path.linear, pd::LinearMethod::automatic);
  EXPECT_NE(path.reason.find("within direct_max_nonzeros"), std::string::npos) << path.reason;
}

TEST(SolverPath, AutoGoesMatrixFreeWithTheShortHorizonAboveTheDirectLimit) {
  pd::SolverSpec spec;
  const pd::SolverPlan path = pd::plan_solver(spec, {160000, 35.7, 2, 3.5});  // the 400^2 crack
  EXPECT_EQ(path.linear, pd::LinearMethod::matrix_free);
  EXPECT_EQ(path.preconditioner, pd::Preconditioner::short_horizon);
  EXPECT_NE(path.reason.find("delta/h = 2"), std::string::npos) << path.reason;
}

TEST(SolverPath, AShortHorizonAlreadyFactorisesTheTangentItself) {
  pd::SolverSpec spec;
  // 200^2 at delta/h = 1.5: the preconditioner's horizon is delta itself.
  const pd::SolverPlan path = pd::plan_solver(spec, {40000, 7.9, 2, 1.5});
  EXPECT_EQ(path.linear, pd::LinearMethod::matrix_free);
  EXPECT_EQ(path.preconditioner, pd::Preconditioner::short_horizon);
  EXPECT_NE(path.reason.find("own factorisation"), std::string::npos) << path.reason;
}

TEST(SolverPath, AutoFallsBackToJacobiWhenThePreconditionerCannotFit) {
  pd::SolverSpec spec;
  // 1000^2 at delta/h = 1.5: even the tangent itself exceeds the limit.
  pd::SolverPlan path = pd::plan_solver(spec, {1000000, 7.9, 2, 1.5});
  EXPECT_EQ(path.linear, pd::LinearMethod::matrix_free);
  EXPECT_EQ(path.preconditioner, pd::Preconditioner::diagonal);
  // 1000^2 at delta/h = 3.5: the delta/h = 2 stiffness alone would exceed the limit.
  path = pd::plan_solver(spec, {1000000, 35.9, 2, 3.5});
  EXPECT_EQ(path.preconditioner, pd::Preconditioner::diagonal);
  EXPECT_NE(path.reason.find("preconditioner_max_nonzeros"), std::string::npos) << path.reason;
}

// Given the preconditioner's counted family (8 at delta = 2h under the cubic influence,
// which is zero on the ring 2h away), the estimate uses it instead of the volume ratio
// (11.7 for a family of 35.9 at delta/h 3.5), and a limit between the two decides.
TEST(SolverPath, ACountedShortFamilyReplacesTheVolumeScaling) {
  pd::SolverSpec spec;
  spec.preconditioner_max_nonzeros = 1.5e8;
  EXPECT_EQ(pd::plan_solver(spec, {1000000, 35.9, 2, 3.5}).preconditioner,
            pd::Preconditioner::diagonal);  // about 1.9e8
  const pd::SolverPlan path = pd::plan_solver(spec, {1000000, 35.9, 2, 3.5, 8.0});
  EXPECT_EQ(path.preconditioner, pd::Preconditioner::short_horizon);
  EXPECT_NE(path.reason.find("1.32e+08"), std::string::npos) << path.reason;  // 1e6 x (4 x 8 + 1) x 4
}

TEST(SolverPath, ExplicitChoicesAreKept) {
  pd::SolverSpec spec;
  spec.linear = pd::LinearMethod::cholmod;
  EXPECT_EQ(pd::plan_solver(spec, {1000000, 35.9, 2, 3.5}).linear, pd::LinearMethod::cholmod);
  spec.linear = pd::LinearMethod::automatic;
  spec.preconditioner = pd::Preconditioner::ic;  // names an assembled Krylov method
  const pd::SolverPlan path = pd::plan_solver(spec, {1000000, 35.9, 2, 3.5});
  EXPECT_EQ(path.linear, pd::LinearMethod::automatic);
  EXPECT_EQ(path.preconditioner, pd::Preconditioner::ic);
}

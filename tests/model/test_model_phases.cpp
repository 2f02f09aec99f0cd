// The model is built in two phases by one constructor (model/model.hpp): the body, then
// what the plan asks for and the effects. Checked here: the planner sees the finished
// body once, before any assembler exists; the plan's matrix, threads and short horizon are
// what the model builds (and nothing it does not ask for); the effects are there without a
// later step; a static run's model is what its solver plan asks for.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "input/scene.hpp"
#include "model/model.hpp"
#include "run/static_run.hpp"

namespace {
// A 20 x 10 plate with a pre-crack: the left side held, a traction on the right.
std::string plate(const std::string& solver) {
  return "dimension: 2\n"
         "domain: {box: {min: [0, 0], max: [0.2, 0.1]}, spacing: 0.01}\n"
         "horizon: {ratio: 3.0}\n"
         "law: oterkus_plane_strain\n"
         "influence: const\n"
         "materials: [{name: m, E: 1.0, nu: 0.25}]\n"
         "boundary:\n"
         "  - region: {side: left}\n"
         "    fixed: [x, y]\n"
         "  - region: {side: right}\n"
         "    traction: [0.001, 0]\n"
         "cracks:\n"
         "  - segment: [[0.095, 0.02], [0.095, 0.08]]\n" +
         solver;
}

TEST(ModelPhases, ThePlannerSeesTheWholeBodyOnceAndTheModelBuildsWhatItAsks) {
  const pd::Scene scene = pd::parse_scene(plate(""), "plate.yaml");
  int calls = 0;
  long long bonds_seen = 0;
  int particles_seen = 0;
  const double short_delta = 1.5 * scene.h;
  const pd::Model model(scene, [&](const pd::DiscretizedBody& body) {
    ++calls;
    particles_seen = body.particles.size();
    bonds_seen = body.bond_count;
    EXPECT_GT(body.cut_by_cracks, 0);  // the cracks have cut the bonds the plan sizes
    EXPECT_EQ(body.dofs.constrained_count(), 2 * 10);
    return pd::ModelPlan{.matrix = true, .threads = 1, .short_delta = short_delta};
  });
  EXPECT_EQ(calls, 1);
  EXPECT_EQ(particles_seen, 200);
  EXPECT_EQ(bonds_seen, model.bond_count);
  ASSERT_NE(model.assembler, nullptr);
  EXPECT_TRUE(model.assembler_options.matrix);
  EXPECT_EQ(model.assembler_options.threads, 1);
  EXPECT_FALSE(model.assembler->intact());  // a cut bond: the damaged variant
  EXPECT_NO_THROW(model.assembler->pattern());
  // The short horizon: every bond within it (at 1.5 h, a particle's 4 axis and 4 diagonal
  // neighbours in the interior), cut by the same crack.
  ASSERT_NE(model.approximation, nullptr);
  ASSERT_GT(model.short_bonds.bond_count(), 0);
  for (int k = 0; k < model.short_bonds.bond_count(); ++k)
    EXPECT_LE(model.short_bonds.length[k], short_delta * (1 + 1e-12));
  EXPECT_LT(model.short_bonds.bond_count(), model.bonds.bond_count());
  // The effects, in the model from the start: the traction and the pre-cracks.
  std::vector<std::string> names;
  for (const auto& e : model.effects) names.push_back(e->name());
  EXPECT_EQ(names.size(), 2u);
  EXPECT_GT(model.build_seconds, 0.0);
}

TEST(ModelPhases, WithoutAskingThereIsNoMatrixAndNoShortHorizon) {
  const pd::Model model = pd::build_model(pd::parse_scene(plate(""), "plate.yaml"));
  EXPECT_FALSE(model.assembler_options.matrix);
  EXPECT_THROW(model.assembler->pattern(), std::logic_error);
  EXPECT_EQ(model.approximation, nullptr);
  EXPECT_EQ(model.short_bonds.bond_count(), 0);
}

// The static driver plans from the body: a direct solve asks for a matrix and no short
// horizon; matrix-free Newton-Krylov with the short-horizon preconditioner asks for the
// approximation and no matrix.
TEST(ModelPhases, AStaticRunsModelIsWhatItsSolverPlanAsks) {
  {
    const pd::Scene scene = pd::parse_scene(plate("solver: {linear: umfpack}\n"), "direct.yaml");
    pd::StaticRun run;
    const pd::Model model = pd::build_static_model(scene, run);
    EXPECT_FALSE(run.plan.matrix_free());
    EXPECT_TRUE(model.assembler_options.matrix);
    EXPECT_EQ(model.approximation, nullptr);
  }
  {
    const pd::Scene scene =
        pd::parse_scene(plate("solver: {linear: matrix_free, preconditioner: short_horizon}\n"), "free.yaml");
    pd::StaticRun run;
    const pd::Model model = pd::build_static_model(scene, run);
    ASSERT_TRUE(run.plan.matrix_free());
    ASSERT_TRUE(run.plan.short_horizon_preconditioner());
    EXPECT_FALSE(model.assembler_options.matrix);
    ASSERT_NE(model.approximation, nullptr);
    EXPECT_GT(model.short_bonds.bond_count(), 0);
  }
}

}  // namespace

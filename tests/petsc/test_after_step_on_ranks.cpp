// Every effect's after_step runs under the PETSc backend as it does serially (issue 28): an
// effect that only counts its calls and the families it was given is added to a dynamic
// run, serially and over this run's ranks (1, 2 or 3). Each rank must be called once per
// step, as the serial run is, and the ranks' families must together be the body's, once
// each. (The old distributed loops called only critical-stretch damage: an effect added
// beside it was silently skipped under mpirun.)
#include <gtest/gtest.h>
#include <mpi.h>

#include <memory>
#include <string>

#include "effects/effect.hpp"
#include "input/scene.hpp"
#include "model/model.hpp"
#include "run/dynamic_run.hpp"

namespace pd {
namespace {

class AfterStepCounter final : public Effect {
 public:
  explicit AfterStepCounter(int particles) : particles_(particles) {}
  std::string name() const override { return "after-step counter"; }
  std::string describe() const override { return "after-step counter (test)"; }
  long long after_step(const double*, FamilyScope scope) override {
    ++calls;
    families += scope.every_family() ? particles_ : static_cast<long long>(scope.owned->size());
    return 0;
  }
  int calls = 0;
  long long families = 0;

 private:
  int particles_;
};

struct Counted {
  int calls = 0;
  long long families = 0;
  int steps = 0;
};

// Runs `text` on `backend` for at most `stop_after` steps with the counter added.
Counted run_counted(const std::string& text, Backend backend, int stop_after) {
  Scene scene = parse_scene(text, "after_step_counter.yaml");
  scene.solver.backend = backend;
  Model model = build_dynamic_model(scene);
  DynamicRun run = prepare_dynamic_run(model, scene, [](const std::string&) {});
  auto counter = std::make_unique<AfterStepCounter>(model.particles.size());
  AfterStepCounter* seen = counter.get();
  model.effects.push_back(std::move(counter));
  const RunSummary s = run_dynamic(run, false, stop_after);
  return {seen->calls, seen->families, s.dynamics->last_step};
}

void expect_counted_alike(const std::string& text, int stop_after) {
  int ranks = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  const Counted serial = run_counted(text, Backend::serial, stop_after);
  const Counted ranked = run_counted(text, Backend::petsc, stop_after);
  ASSERT_EQ(serial.steps, stop_after) << "the run must take every step it is given";
  ASSERT_GT(serial.calls, 0);
  EXPECT_EQ(ranked.steps, serial.steps);
  EXPECT_EQ(ranked.calls, serial.calls) << "each rank calls every effect's after_step once per step";
  long long families = 0;
  MPI_Allreduce(&ranked.families, &families, 1, MPI_LONG_LONG, MPI_SUM, MPI_COMM_WORLD);
  EXPECT_EQ(families, serial.families)
      << "the ranks' families together are the body's, once each, on " << ranks << " rank(s)";
}

const char* kPlate = R"(dimension: 2
domain:
  box: {min: [0, 0], max: [1, 1]}
  count: 12
horizon: {ratio: 3.0}
law: silling_plane_strain
materials:
  - {name: steel, E: 200.0e9, nu: 0.25, density: 7850, plane: strain}
boundary:
  - region: {side: left}
    fixed: [x, y]
  - region: {side: right}
    traction: [1.0e6, 0]
)";

TEST(AfterStepOnRanks, ExplicitDynamicsCallsEveryEffectOnEveryRank) {
  expect_counted_alike(std::string(kPlate) + "dynamics: {method: explicit, steps: 25, output_every: 5}\n",
                       25);
}

TEST(AfterStepOnRanks, RelaxationCallsEveryEffectOnEveryRank) {
  expect_counted_alike(
      std::string(kPlate) + "dynamics: {method: relaxation, tolerance: 1.0e-14, steps: 1000}\n", 30);
}

}  // namespace
}  // namespace pd

// A stiff circular inclusion (modulus ratio 1000:1) under remote biaxial tension
// (scenes/inclusion.yaml) against the exact plane-strain field of an inclusion in an
// infinite plane, imposed on a collar one horizon thick: the solve does not break down
// (Newton converges in a few iterations on a direct solver) and the error of eq. (48)
// falls with h at fixed delta/h. Measured (docs/stability.md): 2.2e-2, 4.6e-3, 1.1e-3 at
// 20^2, 40^2, 80^2 particles, i.e. first order in the RMS displacement error.
#include <gtest/gtest.h>

#include "input/scene.hpp"
#include "run/simulation.hpp"

namespace {
pd::RunSummary solve_inclusion(int count) {
  pd::Scene s = pd::read_scene(std::string(PD_SOURCE_DIR) + "/scenes/inclusion.yaml");
  s.h = (s.hi[0] - s.lo[0]) / count;
  const double inner = 1 - s.delta();  // the collar stays one horizon thick
  s.boundary[0].region.min = {-inner, -inner, 0};
  s.boundary[0].region.max = {inner, inner, 0};
  pd::Simulation sim(s, [](const std::string&) {});
  return sim.run(false);
}
}  // namespace

TEST(Inclusion, StiffInclusionConvergesToTheExactField) {
  const pd::RunSummary coarse = solve_inclusion(20), fine = solve_inclusion(40);
  for (const pd::RunSummary* r : {&coarse, &fine}) {
    ASSERT_TRUE(r->newton.converged) << r->newton.message;
    EXPECT_FALSE(r->newton.stagnated);
    EXPECT_LE(r->newton.iterations(), 4);
    EXPECT_EQ(r->newton.linear_solver, "cholmod");
    ASSERT_TRUE(r->has_field_error);
  }
  EXPECT_LT(fine.field_error, 1e-2);
  EXPECT_LT(fine.field_error, coarse.field_error / 3);  // eq. (48) is squared: 4 for first order
}

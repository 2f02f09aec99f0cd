// A stiff circular inclusion (modulus ratio 1000:1) under remote biaxial tension
// (scenes/inclusion.yaml) against the exact plane-strain field of an inclusion in an
// infinite plane, imposed on a collar one horizon thick: the solve does not break down
// (Newton converges in a few iterations on a direct solver) and the error of eq. (48)
// falls with h at fixed delta/h. Measured (docs/stability.md): 2.2e-2, 4.6e-3, 1.1e-3 at
// 20^2, 40^2, 80^2 particles, i.e. first order in the RMS displacement error. Near
// incompressibility (nu = 0.495 in both phases, delta = 3.5 h as in paper 001) the laws
// that represent it converge at least at first order too.
#include <gtest/gtest.h>

#include "input/scene.hpp"
#include "run/simulation.hpp"

namespace {
// The inclusion scene at count^2 particles; `nu` (> 0) replaces both phases' Poisson
// ratio and makes the inclusion 10x stiffer, with delta = 3.5 h.
pd::RunSummary solve_inclusion(int count, const std::string& law = "", double nu = 0) {
  pd::Scene s = pd::read_scene(std::string(PD_SOURCE_DIR) + "/scenes/inclusion.yaml");
  s.h = (s.hi[0] - s.lo[0]) / count;
  if (!law.empty()) {
    s.law = law;
    s.horizon_ratio = 3.5;
    s.materials[0].elastic = pd::IsotropicElastic::from_E_nu(1, nu);
    s.materials[1].elastic = pd::IsotropicElastic::from_E_nu(10, nu);
    for (auto& m : s.materials) m.parameters["stab"] = 1;
    for (pd::FieldSpec* f : {&s.boundary[0].field, &*s.reference})
      f->parameters["E_inclusion"] = 10, f->parameters["nu_inclusion"] = nu;
  }
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

TEST(Inclusion, NearIncompressibleInclusionConvergesAtLeastAtFirstOrder) {
  // Measured (docs/stability.md): e(20^2) / e(40^2) = 10.6, 9.2 and 4.7.
  for (const char* law :
       {"silling_plane_strain", "lps_corrected_plane_strain", "correspondence_silling_plane_strain"}) {
    const pd::RunSummary coarse = solve_inclusion(20, law, 0.495), fine = solve_inclusion(40, law, 0.495);
    ASSERT_TRUE(coarse.newton.converged && fine.newton.converged) << law;
    EXPECT_LT(fine.field_error, coarse.field_error / 4) << law;  // eq. (48) is squared: 4 for first order
  }
}

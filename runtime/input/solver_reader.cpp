// The scene's `solver` section: its words become SolverSpec's enums here.
#include "input/solver_reader.hpp"

#include <fmt/format.h>

#include <cmath>

#include "input/enum_choice.hpp"

namespace pd {

namespace {
// Which preconditioner words go with which linear method (automatic goes with all).
bool preconditioner_fits(LinearMethod linear, Preconditioner pre) {
  if (pre == Preconditioner::automatic) return true;
  switch (linear) {
    case LinearMethod::automatic:
      return pre != Preconditioner::short_horizon;
    case LinearMethod::cholmod:
    case LinearMethod::umfpack:
      return false;
    case LinearMethod::cg:
      return pre == Preconditioner::ic || pre == Preconditioner::diagonal;
    case LinearMethod::bicgstab:
      return pre == Preconditioner::ilut;
    case LinearMethod::matrix_free:
      return pre == Preconditioner::short_horizon || pre == Preconditioner::diagonal;
  }
  return false;
}
}  // namespace

SolverSpec read_solver(const YamlAt& at) {
  MapReader sv(at);
  SolverSpec s;
  s.linear = enum_choice(sv, "linear", LinearMethod::automatic);
  s.preconditioner = enum_choice(sv, "preconditioner", Preconditioner::automatic);
  s.preconditioner_ratio = sv.number("preconditioner_ratio", 2.0);
  if (!(s.preconditioner_ratio >= 1.0))
    sv.get("preconditioner_ratio").fail("must be at least 1 (a horizon of one spacing)");
  if (!preconditioner_fits(s.linear, s.preconditioner))
    sv.get("preconditioner")
        .fail(fmt::format("preconditioner '{}' does not go with linear solver '{}' (cg: ic or diagonal; "
                          "bicgstab: ilut; matrix_free: short_horizon or diagonal)",
                          name_of(s.preconditioner), name_of(s.linear)));
  s.nonlinear = enum_choice(sv, "nonlinear", NonlinearMethod::newton);
  s.backend = enum_choice(sv, "backend", Backend::serial);
  s.petsc_options = sv.text("petsc_options", "");
  if (s.backend != Backend::petsc && sv.has("petsc_options"))
    sv.get("petsc_options").fail("petsc_options needs backend: petsc");
  if (s.backend == Backend::petsc && s.linear != LinearMethod::automatic)
    sv.get("linear").fail(
        "backend petsc chooses its Krylov method and preconditioner through petsc_options "
        "(-ksp_type, -pc_type); leave linear at auto");
  s.load_steps = sv.integer("load_steps", 1);
  if (s.load_steps < 1) sv.get("load_steps").fail("load_steps must be at least 1");
  if (sv.has("load_path")) {
    s.load_path = sv.numbers("load_path");
    const YamlAt path = sv.get("load_path");
    const auto segments = static_cast<int>(s.load_path.size()) - 1;
    if (segments < 1) path.fail("load_path needs at least two values (the load factor at 0 and at 1)");
    if (s.load_path.front() != 0.0)
      path.fail("load_path starts from the unloaded body: its first value must be 0");
    if (s.load_steps % segments != 0)
      path.fail(
          fmt::format("load_steps ({}) must be a multiple of the path's {} segments, so that every turning "
                      "point is a load step",
                      s.load_steps, segments));
  }
  if (sv.has("duration")) {
    s.duration = sv.number("duration");
    if (!(s.duration > 0) || !std::isfinite(s.duration))
      sv.get("duration")
          .fail("duration is the physical time of the load path: it must be positive and finite");
  }
  s.tolerance = sv.number("tolerance", 1e-10);
  s.max_iterations = sv.integer("max_iterations", 30);
  s.max_step_cuts = sv.integer("max_step_cuts", 0);
  if (s.max_step_cuts < 0 || s.max_step_cuts > 30)
    sv.get("max_step_cuts").fail("max_step_cuts must be between 0 and 30 (each halves the step)");
  if (s.max_step_cuts > 0 && s.backend == Backend::petsc)
    sv.get("max_step_cuts")
        .fail("the PETSc backend does not cut load steps: use the serial backend, or more load_steps");
  s.increment_tolerance = sv.number("increment_tolerance", 1e-9);
  s.krylov_tolerance = sv.number("krylov_tolerance", 1e-12);
  s.krylov_max_iterations = sv.integer("krylov_max_iterations", 0);
  if (s.krylov_max_iterations < 0) sv.get("krylov_max_iterations").fail("must be 0 (automatic) or positive");
  const double direct_max = sv.number("direct_max_nonzeros", 2e6);
  if (!(direct_max >= 0) || direct_max > 9e18)
    sv.get("direct_max_nonzeros").fail("must be a non-negative count");
  s.direct_max_nonzeros = static_cast<long long>(direct_max);
  const double preconditioner_max = sv.number("preconditioner_max_nonzeros", 4e7);
  if (!(preconditioner_max >= 0) || preconditioner_max > 9e18)
    sv.get("preconditioner_max_nonzeros").fail("must be a non-negative count");
  s.preconditioner_max_nonzeros = static_cast<long long>(preconditioner_max);
  if (s.tolerance <= 0) sv.get("tolerance").fail("tolerances must be positive");  // only a given one is <= 0
  if (s.krylov_tolerance <= 0) sv.get("krylov_tolerance").fail("tolerances must be positive");
  if (s.max_iterations < 1) sv.get("max_iterations").fail("max_iterations must be at least 1");
  sv.finish();
  return s;
}

}  // namespace pd

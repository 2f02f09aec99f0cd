// The scene's `solver` section as typed choices. The scene reader turns the words into
// these enums (input/enum_choice.hpp, the words in input/enum_names.hpp tables); everything after reading
// switches on them, so -Wswitch-enum finds every place a new method must be handled.
#pragma once

#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "input/enum_names.hpp"

namespace pd {

enum class NonlinearMethod { newton };
// automatic: decided by plan_solver (solve/solver_plan.hpp). matrix_free: Newton-Krylov on
// the generated tangent-vector product, never forming K.
enum class LinearMethod { automatic, cholmod, umfpack, cg, bicgstab, matrix_free };
// automatic: the method's default (cg: ic; bicgstab: ilut; matrix_free: short_horizon).
enum class Preconditioner { automatic, ic, diagonal, ilut, short_horizon };
// serial: Eigen/SuiteSparse in this process. petsc: PETSc over the MPI processes the run
// was started on (`mpirun -n N pd run`), solve/distributed_backend.hpp.
enum class Backend { serial, petsc };

// The scene's words for each value (and the ones the log and summary.json print), in the
// order the scene reader lists them in its error messages.
template <>
struct enum_names<NonlinearMethod> {
  static constexpr std::array<EnumName<NonlinearMethod>, 1> table{{{NonlinearMethod::newton, "newton"}}};
};
template <>
struct enum_names<LinearMethod> {
  static constexpr std::array<EnumName<LinearMethod>, 6> table{{{LinearMethod::automatic, "auto"},
                                                                {LinearMethod::cholmod, "cholmod"},
                                                                {LinearMethod::umfpack, "umfpack"},
                                                                {LinearMethod::cg, "cg"},
                                                                {LinearMethod::bicgstab, "bicgstab"},
                                                                {LinearMethod::matrix_free, "matrix_free"}}};
};
template <>
struct enum_names<Preconditioner> {
  static constexpr std::array<EnumName<Preconditioner>, 5> table{
      {{Preconditioner::automatic, "auto"},
       {Preconditioner::ic, "ic"},
       {Preconditioner::diagonal, "diagonal"},
       {Preconditioner::ilut, "ilut"},
       {Preconditioner::short_horizon, "short_horizon"}}};
};
template <>
struct enum_names<Backend> {
  static constexpr std::array<EnumName<Backend>, 2> table{
      {{Backend::serial, "serial"}, {Backend::petsc, "petsc"}}};
};

struct SolverSpec {
  Backend backend = Backend::serial;
  std::string petsc_options;  // backend petsc: PETSc options ("-ksp_monitor -pc_type hypre")
  LinearMethod linear = LinearMethod::automatic;
  Preconditioner preconditioner = Preconditioner::automatic;
  double preconditioner_ratio = 2.0;  // matrix_free short_horizon: delta/h of the preconditioning stiffness
  NonlinearMethod nonlinear = NonlinearMethod::newton;  // the only one so far; the key keeps scenes explicit
  int load_steps = 1;
  // solver.load_path: the load factor at the equally spaced pseudo-times 0, 1/K, ..., 1 (K
  // segments, linear between); it may unload and reverse. Empty: proportional, i / load_steps.
  std::vector<double> load_path;
  // solver.duration: the physical time the load path takes (NewtonSettings::duration), for a
  // rate-dependent law in a static scene; 0 (not given): the path has no physical time.
  double duration = 0.0;
  double tolerance = 1e-10;           // on the residual norm relative to the load
  double increment_tolerance = 1e-9;  // or on the last Newton increment relative to u
  int max_iterations = 30;
  // solver.max_step_cuts: bisections of a load step whose Newton iterations fail
  // (NewtonSettings::max_step_cuts); serial backend only. 0: a failed step ends the solve.
  int max_step_cuts = 0;
  double krylov_tolerance = 1e-12;
  int krylov_max_iterations = 0;  // 0: 2 x unknowns for assembled Krylov, 20000 matrix-free
  // auto: the assembled tangent (a direct solver) up to this many estimated nonzeros,
  // matrix-free above. On the crack at delta/h = 3.5 (one run, shared machine) CHOLMOD
  // and the short-horizon matrix-free path broke even near 1.5e6 nonzeros (60^2: 1.10 s
  // vs 0.86 s); at 100^2 (4.3e6) matrix-free took 3.9 s against CHOLMOD's 15 s.
  // The same limit then picks direct or Krylov on the assembled tangent's exact count.
  long long direct_max_nonzeros = 2'000'000;
  // auto, above direct_max_nonzeros: the short-horizon preconditioner while its stiffness
  // has at most this many nonzeros (its factor must fit in memory), Jacobi above
  long long preconditioner_max_nonzeros = 40'000'000;
};

}  // namespace pd

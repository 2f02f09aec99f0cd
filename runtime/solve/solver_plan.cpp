// The solver plan: the `auto` path, the assembled direct/Krylov rule, the fallbacks.
#include "solve/solver_plan.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace pd {

std::int64_t estimated_tangent_nonzeros(int particles, double mean_family_size, int dim, bool pairwise) {
  const double rows_per_particle = (pairwise ? 1.0 : std::pow(2.0, dim)) * mean_family_size + 1.0;
  return static_cast<std::int64_t>(std::llround(particles * rows_per_particle * dim * dim));
}

bool plan_needs_short_family_size(const SolverSpec& spec) {
  return spec.backend == Backend::serial && spec.linear == LinearMethod::automatic &&
         spec.preconditioner == Preconditioner::automatic;
}

SolverPlan plan_solver(const SolverSpec& spec, const ProblemSize& size) {
  SolverPlan plan{spec.nonlinear, spec.linear, spec.preconditioner, {}};
  if (spec.backend == Backend::petsc) {  // PETSc decides the rest (petsc_options)
    plan.backend = Backend::petsc;
    plan.linear = LinearMethod::matrix_free;
    plan.preconditioner = Preconditioner::short_horizon;
    const double ratio = std::min(size.delta_over_h, spec.preconditioner_ratio);
    plan.reason = fmt::format(
        "PETSc: SNES Newton, Krylov on the generated tangent-vector product, the preconditioner "
        "(default GAMG) on the stiffness at delta/h = {:.3g}{}",
        ratio, spec.petsc_options.empty() ? "" : "; options " + spec.petsc_options);
    return plan;
  }
  if (spec.linear != LinearMethod::automatic) {
    plan.reason = fmt::format("linear: {} (scene)", name_of(spec.linear));
    return plan;
  }
  if (spec.preconditioner !=
      Preconditioner::automatic) {  // ic, ilut or diagonal name an assembled Krylov method
    plan.reason =
        fmt::format("assembled tangent (the scene's preconditioner {})", name_of(spec.preconditioner));
    return plan;
  }
  const std::int64_t k_estimate =
      estimated_tangent_nonzeros(size.particles, size.mean_family_size, size.dim, size.pairwise);
  if (k_estimate <= spec.direct_max_nonzeros) {
    plan.reason = fmt::format("assembled tangent: about {:.3g} nonzeros, within direct_max_nonzeros {:.3g}",
                              static_cast<double>(k_estimate), static_cast<double>(spec.direct_max_nonzeros));
    return plan;
  }
  // Without a count, families shrink with the horizon as (ratio / (delta/h))^dim on a
  // uniform cloud (which overestimates where the influence vanishes on the rim).
  const double short_ratio = std::min(size.delta_over_h, spec.preconditioner_ratio);
  const double short_family =
      size.short_family_size >= 0
          ? size.short_family_size
          : size.mean_family_size * std::pow(short_ratio / size.delta_over_h, size.dim);
  const std::int64_t p_estimate =
      estimated_tangent_nonzeros(size.particles, short_family, size.dim, size.pairwise);
  const std::string over =
      fmt::format("assembled tangent would have about {:.3g} nonzeros (> direct_max_nonzeros {:.3g})",
                  static_cast<double>(k_estimate), static_cast<double>(spec.direct_max_nonzeros));
  plan.linear = LinearMethod::matrix_free;
  if (p_estimate <= spec.preconditioner_max_nonzeros) {
    // At delta/h <= preconditioner_ratio the "short" horizon is delta itself: the
    // preconditioner is the tangent's own factorisation, CG converges in an iteration or
    // two, and the path costs what a direct solve does (Jacobi took 1531 iterations and
    // 26 s on the 200^2 crack at delta/h = 1.5, where CHOLMOD takes seconds).
    const std::string which =
        short_ratio < size.delta_over_h
            ? fmt::format("the delta/h = {:.3g} stiffness", short_ratio)
            : std::string("the tangent's own factorisation (delta/h is already that short)");
    plan.preconditioner = Preconditioner::short_horizon;
    plan.reason = fmt::format("{} -> matrix-free Newton-Krylov preconditioned by {} (about {:.3g} nonzeros)",
                              over, which, static_cast<double>(p_estimate));
    return plan;
  }
  plan.preconditioner = Preconditioner::diagonal;
  plan.reason = fmt::format(
      "{} -> matrix-free Newton-Krylov with Jacobi (the {} stiffness, about {:.3g} nonzeros, exceeds "
      "preconditioner_max_nonzeros {:.3g})",
      over, short_ratio < size.delta_over_h ? "short-horizon" : "full", static_cast<double>(p_estimate),
      static_cast<double>(spec.preconditioner_max_nonzeros));
  return plan;
}

SolverChoice choose_linear_solver(LinearMethod method, Preconditioner preconditioner,
                                  long long direct_max_nonzeros, std::int64_t unknowns, std::int64_t nonzeros,
                                  bool symmetric) {
  if (method != LinearMethod::automatic) return {method, preconditioner, "named in the options"};
  const bool direct = nonzeros <= direct_max_nonzeros;
  const LinearMethod m = direct ? (symmetric ? LinearMethod::cholmod : LinearMethod::umfpack)
                                : (symmetric ? LinearMethod::cg : LinearMethod::bicgstab);
  const std::string rule =
      direct_max_nonzeros == std::numeric_limits<long long>::max()
          ? std::string("direct at any size")
          : fmt::format("{} {} nonzeros", direct ? "direct up to" : "Krylov above", direct_max_nonzeros);
  return {m, preconditioner,
          fmt::format("{} unknowns, {} nonzeros, {} -> {} ({})", unknowns, nonzeros,
                      symmetric ? "symmetric" : "non-symmetric", name_of(m), rule)};
}

std::optional<SolverChoice> fallback_after_failure(const SolverChoice& failed) {
  if (failed.method == LinearMethod::cholmod)
    return SolverChoice{LinearMethod::umfpack, Preconditioner::automatic, "umfpack"};
  const bool ic =
      failed.preconditioner == Preconditioner::automatic || failed.preconditioner == Preconditioner::ic;
  if (failed.method == LinearMethod::cg && ic)
    return SolverChoice{LinearMethod::cg, Preconditioner::diagonal, "cg+diagonal"};
  return std::nullopt;
}

}  // namespace pd

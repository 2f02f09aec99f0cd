#include "run/solver_path.hpp"

#include <cmath>

#include <fmt/format.h>

namespace pd {

std::int64_t estimated_tangent_nonzeros(int particles, double mean_family_size, int dim) {
  const double rows_per_particle = std::pow(2.0, dim) * mean_family_size + 1.0;
  return static_cast<std::int64_t>(std::llround(particles * rows_per_particle * dim * dim));
}

SolverPath choose_solver_path(const SolverSpec& solver, int particles, double mean_family_size, int dim,
                              double delta_over_h, double short_family_size) {
  if (solver.linear != "auto") return {solver.linear, solver.preconditioner, "linear: " + solver.linear + " (scene)"};
  if (solver.preconditioner != "auto")  // ic, ilut or diagonal name an assembled Krylov method
    return {"auto", solver.preconditioner, "assembled tangent (the scene's preconditioner " + solver.preconditioner + ")"};
  const std::int64_t k_estimate = estimated_tangent_nonzeros(particles, mean_family_size, dim);
  if (k_estimate <= solver.direct_max_nonzeros)
    return {"auto", solver.preconditioner,
            fmt::format("assembled tangent: about {:.3g} nonzeros, within direct_max_nonzeros {:.3g}",
                        static_cast<double>(k_estimate), static_cast<double>(solver.direct_max_nonzeros))};
  // Without a count, families shrink with the horizon as (ratio / (delta/h))^dim on a
  // uniform cloud (which overestimates where the influence vanishes on the rim).
  const double short_ratio = std::min(delta_over_h, solver.preconditioner_ratio);
  const double short_family =
      short_family_size >= 0 ? short_family_size : mean_family_size * std::pow(short_ratio / delta_over_h, dim);
  const std::int64_t p_estimate = estimated_tangent_nonzeros(particles, short_family, dim);
  const std::string over = fmt::format("assembled tangent would have about {:.3g} nonzeros (> direct_max_nonzeros {:.3g})",
                                       static_cast<double>(k_estimate), static_cast<double>(solver.direct_max_nonzeros));
  if (p_estimate <= solver.preconditioner_max_nonzeros) {
    // At delta/h <= preconditioner_ratio the "short" horizon is delta itself: the
    // preconditioner is the tangent's own factorisation, CG converges in an iteration or
    // two, and the path costs what a direct solve does (Jacobi took 1531 iterations and
    // 26 s on the 200^2 crack at delta/h = 1.5, where CHOLMOD takes seconds).
    const std::string which = short_ratio < delta_over_h
                                  ? fmt::format("the delta/h = {:.3g} stiffness", short_ratio)
                                  : std::string("the tangent's own factorisation (delta/h is already that short)");
    return {"matrix_free", "short_horizon",
            fmt::format("{} -> matrix-free Newton-Krylov preconditioned by {} (about {:.3g} nonzeros)", over, which,
                        static_cast<double>(p_estimate))};
  }
  return {"matrix_free", "diagonal",
          fmt::format("{} -> matrix-free Newton-Krylov with Jacobi (the {} stiffness, about {:.3g} nonzeros, exceeds "
                      "preconditioner_max_nonzeros {:.3g})",
                      over, short_ratio < delta_over_h ? "short-horizon" : "full", static_cast<double>(p_estimate),
                      static_cast<double>(solver.preconditioner_max_nonzeros))};
}

}  // namespace pd

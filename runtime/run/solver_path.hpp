// Which linear-solver path a static run takes when the scene says `linear: auto`,
// decided before any matrix is built (building K to measure it would already cost
// the memory the choice is meant to save).
#pragma once

#include <cstdint>
#include <string>

#include "input/scene.hpp"

namespace pd {

// Nonzeros of the assembled tangent, estimated from the mean family size: every
// family couples all its particles (two-horizon reach), so a particle's row holds
// about the particles within 2 delta, 2^dim L_mean + 1 of them, each a dim x dim block.
std::int64_t estimated_tangent_nonzeros(int particles, double mean_family_size, int dim);

struct SolverPath {
  std::string linear;          // the SolverSpec::linear the run uses
  std::string preconditioner;  // and its preconditioner
  std::string reason;          // one line for the log and the summary
};

// linear != auto, or a preconditioner named with auto: the scene's choice. Else:
//  - estimated K nonzeros <= direct_max_nonzeros: assembled (the direct/Krylov rule of
//    the linear solver then decides on the exact count);
//  - above, matrix-free Newton-Krylov: preconditioned by the factorised stiffness on
//    the horizon min(delta, preconditioner_ratio h) while its estimate fits
//    preconditioner_max_nonzeros, else by Jacobi (the least memory).
// short_family_size: the preconditioner's mean family size (mean_short_family_size);
// negative: scaled from mean_family_size by the horizons' volume ratio.
SolverPath choose_solver_path(const SolverSpec& solver, int particles, double mean_family_size, int dim,
                              double delta_over_h, double short_family_size = -1);

}  // namespace pd

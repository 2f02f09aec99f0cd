// What the relaxation loop (run/relaxation_run.cpp, serial or over the ranks) needs besides
// the ADR update: the reference force of the convergence test and the checkpoint's scalars,
// so a checkpoint written on any number of processes restarts on any other.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "model/model.hpp"

namespace pd {

// The reference force: the larger of |f| (the initial out-of-balance force) and each
// load's norm at u (in full: relaxation has no time functions); 1 when all are zero.
// norm: the Euclidean norm over the free dofs (a distributed loop sums it over the ranks).
double relaxation_reference(const Model& model, const std::vector<double>& u, const std::vector<double>& f,
                            const std::function<double(const std::vector<double>&)>& norm);

// Checkpoint scalars: [iterations, reference, broken_start, v (N), f_prev (N)]. The
// reference is the one of iteration 0: recomputed at the restored u it would be the
// residual there, and the restarted run would stop at another iteration.
struct RelaxationRestart {
  int iterations = 0;
  double reference = 0;
  long long broken_start = 0;
  std::vector<double> v, f_prev;
};
std::vector<double> relaxation_scalars(const RelaxationRestart& state);
// Throws std::runtime_error naming `file` when the scalars are not those of N dofs.
RelaxationRestart relaxation_restart(const std::vector<double>& scalars, std::size_t N,
                                     const std::string& file);

}  // namespace pd

// The distributed dynamic run of a scene's method (distributed_dynamics.hpp).
#include "petsc/distributed_dynamics.hpp"

#include "run/dynamic_run.hpp"

namespace pd {

RunSummary run_distributed_dynamics(DynamicRun& run, bool write, int stop_after) {
  return run.explicit_dynamics() ? run_distributed_explicit(run, write, stop_after)
                                 : run_distributed_relaxation(run, write, stop_after);
}

}  // namespace pd

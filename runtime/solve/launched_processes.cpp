// How many processes the MPI launcher started, read from its environment (MPI itself
// is initialised only by a run that uses the distributed backend).
#include <cstdlib>

#include "solve/distributed_backend.hpp"

namespace pd {

int launched_process_count() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_SIZE", "SLURM_NTASKS"})
    if (const char* v = std::getenv(name)) {
      const int n = std::atoi(v);
      if (n > 0) return n;
    }
  return 1;
}

}  // namespace pd

// The whole state on rank 0, from the values each rank owns: what rank 0 needs to write
// the serial run's files (series rows, snapshots, checkpoints, results). Collective:
// every rank of the partition's communicator calls it with the same arguments' shapes.
#pragma once

#include <mpi.h>

#include <vector>

#include "particles.hpp"
#include "petsc/partition.hpp"

namespace pd {

// full: [n * width] in model order on every rank; on return rank 0's holds every
// particle's owned values (each from the rank owning it), the other ranks' are unchanged.
void gather_particle_values(const Partition& part, int width, std::vector<double>& full, MPI_Comm comm);

// bonds.alpha on rank 0 = each family's factors as the rank owning the family holds them
// (the copy its forces used); the other ranks' are unchanged.
void gather_family_alpha(const Partition& part, Bonds& bonds, MPI_Comm comm);

}  // namespace pd

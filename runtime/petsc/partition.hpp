// Splitting the particles among MPI ranks: a space-filling-curve order, one contiguous
// block of it per rank, and the ghost layer each rank's families read.
#pragma once

#include <vector>

#include "assembly/sparsity_pattern.hpp"
#include "particles.hpp"

namespace pd {

// The particles in Morton (Z-curve) order of their positions: nearby particles get
// nearby numbers, so a contiguous block of the order is a compact piece of the body and
// its ghost layer is a thin shell. order[k] is the model particle at position k;
// position[p] is the position of model particle p (the inverse).
struct ParticleOrder {
  std::vector<int> order, position;
};
ParticleOrder morton_order(const Particles& particles);

// Rank `rank` of `ranks` owns positions [begin, end) of the order: equal blocks (the
// first n % ranks ranks one more). ghosts: the model particles that are not owned but
// are bonded to an owned one -- one horizon, what the rank's families read. Sorted by
// position, so PETSc's ghost list is in global order.
struct Partition {
  int rank = 0, ranks = 1;
  int begin = 0, end = 0;  // owned positions in the order
  ParticleOrder order;
  std::vector<int> ghosts;  // model particle ids
  int owned() const { return end - begin; }
  bool owns(int model_particle) const {
    const int k = order.position[model_particle];
    return k >= begin && k < end;
  }
  // The model id of owned particle i (0 <= i < owned()).
  int owned_particle(int i) const { return order.order[begin + i]; }
};
Partition make_partition(const Particles& particles, const Bonds& bonds, int rank, int ranks);

// Block (particle) nonzeros of the owned rows of the pattern of `bonds` in the
// partition's order. Coupling::family (two horizons): row i couples to every particle of
// every family that holds i (i's own and its neighbours'); Coupling::pairwise (one
// horizon, a law without states): to i and its own neighbours only.
// diagonal: columns owned by this rank; off: the others.
void block_row_counts(const Partition& part, const Bonds& bonds, Coupling coupling,
                      std::vector<int>& diagonal, std::vector<int>& off);

}  // namespace pd

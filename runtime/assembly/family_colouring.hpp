// Groups families into colours whose members share no particle, so threads never collide.
#pragma once

#include <vector>

#include "particles.hpp"

namespace pd {

// Families are cut into chunks of consecutive indices; two chunks conflict when a
// family of one and a family of the other hold a common particle (centers within two
// horizons). Chunks are coloured greedily, so within a colour every chunk writes a
// disjoint set of particles (force entries) and of particle columns (matrix entries).
//
// Why colouring rather than atomic adds: (1) no atomic read-modify-write per matrix
// entry; (2) each entry receives its contributions in an order fixed by the colouring
// alone, so the assembled forces and matrix are bitwise identical for any thread
// count; (3) consecutive-index chunks keep a thread on one neighbourhood of a grid-
// ordered cloud, so the scattered writes stay in cache. A colour ends with a barrier;
// chunking keeps the colour count small (about (2 delta / chunk width + 1) rows of
// chunks on a lattice: 10-30 colours) so those barriers are cheap.
class FamilyColouring {
 public:
  // chunk_size 0: chosen from the particle count (enough chunks per colour for the
  // threads to balance, long enough to amortise the barrier).
  explicit FamilyColouring(const Bonds& bonds, int chunk_size = 0);

  int colours() const { return static_cast<int>(colour_start_.size()) - 1; }
  // Chunks of colour c: chunk_ids()[colour_start(c) .. colour_start(c+1)).
  int colour_start(int c) const { return colour_start_[c]; }
  int chunk_id(int i) const { return chunk_ids_[i]; }
  int chunk_begin(int chunk) const { return chunk * chunk_size_; }
  int chunk_end(int chunk) const { return chunk * chunk_size_ + chunk_size_ < n_ ? chunk * chunk_size_ + chunk_size_ : n_; }
  int chunk_size() const { return chunk_size_; }

 private:
  int n_, chunk_size_;
  std::vector<int> colour_start_, chunk_ids_;
};

}  // namespace pd

// Groups families into colours whose members share no particle, so threads never collide.
#pragma once

#include <vector>

#include "particles.hpp"

namespace pd {

// Families are cut into chunks; two chunks conflict when a family of one and a family
// of the other hold a common particle (centers within two horizons). Chunks are
// coloured greedily, so within a colour every chunk writes a disjoint set of particles
// (force entries) and of particle columns (matrix entries).
//
// Chunks (chunk_size 0, the default) are square tiles of the body, two horizons on a
// side: a tile's families write the particle columns within a horizon of it, about
// 1 MB of K at delta/h = 3.5 in 2D, so the scatter's writes stay in a core's L2 while
// the tile is assembled. Chunks of consecutive family indices (rows of a lattice) wrote
// a strip 400 particles long per chunk: every entry of K came back from memory once
// per family row holding it, and the scatter waited on those loads (docs/performance.md).
// chunk_size > 0: chunks of that many consecutive indices instead (tests, comparison).
//
// Why colouring rather than atomic adds: (1) no atomic read-modify-write per matrix
// entry; (2) each entry receives its contributions in an order fixed by the colouring
// alone, so the assembled forces and matrix are bitwise identical for any thread
// count. A colour ends with a barrier; tiles of two horizons give a handful of colours
// (9 or so in 2D) so those barriers are cheap.
class FamilyColouring {
 public:
  FamilyColouring(const Particles& particles, const Bonds& bonds, int chunk_size = 0);

  int colours() const { return static_cast<int>(colour_start_.size()) - 1; }
  // Chunks of colour c: chunk_ids()[colour_start(c) .. colour_start(c+1)).
  int colour_start(int c) const { return colour_start_[c]; }
  int chunk_id(int i) const { return chunk_ids_[i]; }
  // The families of a chunk: family(j) for j in [chunk_begin, chunk_end).
  int chunk_begin(int chunk) const { return chunk_start_[chunk]; }
  int chunk_end(int chunk) const { return chunk_start_[chunk + 1]; }
  int family(int j) const { return order_[j]; }
  int chunks() const { return static_cast<int>(chunk_start_.size()) - 1; }

 private:
  std::vector<int> order_;        // families, chunk by chunk
  std::vector<int> chunk_start_;  // [chunks + 1] ranges in order_
  std::vector<int> colour_start_, chunk_ids_;
};

}  // namespace pd

// A non-uniform body (paper 003 sections 4.2, 5.3-5.4, Fig. 23): several boxes, each filled
// with its own cell-centred lattice, so each particle has the volume h_b^dim and the horizon
// delta_b = ratio * h_b of its block (the paper's delta = k dx per region).
//
// What a bond between particles of different horizons means (the paper's reading of its
// eq. 5, written out here because the paper does not): the family of x is every particle
// within x's own horizon, H_x = {x' : |x' - x| <= delta_x}. So near an interface x' may be in
// H_x while x is not in H_x' (a fine particle's short horizon misses the coarse particle whose
// long horizon reaches it). The force density on x is
//   sum_{x' in H_x} T[x]<x' - x> V' - sum_{x' : x in H_x'} T[x']<x - x'> V',
// each term computed by the owner of the family from its own delta, volumes and moments, and
// each pair force applied with equal and opposite sign to the two particles: linear momentum
// is balanced exactly (tests/runtime/test_lattice_blocks.cpp); the asymmetry shows as ghost
// forces at the interface under a homogeneous strain, which the patch test measures.
#pragma once

#include <string>
#include <vector>

#include "input/region.hpp"  // Point
#include "particles.hpp"

namespace pd {

struct LatticeBlock {
  Point lo{}, hi{};
  double spacing = 0;
  std::string where;  // "file:line: domain.blocks[i]" for messages
};

// The union of the blocks' cell-centred lattices, block by block; spacing[i] is particle
// i's lattice spacing. Throws std::invalid_argument naming the block when a block's
// sides are not whole multiples of its spacing (to 1e-9) or two blocks overlap.
Particles lattice_blocks(const std::vector<LatticeBlock>& blocks, int dim, std::vector<double>& spacing);

// Families with a horizon per particle: q is in p's family when |x_q - x_p| <= delta[p]
// (1 + 1e-12, as find_bonds), w = influence(|xi|, delta[p]); bonds.delta = delta. Every
// neighbour counts with its whole volume (domain.quadrature: volume).
Bonds find_bonds_per_particle(const Particles& p, const std::vector<double>& delta,
                              double (*influence)(double r, double delta));

}  // namespace pd

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

#include "input/lattice_block_cloud.hpp"  // LatticeBlock, lattice_blocks: the particles
#include "input/quadrature.hpp"
#include "particles.hpp"

namespace pd {

// Families with a horizon per particle: q is in p's family when |x_q - x_p| <= delta[p]
// (1 + 1e-12, as find_bonds), w = influence(|xi|, delta[p]); bonds.delta = delta. Every
// neighbour counts with its whole volume (domain.quadrature: volume).
Bonds find_bonds_per_particle(const Particles& p, const std::vector<double>& delta,
                              double (*influence)(double r, double delta));

// The families of a body of blocks under a quadrature: `volume` is find_bonds_per_particle;
// `partial_linear` (paper 003 eq. 17 = paper 002 eq. 2.16) weighs neighbour j of i by
// (delta_i + h_j/2 - |xi|) / h_j clipped to [0, 1], h_j the spacing of j's own cell (the cell
// whose share of i's horizon is measured), so a fine neighbour's cell is cut finer than a
// coarse one's; as find_quadrature_bonds, w is taken at min(|xi|, delta_i) and bonds of factor 0
// are left out. On one spacing it gives find_quadrature_bonds' families. Other quadratures
// throw std::invalid_argument.
Bonds find_block_bonds(const Particles& p, const std::vector<double>& delta,
                       const std::vector<double>& spacing, Quadrature q,
                       double (*influence)(double r, double delta));

}  // namespace pd

// The discretised body: particles and their families (bonds in compressed rows).
#pragma once

#include <cstddef>
#include <vector>

namespace pd {

// Particle cloud in the reference configuration.
struct Particles {
  int dim = 2;
  std::vector<double> x;       // [n*dim] reference positions
  std::vector<double> volume;  // [n] particle volumes (areas in 2D)
  std::vector<int> material;   // [n] index into the scene's material list
  int size() const { return static_cast<int>(volume.size()); }
  const double* position(int p) const { return x.data() + static_cast<std::ptrdiff_t>(p) * dim; }
};

// Families of all particles in compressed-row form: the bonds of particle p are
// offsets[p] .. offsets[p+1]-1. Bond b joins p to neighbor[b]; a bond appears once
// in each of its two families (p's and the neighbour's), as peridynamics needs.
struct Bonds {
  int dim = 2;
  std::vector<int> offsets;    // [n+1]
  std::vector<int> neighbor;   // [nb]
  std::vector<double> xi;      // [nb*dim] reference bond x_neighbor - x_p
  std::vector<double> length;  // [nb] |xi|
  std::vector<double> w;       // [nb] influence weight
  std::vector<double> alpha;   // [nb] 1 intact, 0 broken
  std::vector<double> delta;   // [n] horizon of each particle
  // [nb] share of the neighbour's volume inside the horizon (domain.quadrature, paper 002);
  // empty: every neighbour counts whole.
  std::vector<double> volume_factor;
  // [nb] surface correction (domain.surface_correction, assembly/surface_correction.hpp):
  // the bond's factor on the law's dilatation sum and on its force state; empty: 1.
  std::vector<double> surface_dilatation, surface_force;

  int particle_count() const { return offsets.empty() ? 0 : static_cast<int>(offsets.size()) - 1; }
  int bond_count() const { return static_cast<int>(neighbor.size()); }
  int family_size(int p) const { return offsets[p + 1] - offsets[p]; }
};

}  // namespace pd

// The full family of a particle in an infinite regular lattice: the reference a
// per-particle boundary factor compares a truncated family with (paper 002's
// compensation factor, paper 003's surface correction). Every lattice offset within the
// quadrature's reach with a positive volume factor, as find_quadrature_bonds would give
// an interior particle, with the same influence weights and alpha = 1.
#pragma once

#include <vector>

#include "input/quadrature.hpp"
#include "kernel_abi.hpp"

namespace pd {

struct LatticeFamily {
  std::vector<double> xi, Y, w, alpha, V, scratch;
  int n = 0;
  // Y = (1 + stretch) xi; spacing h, horizon delta, dimension dim.
  LatticeFamily(Quadrature quadrature, double delta, double h, int dim,
                double (*influence)(double r, double delta), double stretch, int scratch_per_bond);
  // The kernels' view of it for a center of volume V0 (no moments set).
  abi::Family family(double V0, double delta, const double* params);
};

}  // namespace pd

// The particles of a body of lattice blocks (lattice_block_cloud.hpp).
#include "input/lattice_block_cloud.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace pd {

namespace {
// Cells along an axis of a block: its side over its spacing, which must be a whole number.
int cells_along(const LatticeBlock& b, int c) {
  const double side = b.hi[c] - b.lo[c];
  const double n = std::round(side / b.spacing);
  if (!(side > 0) || n < 1 || std::abs(n * b.spacing - side) > 1e-9 * side)
    throw std::invalid_argument(
        fmt::format("{}: the side {} along {} is not a whole number of spacings {} "
                    "(each block is filled with whole cells)",
                    b.where, side, "xyz"[c], b.spacing));
  return static_cast<int>(n);
}

bool interiors_overlap(const LatticeBlock& a, const LatticeBlock& b, int dim) {
  for (int c = 0; c < dim; ++c) {
    const double tol = 1e-9 * std::min(a.spacing, b.spacing);
    if (a.hi[c] <= b.lo[c] + tol || b.hi[c] <= a.lo[c] + tol) return false;
  }
  return true;
}
}  // namespace

Particles lattice_blocks(const std::vector<LatticeBlock>& blocks, int dim, std::vector<double>& spacing) {
  Particles p;
  p.dim = dim;
  spacing.clear();
  for (std::size_t i = 0; i < blocks.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (interiors_overlap(blocks[i], blocks[j], dim))
        throw std::invalid_argument(fmt::format("{}: overlaps {}", blocks[i].where, blocks[j].where));
  for (const LatticeBlock& b : blocks) {
    if (!(b.spacing > 0)) throw std::invalid_argument(b.where + ": spacing must be positive");
    int n[3] = {1, 1, 1};
    for (int c = 0; c < dim; ++c) n[c] = cells_along(b, c);
    const double volume = std::pow(b.spacing, dim);
    for (int k = 0; k < n[2]; ++k)
      for (int j = 0; j < n[1]; ++j)
        for (int i = 0; i < n[0]; ++i) {
          const int idx[3] = {i, j, k};
          for (int c = 0; c < dim; ++c) p.x.push_back(b.lo[c] + (idx[c] + 0.5) * b.spacing);
          p.volume.push_back(volume);
          p.material.push_back(0);
          spacing.push_back(b.spacing);
        }
  }
  return p;
}

}  // namespace pd

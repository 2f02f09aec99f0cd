// Non-uniform lattices and families with a horizon per particle (lattice_blocks.hpp).
#include "discretize/lattice_blocks.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "discretize/partial_volume.hpp"

namespace pd {

namespace {

// Particles binned in a uniform grid of cubic cells (edge `size`) over their bounding box.
struct CellList {
  int d = 0;
  double size = 0;
  double lo[3] = {0, 0, 0};
  int dims[3] = {1, 1, 1};
  std::vector<int> start, items;  // items[start[c] .. start[c + 1]) are the particles of cell c
  // The (clamped) cell coordinates of point x.
  void cell_of(const double* x, int* ci) const {
    for (int c = 0; c < 3; ++c)
      ci[c] = c < d ? std::min(dims[c] - 1, static_cast<int>((x[c] - lo[c]) / size)) : 0;
  }
};

// Builds the cell list of the particles with cells of edge `size` (a counting sort by cell).
CellList build_cell_list(const Particles& p, double size) {
  const int d = p.dim, n = p.size();
  CellList cl;
  cl.d = d;
  cl.size = size;
  double hi[3] = {0, 0, 0};
  for (int c = 0; c < d; ++c) {
    cl.lo[c] = hi[c] = p.x[c];
    for (int i = 0; i < n; ++i)
      cl.lo[c] = std::min(cl.lo[c], p.x[i * d + c]), hi[c] = std::max(hi[c], p.x[i * d + c]);
  }
  for (int c = 0; c < d; ++c) cl.dims[c] = std::max(1, static_cast<int>((hi[c] - cl.lo[c]) / size) + 1);
  const std::size_t n_cells = static_cast<std::size_t>(cl.dims[0]) * cl.dims[1] * cl.dims[2];
  cl.start.assign(n_cells + 1, 0);
  cl.items.assign(static_cast<std::size_t>(n), 0);
  std::vector<std::size_t> cell_index(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    int ci[3];
    cl.cell_of(p.position(i), ci);
    cell_index[i] = (static_cast<std::size_t>(ci[2]) * cl.dims[1] + ci[1]) * cl.dims[0] + ci[0];
    ++cl.start[cell_index[i] + 1];
  }
  for (std::size_t c = 0; c < n_cells; ++c) cl.start[c + 1] += cl.start[c];
  {
    std::vector<int> fill(cl.start.begin(), cl.start.end() - 1);
    for (int i = 0; i < n; ++i) cl.items[fill[cell_index[i]]++] = i;
  }
  return cl;
}

// Appends to b the bonds of particle i to its sorted neighbours `found` (xi, length, weight, alpha).
void append_family(Bonds& b, const Particles& p, int i, const std::vector<int>& found, double delta_i,
                   double (*influence)(double, double)) {
  const int d = p.dim;
  for (int j : found) {
    double r2 = 0;
    for (int c = 0; c < d; ++c) {
      const double e = p.x[j * d + c] - p.x[i * d + c];
      b.xi.push_back(e);
      r2 += e * e;
    }
    const double r = std::sqrt(r2);
    b.neighbor.push_back(j);
    b.length.push_back(r);
    b.w.push_back(influence(r, delta_i));
    b.alpha.push_back(1.0);
  }
}

}  // namespace

Bonds find_bonds_per_particle(const Particles& p, const std::vector<double>& delta,
                              double (*influence)(double, double)) {
  const int d = p.dim, n = p.size();
  if (static_cast<int>(delta.size()) != n)
    throw std::invalid_argument("find_bonds_per_particle: one delta per particle");
  if (n == 0) return Bonds{d, {0}, {}, {}, {}, {}, {}, {}, {}, {}, {}};
  // A cell list with cells a little larger than the smallest horizon; a particle scans as
  // many cells each way as its own horizon needs (a fine particle does not scan a coarse
  // one's reach). The 1e-9 margin keeps a neighbour exactly delta away (integer delta/h on
  // a lattice) inside the scanned cells whatever the rounding of (x - lo) / size; with one
  // horizon for all, span = 1: the 3^d cells of the uniform search.
  const double size = *std::min_element(delta.begin(), delta.end()) * (1 + 1e-9);
  const CellList cells = build_cell_list(p, size);
  const int* dims = cells.dims;
  const std::vector<int>& cell_start = cells.start;
  const std::vector<int>& cell_items = cells.items;
  Bonds b;
  b.dim = d;
  b.offsets.assign(static_cast<std::size_t>(n) + 1, 0);
  b.delta = delta;
  std::vector<int> found;
  for (int i = 0; i < n; ++i) {
    const double reach = delta[i] * (1 + 1e-12);  // a lattice site exactly delta away stays in
    const int span = static_cast<int>(std::ceil(reach / size));
    int ci[3];
    cells.cell_of(p.position(i), ci);
    found.clear();
    const int sz = d == 3 ? span : 0;
    for (int dz = -sz; dz <= sz; ++dz)
      for (int dy = -span; dy <= span; ++dy)
        for (int dx = -span; dx <= span; ++dx) {
          const int cx = ci[0] + dx, cy = ci[1] + dy, cz = ci[2] + dz;
          if (cx < 0 || cy < 0 || cz < 0 || cx >= dims[0] || cy >= dims[1] || cz >= dims[2]) continue;
          const std::size_t cell = (static_cast<std::size_t>(cz) * dims[1] + cy) * dims[0] + cx;
          for (int q = cell_start[cell]; q < cell_start[cell + 1]; ++q) {
            const int j = cell_items[q];
            if (j == i) continue;
            double r2 = 0;
            for (int c = 0; c < d; ++c)
              r2 += (p.x[j * d + c] - p.x[i * d + c]) * (p.x[j * d + c] - p.x[i * d + c]);
            if (r2 <= reach * reach) found.push_back(j);
          }
        }
    std::sort(found.begin(), found.end());
    append_family(b, p, i, found, delta[i], influence);
    b.offsets[i + 1] = static_cast<int>(b.neighbor.size());
  }
  return b;
}

Bonds find_block_bonds(const Particles& p, const std::vector<double>& delta,
                       const std::vector<double>& spacing, Quadrature q,
                       double (*influence)(double, double)) {
  if (q == Quadrature::Volume) return find_bonds_per_particle(p, delta, influence);
  if (q != Quadrature::PartialLinear)
    throw std::invalid_argument("a body of blocks supports quadrature: volume or partial_linear");
  if (spacing.size() != delta.size())
    throw std::invalid_argument("find_block_bonds: one spacing per particle");
  const int d = p.dim;
  // Search out to delta_i + h_max / 2, the farthest a cell of any block can still reach in.
  const double half = 0.5 * *std::max_element(spacing.begin(), spacing.end());
  std::vector<double> reach(delta);
  for (double& r : reach) r += half;
  const Bonds all = find_bonds_per_particle(p, reach, influence);
  Bonds b;
  b.dim = d;
  b.offsets.assign(all.offsets.size(), 0);
  b.delta = delta;
  for (int i = 0; i < all.particle_count(); ++i) {
    for (int k = all.offsets[i]; k < all.offsets[i + 1]; ++k) {
      const int j = all.neighbor[k];
      const double f = linear_volume_factor(all.length[k], delta[i], spacing[j]);
      if (f <= 0.0) continue;
      b.neighbor.push_back(j);
      for (int c = 0; c < d; ++c) b.xi.push_back(all.xi[static_cast<std::size_t>(k) * d + c]);
      b.length.push_back(all.length[k]);
      b.w.push_back(influence(std::min(all.length[k], delta[i]), delta[i]));
      b.alpha.push_back(1.0);
      b.volume_factor.push_back(f);
    }
    b.offsets[i + 1] = static_cast<int>(b.neighbor.size());
  }
  return b;
}

}  // namespace pd

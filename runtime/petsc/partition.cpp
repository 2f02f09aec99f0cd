// Morton order, block ownership, ghost layer and the per-row preallocation counts.
#include "petsc/partition.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <stdexcept>

namespace pd {

namespace {
// Spreads the low 21 bits of v so that two (3D) zero bits follow each one; in 2D the
// same spreading with one zero bit.
std::uint64_t spread(std::uint64_t v, int dim) {
  std::uint64_t out = 0;
  for (int b = 0; b < 21; ++b) out |= ((v >> b) & 1u) << (b * dim);
  return out;
}
}  // namespace

ParticleOrder morton_order(const Particles& particles) {
  const int n = particles.size(), d = particles.dim;
  double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
  for (int c = 0; c < d; ++c) lo[c] = hi[c] = n > 0 ? particles.position(0)[c] : 0.0;
  for (int p = 0; p < n; ++p)
    for (int c = 0; c < d; ++c)
      lo[c] = std::min(lo[c], particles.position(p)[c]), hi[c] = std::max(hi[c], particles.position(p)[c]);
  double extent = 0;
  for (int c = 0; c < d; ++c) extent = std::max(extent, hi[c] - lo[c]);
  // One cube over the whole body keeps the curve's cells square: a flat body does not
  // get cells stretched along its short side.
  const double scale = extent > 0 ? ((1u << 21) - 1) / extent : 0.0;
  std::vector<std::uint64_t> key(static_cast<std::size_t>(n));
  for (int p = 0; p < n; ++p) {
    std::uint64_t k = 0;
    for (int c = 0; c < d; ++c) {
      const auto q = static_cast<std::uint64_t>(std::llround((particles.position(p)[c] - lo[c]) * scale));
      k |= spread(q, d) << c;
    }
    key[p] = k;
  }
  ParticleOrder o;
  o.order.resize(static_cast<std::size_t>(n));
  std::iota(o.order.begin(), o.order.end(), 0);
  // Ties (coincident keys) by model id: the order is the same on every rank.
  std::stable_sort(o.order.begin(), o.order.end(), [&](int a, int b) { return key[a] < key[b]; });
  o.position.resize(static_cast<std::size_t>(n));
  for (int k = 0; k < n; ++k) o.position[o.order[k]] = k;
  return o;
}

Partition make_partition(const Particles& particles, const Bonds& bonds, int rank, int ranks) {
  if (ranks < 1 || rank < 0 || rank >= ranks) throw std::invalid_argument("make_partition: bad rank");
  Partition part;
  part.rank = rank, part.ranks = ranks;
  part.order = morton_order(particles);
  const int n = particles.size(), base = n / ranks, extra = n % ranks;
  part.begin = rank * base + std::min(rank, extra);
  part.end = part.begin + base + (rank < extra ? 1 : 0);
  std::vector<char> seen(static_cast<std::size_t>(n), 0);
  for (int i = 0; i < part.owned(); ++i) {
    const int p = part.owned_particle(i);
    for (int b = bonds.offsets[p]; b < bonds.offsets[p + 1]; ++b) {
      const int q = bonds.neighbor[b];
      if (!seen[q] && !part.owns(q)) seen[q] = 1, part.ghosts.push_back(q);
    }
  }
  std::sort(part.ghosts.begin(), part.ghosts.end(),
            [&](int a, int b) { return part.order.position[a] < part.order.position[b]; });
  return part;
}

void block_row_counts(const Partition& part, const Bonds& bonds, Coupling coupling,
                      std::vector<int>& diagonal, std::vector<int>& off) {
  const int n = bonds.particle_count();
  diagonal.assign(static_cast<std::size_t>(part.owned()), 0);
  off.assign(static_cast<std::size_t>(part.owned()), 0);
  std::vector<int> stamp(static_cast<std::size_t>(n), -1);
  for (int i = 0; i < part.owned(); ++i) {
    const int row = part.owned_particle(i);
    const auto visit = [&](int q) {
      if (stamp[q] == i) return;
      stamp[q] = i;
      (part.owns(q) ? diagonal[i] : off[i]) += 1;
    };
    // Families are symmetric (a bond is in both its particles' families): the families
    // holding `row` are its own and those of its neighbours.
    const auto family = [&](int f) {
      visit(f);
      for (int b = bonds.offsets[f]; b < bonds.offsets[f + 1]; ++b) visit(bonds.neighbor[b]);
    };
    family(row);
    if (coupling == Coupling::pairwise) continue;  // T_ik = 0 for i != k: no two-horizon blocks
    for (int b = bonds.offsets[row]; b < bonds.offsets[row + 1]; ++b) family(bonds.neighbor[b]);
  }
}

}  // namespace pd

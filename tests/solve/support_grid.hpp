// Test bodies: small perturbed lattices with brute-force families, optional broken bonds.
#pragma once

#include <cmath>
#include <random>
#include <vector>

#include "particles.hpp"

namespace pd::test {

struct Body {
  Particles particles;
  Bonds bonds;
};

// nx x ny (x nz) lattice of spacing h, points jittered by up to `jitter`*h (seeded),
// horizon delta = ratio*h, influence w = 1 - r/(2 delta) (not constant, so a wrong
// weight shows), every `break_every`-th bond pair broken (0: none).
inline Body make_grid(int dim, int nx, int ny, int nz, double ratio, double jitter = 0.0, int break_every = 0,
                      unsigned seed = 7) {
  Body b;
  const double h = 0.1, delta = ratio * h;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  Particles& P = b.particles;
  P.dim = dim;
  for (int k = 0; k < (dim == 3 ? nz : 1); ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        P.x.push_back(i * h + jitter * h * U(rng));
        P.x.push_back(j * h + jitter * h * U(rng));
        if (dim == 3) P.x.push_back(k * h + jitter * h * U(rng));
        P.volume.push_back(std::pow(h, dim) * (1.0 + 0.1 * U(rng)));
        P.material.push_back(0);
      }
  const int n = P.size();
  Bonds& B = b.bonds;
  B.dim = dim;
  B.offsets.push_back(0);
  for (int p = 0; p < n; ++p) {
    for (int q = 0; q < n; ++q) {
      if (q == p) continue;
      double r2 = 0;
      for (int c = 0; c < dim; ++c)
        r2 += (P.x[q * dim + c] - P.x[p * dim + c]) * (P.x[q * dim + c] - P.x[p * dim + c]);
      if (r2 > delta * delta) continue;
      const double r = std::sqrt(r2);
      B.neighbor.push_back(q);
      for (int c = 0; c < dim; ++c) B.xi.push_back(P.x[q * dim + c] - P.x[p * dim + c]);
      B.length.push_back(r);
      B.w.push_back(1.0 - r / (2 * delta));
      // Break the pair symmetrically: decided by the unordered pair.
      const int lo = p < q ? p : q, hi = p < q ? q : p;
      B.alpha.push_back(break_every > 0 && (lo * 31 + hi) % break_every == 0 ? 0.0 : 1.0);
    }
    B.offsets.push_back(static_cast<int>(B.neighbor.size()));
    B.delta.push_back(delta);
  }
  return b;
}

}  // namespace pd::test

// The full family of an infinite lattice, lattice_family.hpp.
#include "discretize/lattice_family.hpp"

#include <algorithm>
#include <cmath>

#include "discretize/partial_volume.hpp"

namespace pd {

LatticeFamily::LatticeFamily(Quadrature quadrature, double delta, double h, int dim,
                             double (*influence)(double r, double delta), double stretch,
                             int scratch_per_bond) {
  const double reach = quadrature_reach(quadrature, delta, h, dim);
  const int m = static_cast<int>(std::ceil(reach / h)) + 1;
  const double cell = std::pow(h, dim);
  int idx[3] = {-m, -m, dim == 3 ? -m : 0};
  const int last3 = dim == 3 ? m : 0;
  for (idx[0] = -m; idx[0] <= m; ++idx[0])
    for (idx[1] = -m; idx[1] <= m; ++idx[1])
      for (idx[2] = dim == 3 ? -m : 0; idx[2] <= last3; ++idx[2]) {
        double x[3] = {idx[0] * h, idx[1] * h, idx[2] * h}, r2 = 0;
        for (int c = 0; c < dim; ++c) r2 += x[c] * x[c];
        if (r2 == 0 || r2 > reach * reach * (1 + 1e-12)) continue;
        const double f = volume_factor(quadrature, x, dim, delta, h);
        if (f <= 0) continue;
        const double r = std::sqrt(r2);
        for (int c = 0; c < dim; ++c) xi.push_back(x[c]), Y.push_back(x[c] * (1 + stretch));
        w.push_back(influence(std::min(r, delta), delta));
        alpha.push_back(1.0);
        V.push_back(cell * f);
        ++n;
      }
  scratch.resize(static_cast<std::size_t>(n) * scratch_per_bond);
}

abi::Family LatticeFamily::family(double V0, double delta, const double* params) {
  abi::Family f;
  f.n_bonds = n, f.xi = xi.data(), f.Y = Y.data(), f.w = w.data(), f.alpha = alpha.data(), f.V = V.data();
  f.V0 = V0, f.delta = delta, f.params = params, f.scratch = scratch.data();
  return f;
}

}  // namespace pd

// The peridynamic stress (paper 002 eq. 2.12-2.13), peridynamic_stress.hpp.
#include "assembly/peridynamic_stress.hpp"

#include <fmt/core.h>

#include <cmath>
#include <cstddef>
#include <stdexcept>

#include "assembly/family_gather.hpp"

namespace pd {

std::vector<double> peridynamic_stress(const FamilyAssembler& assembler, const double* u) {
  const FamilyInputs& in = assembler.inputs();
  const Particles& p = *in.particles;
  const Bonds& bonds = *in.bonds;
  const int n = p.size(), d = p.dim, dd = d * d;
  std::vector<double> sigma(static_cast<std::size_t>(n) * dd, 0.0);
  FamilyGather gather(in);
  std::vector<double> forces(static_cast<std::size_t>(gather.max_bonds() + 1) * d);
  for (int q = 0; q < n; ++q) {
    const abi::Family fam = gather.gather(q, u);
    if (!has_intact_bond(fam)) continue;  // cut free by damage: no bond force
    assembler.variant().residual(fam, forces.data());
    for (int e = bonds.offsets[q], k = 1; e < bonds.offsets[q + 1]; ++e, ++k) {
      const int j = bonds.neighbor[e];
      const double* F = forces.data() + static_cast<std::ptrdiff_t>(k) * d;  // -V_q V_j t_q<j>
      const double* xi = bonds.xi.data() + static_cast<std::ptrdiff_t>(e) * d;
      // t_q<j> enters sigma_q as +1/2 V_j t (x) xi_qj and sigma_j as -1/2 V_q (-t) (x) xi_qj
      // (f_jq = t_j<q> - t_q<j>, xi_jq = -xi_qj): the same tensor, weighted by the other end.
      for (int a = 0; a < d; ++a)
        for (int b = 0; b < d; ++b) {
          const double half = -0.5 * F[a] * xi[b];  // 1/2 V_q V_j t_a xi_b
          sigma[static_cast<std::size_t>(q) * dd + a * d + b] += half / p.volume[q];
          sigma[static_cast<std::size_t>(j) * dd + a * d + b] += half / p.volume[j];
        }
    }
  }
  for (int i = 0; i < n; ++i)
    for (int c = 0; c < dd; ++c)
      if (!std::isfinite(sigma[static_cast<std::size_t>(i) * dd + c]))
        throw std::runtime_error(fmt::format("the peridynamic stress is not finite at particle {} (law {})",
                                             i, assembler.law().name));
  return sigma;
}

void family_stress(abi::ResidualKernel residual, const abi::Family& family, int dim, double* forces,
                   double* sigma) {
  residual(family, forces);
  for (int c = 0; c < dim * dim; ++c) sigma[c] = 0;
  for (int k = 0; k < family.n_bonds; ++k) {
    const double* F = forces + static_cast<std::ptrdiff_t>(k + 1) * dim;  // -V_0 V_k t_0<k>
    const double* xi = family.xi + static_cast<std::ptrdiff_t>(k) * dim;
    for (int a = 0; a < dim; ++a)
      for (int b = 0; b < dim; ++b) sigma[a * dim + b] -= F[a] * xi[b] / family.V0;
  }
}

}  // namespace pd

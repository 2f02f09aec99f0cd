// The boundary compensation factor (paper 002 eqs. 3.59-3.62), compensation.hpp.
#include "discretize/compensation.hpp"

#include <fmt/core.h>

#include <cmath>
#include <cstddef>
#include <map>
#include <stdexcept>

#include "assembly/family_gather.hpp"
#include "discretize/partial_volume.hpp"

namespace pd {

namespace {
// The trial energy density of one family: moments from the family itself, then W.
double trial_energy(const abi::LawDescriptor& law, abi::Family f, std::vector<double>& moments) {
  moments.assign(static_cast<std::size_t>(law.n_moments), 0.0);
  if (law.n_moments > 0) law.intact.moments(f, moments.data());
  f.moments = law.n_moments > 0 ? moments.data() : nullptr;
  return law.intact.energy(f);
}

// The full family of a particle of volume V0 in an infinite lattice of spacing h: every
// offset within the quadrature's reach with a positive factor, as find_quadrature_bonds.
struct FullFamily {
  std::vector<double> xi, Y, w, alpha, V, scratch;
  int n = 0;
  FullFamily(const CompensationInputs& in, int dim, double stretch, int scratch_per_bond) {
    const double reach = quadrature_reach(in.quadrature, in.delta, in.h, dim);
    const int m = static_cast<int>(std::ceil(reach / in.h)) + 1;
    const double cell = std::pow(in.h, dim);
    int idx[3] = {-m, -m, dim == 3 ? -m : 0};
    const int last3 = dim == 3 ? m : 0;
    for (idx[0] = -m; idx[0] <= m; ++idx[0])
      for (idx[1] = -m; idx[1] <= m; ++idx[1])
        for (idx[2] = dim == 3 ? -m : 0; idx[2] <= last3; ++idx[2]) {
          double x[3] = {idx[0] * in.h, idx[1] * in.h, idx[2] * in.h}, r2 = 0;
          for (int c = 0; c < dim; ++c) r2 += x[c] * x[c];
          if (r2 == 0 || r2 > reach * reach * (1 + 1e-12)) continue;
          const double f = volume_factor(in.quadrature, x, dim, in.delta, in.h);
          if (f <= 0) continue;
          const double r = std::sqrt(r2);
          for (int c = 0; c < dim; ++c) xi.push_back(x[c]), Y.push_back(x[c] * (1 + stretch));
          w.push_back(in.influence(std::min(r, in.delta), in.delta));
          alpha.push_back(1.0);
          V.push_back(cell * f);
          ++n;
        }
    scratch.resize(static_cast<std::size_t>(n) * scratch_per_bond);
  }
  abi::Family family(double V0, double delta, const double* params) {
    abi::Family f;
    f.n_bonds = n, f.xi = xi.data(), f.Y = Y.data(), f.w = w.data(), f.alpha = alpha.data(), f.V = V.data();
    f.V0 = V0, f.delta = delta, f.params = params, f.scratch = scratch.data();
    return f;
  }
};
}  // namespace

std::vector<double> compensation_factors(const Particles& p, const Bonds& b, const CompensationInputs& in) {
  const abi::LawDescriptor& law = *in.law;
  if (law.intact.energy == nullptr)
    throw std::invalid_argument(fmt::format("law {} has no energy kernel: the compensation factor is a ratio of energy "
                                            "densities (paper 002 eq. 3.61)", law.name));
  const int d = p.dim, n = p.size();
  FullFamily full(in, d, in.stretch, law.scratch_per_bond);
  std::vector<double> moments;
  std::map<std::pair<int, double>, double> w_inf;  // (material, V0) -> W of the full family
  FamilyInputs fi;
  fi.particles = &p, fi.bonds = &b, fi.params = *in.params, fi.scratch_per_bond = law.scratch_per_bond;
  FamilyGather gather(fi);
  std::vector<double> u(p.x.size());
  for (std::size_t i = 0; i < u.size(); ++i) u[i] = in.stretch * p.x[i];
  std::vector<double> beta(static_cast<std::size_t>(n), 1.0);
  for (int i = 0; i < n; ++i) {
    const int mat = p.material[i];
    const double* params = (*in.params)[static_cast<std::size_t>(mat)].data();
    const auto key = std::make_pair(mat, p.volume[i]);
    auto it = w_inf.find(key);
    if (it == w_inf.end()) it = w_inf.emplace(key, trial_energy(law, full.family(p.volume[i], in.delta, params), moments)).first;
    const double truncated = trial_energy(law, gather.gather(i, u.data()), moments);
    if (!(truncated > 0) || !std::isfinite(truncated) || !(it->second > 0) || !std::isfinite(it->second))
      throw std::runtime_error(fmt::format("compensation factor: the trial energy of particle {} is {:.6g} (full horizon "
                                           "{:.6g}; law {}): not a positive number", i, truncated, it->second, law.name));
    beta[static_cast<std::size_t>(i)] = it->second / truncated;
  }
  return beta;
}

void apply_compensation(Bonds& b, const std::vector<double>& beta) {
  if (b.volume_factor.empty()) b.volume_factor.assign(b.neighbor.size(), 1.0);
  for (int i = 0; i < b.particle_count(); ++i)
    for (int e = b.offsets[i]; e < b.offsets[i + 1]; ++e)
      b.volume_factor[e] *= 0.5 * (beta[static_cast<std::size_t>(i)] + beta[static_cast<std::size_t>(b.neighbor[e])]);
}

}  // namespace pd

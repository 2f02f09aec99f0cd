// The boundary compensation factor (paper 002 eqs. 3.59-3.62), compensation.hpp.
#include "assembly/compensation.hpp"

#include <fmt/core.h>

#include <cmath>
#include <cstddef>
#include <map>
#include <stdexcept>

#include "assembly/family_gather.hpp"
#include "discretize/lattice_family.hpp"

namespace pd {

namespace {
// The trial energy density of one family: moments from the family itself, then W.
double trial_energy(const abi::LawDescriptor& law, abi::Family f, std::vector<double>& moments) {
  moments.assign(static_cast<std::size_t>(law.n_moments), 0.0);
  if (law.n_moments > 0) law.intact.moments(f, moments.data());
  f.moments = law.n_moments > 0 ? moments.data() : nullptr;
  return law.intact.energy(f);
}
}  // namespace

std::vector<double> compensation_factors(const Particles& p, const Bonds& b, const CompensationInputs& in) {
  const abi::LawDescriptor& law = *in.law;
  if (law.intact.energy == nullptr)
    throw std::invalid_argument(
        fmt::format("law {} has no energy kernel: the compensation factor is a ratio of energy "
                    "densities (paper 002 eq. 3.61)",
                    law.name));
  const int d = p.dim, n = p.size();
  LatticeFamily full(in.quadrature, in.delta, in.h, d, in.influence, in.stretch, law.scratch_per_bond);
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
    if (it == w_inf.end())
      it = w_inf.emplace(key, trial_energy(law, full.family(p.volume[i], in.delta, params), moments)).first;
    const double truncated = trial_energy(law, gather.gather(i, u.data()), moments);
    if (!(truncated > 0) || !std::isfinite(truncated) || !(it->second > 0) || !std::isfinite(it->second))
      throw std::runtime_error(
          fmt::format("compensation factor: the trial energy of particle {} is {:.6g} (full horizon "
                      "{:.6g}; law {}): not a positive number",
                      i, truncated, it->second, law.name));
    beta[static_cast<std::size_t>(i)] = it->second / truncated;
  }
  return beta;
}

void apply_compensation(Bonds& b, const std::vector<double>& beta) {
  if (b.volume_factor.empty()) b.volume_factor.assign(b.neighbor.size(), 1.0);
  for (int i = 0; i < b.particle_count(); ++i)
    for (int e = b.offsets[i]; e < b.offsets[i + 1]; ++e)
      b.volume_factor[e] *=
          0.5 * (beta[static_cast<std::size_t>(i)] + beta[static_cast<std::size_t>(b.neighbor[e])]);
}

}  // namespace pd

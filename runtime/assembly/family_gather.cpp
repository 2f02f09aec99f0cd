// Family gathering: deformed bonds from the displacement, neighbour volumes, parameters.
#include "assembly/family_gather.hpp"

#include <algorithm>
#include <cstddef>
#include <stdexcept>

namespace pd {

int FamilyInputs::max_family_size() const {
  if (max_bonds >= 0) return max_bonds;
  int m = 0;
  for (int p = 0; p < bonds->particle_count(); ++p) m = std::max(m, bonds->family_size(p));
  return m;
}

FamilyGather::FamilyGather(const FamilyInputs& inputs) : in_(&inputs), max_bonds_(inputs.max_family_size()) {
  const auto d = static_cast<std::size_t>(inputs.dim()), L = static_cast<std::size_t>(max_bonds_);
  Y_.resize(L * d);
  V_.resize(L);
  local_in_.resize((L + 1) * d);
  local_out_.resize((L + 1) * d);
  scratch_.resize(L * static_cast<std::size_t>(inputs.scratch_per_bond));
  // The dense local matrix is only needed for the tangent; it is (L+1)^2 d^2 doubles
  // (46 kB at 36 bonds in 2D, 1.2 MB at 122 bonds in 3D), allocated once per thread.
  local_matrix_.resize((L + 1) * d * (L + 1) * d);
}

abi::Family FamilyGather::gather(int p, const double* u) {
  const Particles& P = *in_->particles;
  const Bonds& B = *in_->bonds;
  const int d = P.dim, b0 = B.offsets[p], L = B.family_size(p);
  for (int k = 0; k < L; ++k) {
    const int q = B.neighbor[b0 + k];
    V_[k] = in_->collocation          ? in_->collocation->weight[b0 + k]
            : B.volume_factor.empty() ? P.volume[q]
                                      : P.volume[q] * B.volume_factor[b0 + k];
    const double* xi = B.xi.data() + static_cast<std::ptrdiff_t>(b0 + k) * d;
    if (u == nullptr) {
      for (int c = 0; c < d; ++c) Y_[k * d + c] = xi[c];
    } else {
      const double* uq = u + static_cast<std::ptrdiff_t>(q) * d;
      const double* up = u + static_cast<std::ptrdiff_t>(p) * d;
      // Y = xi + u_q - u_p rather than y_q - y_p: the small-displacement difference is
      // formed first, so the bond stretch keeps its digits.
      for (int c = 0; c < d; ++c) Y_[k * d + c] = xi[c] + (uq[c] - up[c]);
    }
  }
  abi::Family f;
  f.n_bonds = L;
  f.xi = B.xi.data() + static_cast<std::ptrdiff_t>(b0) * d;
  f.Y = Y_.data();
  f.w = B.w.data() + b0;
  f.alpha = B.alpha.data() + b0;
  f.V = V_.data();
  f.V0 = P.volume[p];
  f.delta = B.delta[p];
  f.params = in_->params[static_cast<std::size_t>(P.material[p])].data();
  f.nbr_params = neighbour_params(
      in_->params, P.material[p], L, [&](int k) { return P.material[B.neighbor[b0 + k]]; }, nbr_params_);
  f.moments = in_->n_moments > 0 && !in_->moments.empty()
                  ? in_->moments.data() + static_cast<std::ptrdiff_t>(p) * in_->n_moments
                  : nullptr;
  f.scratch = scratch_.data();
  f.dilatation_factor = B.surface_dilatation.empty() ? nullptr : B.surface_dilatation.data() + b0;
  f.force_factor = B.surface_force.empty() ? nullptr : B.surface_force.data() + b0;
  f.history =
      in_->history == nullptr ? nullptr : in_->history + static_cast<std::ptrdiff_t>(b0) * in_->n_history;
  f.particle_history = in_->particle_history == nullptr
                           ? nullptr
                           : in_->particle_history + static_cast<std::ptrdiff_t>(p) * in_->n_particle_history;
  f.time_step = in_->time_step == nullptr ? 0.0 : *in_->time_step;
  return f;
}

bool has_intact_bond(const abi::Family& f) {
  for (int k = 0; k < f.n_bonds; ++k)
    if (f.alpha[k] != 0.0) return true;
  return false;
}

const double* FamilyGather::gather_local(int p, const double* global) {
  const int d = in_->dim(), L = in_->bonds->family_size(p);
  for (int a = 0; a <= L; ++a) {
    const double* src = global + static_cast<std::ptrdiff_t>(particle(p, a)) * d;
    for (int c = 0; c < d; ++c) local_in_[a * d + c] = src[c];
  }
  return local_in_.data();
}

}  // namespace pd

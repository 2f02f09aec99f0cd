// Fills the kernel ABI's per-family inputs from the global particle and bond arrays.
#pragma once

#include <algorithm>
#include <cstddef>
#include <span>
#include <vector>

#include "assembly/collocation.hpp"
#include "kernel_abi.hpp"
#include "particles.hpp"

namespace pd {

// What every family of a body shares: the cloud, its bonds, one parameter vector per
// material, and the per-particle moments (empty until compute_moments ran).
struct FamilyInputs {
  const Particles* particles = nullptr;
  const Bonds* bonds = nullptr;
  std::vector<std::vector<double>> params;  // [material][law.n_params]
  std::vector<double> moments;              // [n * n_moments]
  int n_moments = 0;
  int scratch_per_bond = 0;  // the law's LawDescriptor::scratch_per_bond
  int max_bonds = -1;        // largest family; -1 until cache_max_bonds() (then gathers skip the scan)
  // Set for collocation assembly: the families see per-bond quadrature weights as V.
  const Collocation* collocation = nullptr;
  // A law with memory: the committed per-bond history, [bonds * n_history] in bond order
  // (Family::history of particle p starts at bond offsets[p]); null: every bond virgin.
  const double* history = nullptr;
  int n_history = 0;
  // The committed per-particle history, [n * n_particle_history] (particle p's at
  // [p * n_particle_history]); null: every particle at the law's initial values.
  const double* particle_history = nullptr;
  int n_particle_history = 0;
  // A rate-dependent law (LawDescriptor::uses_time_step): the duration of the current step
  // every family reads (Family::time_step), owned by the caller (Model::step_duration); null: 0.
  const double* time_step = nullptr;

  int dim() const { return particles->dim; }
  int size() const { return particles->size(); }
  int max_family_size() const;
  void cache_max_bonds() { max_bonds = -1, max_bonds = max_family_size(); }
};

// One per thread. The buffers are sized once for the largest family, so gathering a
// family never allocates; the returned abi::Family points into them (and into the
// bond arrays) and stays valid until the next gather on this object.
class FamilyGather {
 public:
  explicit FamilyGather(const FamilyInputs& inputs);

  // Family of particle p at displacement u ([n*dim]; null = reference configuration).
  abi::Family gather(int p, const double* u);
  // Global particle index of local particle a (0 = center, a = k+1 for bond k).
  int particle(int p, int a) const {
    return a == 0 ? p : in_->bonds->neighbor[in_->bonds->offsets[p] + a - 1];
  }
  // Copies the entries of a global [n*dim] vector for the family's particles into a
  // local [(L+1)*dim] buffer owned by this object.
  const double* gather_local(int p, const double* global);
  // Scratch for a family's local vector or matrix; grows only the first time.
  double* local_vector() { return local_out_.data(); }
  double* local_matrix() { return local_matrix_.data(); }
  int max_bonds() const { return max_bonds_; }

 private:
  const FamilyInputs* in_;
  int max_bonds_;
  std::vector<double> Y_, V_, local_in_, local_out_, local_matrix_, scratch_, nbr_params_;
};

// Family::nbr_params of a family whose center has material `center` and whose bond k
// reaches a particle of material material_of(k): null when every neighbour has the
// center's material (the kernels then take the center's values, the same numbers), else
// `buffer` filled bond-major with each neighbour's parameter vector.
template <class MaterialOf>
const double* neighbour_params(const std::vector<std::vector<double>>& params, int center, int n_bonds,
                               MaterialOf material_of, std::vector<double>& buffer) {
  if (params.size() < 2) return nullptr;
  int k = 0;
  while (k < n_bonds && material_of(k) == center) ++k;
  if (k == n_bonds) return nullptr;
  const std::size_t n = params[static_cast<std::size_t>(center)].size();
  buffer.resize(static_cast<std::size_t>(n_bonds) * n);
  for (k = 0; k < n_bonds; ++k) {
    const std::vector<double>& q = params[static_cast<std::size_t>(material_of(k))];
    std::copy(q.begin(), q.end(), buffer.begin() + static_cast<std::ptrdiff_t>(k * n));
  }
  return buffer.data();
}

// False when every bond of the family is broken (alpha = 0 for all; also for a family
// with no bonds). Such a family carries no force and no stiffness, since every law weights
// its bond's force state by the bond's alpha (the law test BrokenBondsCarryNoForce holds
// each law to it), so its kernels are not evaluated: state-based laws divide by sums over
// intact bonds (LPS's weighted volume, the shape tensor) and would give 0/0 for a particle
// that damage has cut free.
bool has_intact_bond(const abi::Family& f);

}  // namespace pd

// Effects: the physics a scene calls for besides the law's internal forces (loads, crack
// pressure, body forces from a field, damage evolution, inertia, damping). Each is a
// separate object created only when the scene needs it, so an effect that is off costs
// nothing; a new one is one file (docs/runtime.md, "Adding an effect").
//
// Vectors are particle-major [n * dim]; r is the out-of-balance force (internal plus
// external: zero at equilibrium) and K = -dr/du, the solver's sign (docs/conventions.md).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "assembly/sparsity_pattern.hpp"

namespace pd {

// The families an after_step may change: every family (one process holds the whole body),
// or the families of the particles this process owns (an MPI rank holds u only at its own
// particles and their ghosts; each family is changed by its owner, and the owners' results
// are what rank 0 gathers).
struct FamilyScope {
  const std::vector<int>* owned = nullptr;  // null: every family
  bool every_family() const { return owned == nullptr; }
};

class Effect {
 public:
  virtual ~Effect() = default;
  virtual std::string name() const = 0;      // e.g. "external loads"
  virtual std::string describe() const = 0;  // one line for the run log and summary.json
  // Bytes it holds per run (its force vector, pair list, mass array): what turning it on costs.
  virtual std::size_t allocated_bytes() const { return 0; }
  // Adds this effect's nodal forces at load factor `load` to r (nothing by default).
  virtual void add_forces(const double* u, double load, double* r) const;
  // Adds its contribution to K = -dr/du, whose pattern is `pattern` (nothing for dead loads).
  virtual void add_stiffness(const double* u, double load, const SparsityPattern& pattern,
                             SparseMatrix& K) const;
  // Matrix-free counterparts: Kv += K_effect v, diag += diag(K_effect).
  virtual void add_stiffness_product(const double* u, double load, const double* v, double* Kv) const;
  virtual void add_stiffness_diagonal(const double* u, double load, double* diag) const;
  virtual bool symmetric() const { return true; }
  // True for the effects that load the body (forces at load factor 1 that are not zero
  // at u = 0): a static run without any, and without prescribed motion, has u = 0.
  virtual bool is_load() const { return false; }
  // Called with the solution of every converged step (a static load step, a time step,
  // a relaxation iteration); returns how many changes it made to the model (bonds
  // broken). Non-zero: a static run solves the same load step again. `scope`: the
  // families it may change (u is current at their particles and bonds' ends).
  virtual long long after_step(const double* u, FamilyScope scope);
};

}  // namespace pd

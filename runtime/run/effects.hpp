// Effects: the physics a scene calls for besides the law's internal forces. Each is a
// separate object created only when the scene needs it (see make_effects), so an
// effect that is off costs nothing. New effects (inertia, damping, damage evolution)
// implement this interface without touching the existing ones.
//
// Vectors are particle-major [n * dim]; r is the out-of-balance force (internal plus
// external: zero at equilibrium) and K = -dr/du, the solver's sign (docs/conventions.md).
#pragma once

#include <memory>
#include <span>
#include <string>
#include <vector>

#include "assembly/sparsity_pattern.hpp"
#include "input/scene.hpp"
#include "particles.hpp"

namespace pd {

class Effect {
 public:
  virtual ~Effect() = default;
  virtual std::string name() const = 0;      // e.g. "tractions"
  virtual std::string describe() const = 0;  // one line for the run log
  // Adds this effect's nodal forces at load factor `load` to r.
  virtual void add_forces(const double* u, double load, double* r) const = 0;
  // Adds its contribution to K = -dr/du, whose pattern is `pattern` (nothing for dead loads).
  virtual void add_stiffness(const double* u, double load, const SparsityPattern& pattern, SparseMatrix& K) const;
  // Matrix-free counterparts: Kv += K_effect v, diag += diag(K_effect).
  virtual void add_stiffness_product(const double* u, double load, const double* v, double* Kv) const;
  virtual void add_stiffness_diagonal(const double* u, double load, double* diag) const;
  virtual bool symmetric() const { return true; }
};

// Dead loads given as a nodal force vector [n * dim] at full load.
std::unique_ptr<Effect> make_nodal_forces(std::vector<double> f, std::string description);

// Dead loads: tractions on boundary particles (paper 000 eq. 34: the total force T x
// face measure shared equally by the region's particles) and body forces (per volume).
std::unique_ptr<Effect> make_external_loads(const Scene& scene, const Particles& p);
// The same for some of the scene's conditions only (a dynamic run scales each by its own
// function of time); the others in `conditions` are skipped.
std::unique_ptr<Effect> make_external_loads(const Scene& scene, const Particles& p,
                                            std::span<const BoundaryCondition> conditions);

// Crack pressure on the broken bonds between nearest neighbours across a crack
// (paper 000 eqs. 23, 30): a pair force of magnitude p V / |xi| along the deformed
// bond, pushing the two particles apart (p h per face particle for |xi| = h in 2D). On a
// perturbed cloud the pair forces are scaled so the total normal load on each face is
// still p x crack length (area in 3D); on the paper's lattice the scale is exactly 1.
// One effect for all the pressurised cracks given; h: the particle spacing (the pairs
// are the nearest neighbours, |xi| < 1.2 h, whose bond the crack crosses). Reads the
// bonds and particles without copying them.
std::unique_ptr<Effect> make_crack_pressure(std::span<const Crack> cracks, double h, const Particles& p,
                                            const Bonds& bonds);
std::unique_ptr<Effect> make_crack_pressure(const Scene& scene, const Particles& p, const Bonds& bonds);

}  // namespace pd

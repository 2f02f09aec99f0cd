// The force operator: what the solvers, effects and outputs ask of a discretised law,
// whatever the quadrature integrates the families over.
//
// Two operators implement it: FamilyAssembler (assembler.hpp), the families over their
// bonds (volume rules, partial volumes, OBQ collocation), and GaussPointAssembler
// (gauss_point_assembler.hpp), the families over fixed Gauss points mapped to the nodes by
// MLS shape functions (paper 002 §3.3). make_force_operator is the one place that chooses;
// nothing above this layer branches on the quadrature.
//
// Signs (docs/conventions.md): forces are the kernel's nodal forces f, summed over
// families; the stiffness is the solver's K = -df/du; the product and diagonal are those
// of K. All vectors are [n*dim], particle-major; u null means zero displacement.
#pragma once

#include <memory>
#include <vector>

#include "assembly/sparsity_pattern.hpp"
#include "kernel_abi.hpp"
#include "particles.hpp"

namespace pd {

class FamilyAssembler;
struct AssemblerOptions;

class ForceOperator {
 public:
  virtual ~ForceOperator() = default;

  // Recompute the moments (after bond factors alpha changed).
  virtual void update_moments() = 0;
  // OpenMP threads of one pass (0: OpenMP's default, or one thread on small bodies).
  virtual void set_threads(int threads) = 0;

  // forces (may be null) overwritten with f(u); K (may be null) overwritten with -df/du in
  // pattern().
  virtual void assemble(const double* u, double* forces, SparseMatrix* K) const = 0;
  void internal_forces(const double* u, double* forces) const { assemble(u, forces, nullptr); }
  void stiffness(const double* u, SparseMatrix& K, double* forces = nullptr) const {
    assemble(u, forces, &K);
  }
  // Kv = K(u) v from the kernel's tangent-vector product: no matrix.
  virtual void stiffness_product(const double* u, const double* v, double* Kv) const = 0;
  // diag = diagonal of K(u): the Jacobi preconditioner of the matrix-free path.
  virtual void stiffness_diagonal(const double* u, double* diag) const = 0;
  // S_r >= sum_c |K_rc| for every dof r, at u (null: the reference configuration): the
  // row sums of the formed matrix for bond families, a bound formed without the matrix
  // for Gauss families. For the stable step and the fictitious density
  // (effects/time_step.hpp). Works without a matrix pattern.
  virtual std::vector<double> stiffness_row_sums(const double* u) const = 0;

  // Whether the forces are the gradient of strain_energy (false also means K is not
  // symmetric: the solver needs UMFPACK or GMRES then).
  virtual bool has_energy() const = 0;
  virtual bool symmetric() const = 0;
  // Strain energy sum_p V_p W_p(u); throws std::logic_error when has_energy() is false.
  virtual double strain_energy(const double* u) const = 0;
  // The law's per-particle outputs [n * law.n_outputs] (empty if the law has none).
  virtual std::vector<double> particle_outputs(const double* u) const = 0;
  // The peridynamic stress of every particle [n*dim*dim] (assembly/peridynamic_stress.hpp).
  virtual std::vector<double> stresses(const double* u) const = 0;

  // The assembly pattern; throws if the operator was built without one.
  virtual const SparsityPattern& pattern() const = 0;
  SparseMatrix make_matrix() const { return pattern().matrix(); }
  virtual const abi::LawDescriptor& law() const = 0;
  // The kernels it calls: law().intact or law().damaged.
  virtual const abi::KernelVariant& variant() const = 0;
  // True for the variant with alpha folded to 1 (no bond is broken).
  virtual bool intact() const = 0;
  virtual int dofs() const = 0;
  // The longest reference bond |xi| its kernels see: Y = xi + (u_q - u_p) is rounded
  // against it, so it sets the residual's rounding floor (solve/newton.hpp).
  virtual double longest_bond() const = 0;

  // The bond-family operator, or null: for what only bond families can do (break bonds,
  // the J-integral, the strain-mode check, the PETSc ranks' family loops). A caller that
  // gets null says that its feature does not run on this quadrature.
  virtual const FamilyAssembler* bond_families() const { return nullptr; }
  FamilyAssembler* bond_families() {
    return const_cast<FamilyAssembler*>(static_cast<const ForceOperator*>(this)->bond_families());
  }
};

// The checks both operators' constructors make: the law's dimension is the body's and every
// material has the law's parameters (std::invalid_argument naming `who` otherwise). Returns
// whether the law uses pair parameters and the particles' parameters differ (no potential then).
bool check_law_inputs(const Particles& particles, const abi::LawDescriptor& law,
                      const std::vector<std::vector<double>>& params, const char* who);

// op's bond families, or std::invalid_argument saying that `feature` runs on bond families only
// (not over Gauss points).
const FamilyAssembler& bond_families(const ForceOperator& op, const char* feature);

// The force operator of a law on a body: over options.gauss_points when they are set,
// over the bonds otherwise. params: one parameter vector per material (in the order of
// law.param_names). particles, bonds and everything options points to must outlive it.
std::unique_ptr<ForceOperator> make_force_operator(const Particles& particles, const Bonds& bonds,
                                                   const abi::LawDescriptor& law,
                                                   std::vector<std::vector<double>> params,
                                                   const AssemblerOptions& options);

}  // namespace pd

// The bond-family force operator: one law over all families, each integrated over its bonds.
#pragma once

#include <Eigen/Core>
#include <memory>
#include <optional>
#include <vector>

#include "assembly/family_colouring.hpp"
#include "assembly/family_gather.hpp"
#include "assembly/force_operator.hpp"
#include "assembly/sparsity_pattern.hpp"
#include "discretize/gauss_points.hpp"
#include "kernel_abi.hpp"
#include "particles.hpp"

namespace pd {

struct AssemblerOptions {
  bool intact = false;  // the variant with alpha folded to 1: only when no bond is broken
  bool matrix = true;   // build the sparsity pattern and slots (false: matrix-free use only)
  int threads = 0;      // 0: OpenMP's default
  int chunk_size = 0;   // 0: tiles of two horizons as colouring chunks; > 0: runs of this many family indices
  // Non-null: collocation assembly with these per-bond weights (collocation.hpp); the
  // stiffness is then not symmetric and there is no energy. Must outlive the assembler.
  const Collocation* collocation = nullptr;
  // The pattern's coupling; unset: the law's (coupling_of_law: pairwise for a law
  // without states). Coupling::family on a pairwise law stores its structural zeros
  // (the two-horizon pattern, for comparison); pairwise on a law with states throws.
  std::optional<Coupling> coupling;
  // Non-null: make_force_operator integrates the families over these fixed Gauss points
  // (paper 002 §3.3, gauss_point_assembler.hpp); FamilyAssembler refuses them. Must outlive the operator.
  const GaussPoints* gauss_points = nullptr;
  // A law with memory (LawDescriptor::n_history > 0): the committed per-bond history the
  // families read, [bonds * n_history] in bond order, owned by the caller (Model) and read
  // only; null: every bond at the law's initial values. Must outlive the assembler.
  const double* history = nullptr;
  // Likewise the committed per-particle history, [particles * n_particle_history].
  const double* particle_history = nullptr;
  // A rate-dependent law (LawDescriptor::uses_time_step): the duration of the current step,
  // read at every evaluation (the caller sets it before each step); null: 0. Must outlive it.
  const double* time_step = nullptr;
};

// A law's internal variables (LawDescriptor::n_history, n_particle_history): per bond in
// bond order, [bonds * n_history], and per particle, [particles * n_particle_history].
struct LawHistory {
  std::vector<double> bond;
  std::vector<double> particle;
  bool empty() const { return bond.empty() && particle.empty(); }
};

// One code path, assemble(), fills forces, K, or both: families are visited colour by
// colour (FamilyColouring) so no two threads touch the same entry, the local matrix is
// formed by pd::form_local_matrix and written straight into the family's precomputed
// slots. Results do not depend on the thread count, bit for bit.
//
// Every kernel output is checked before it is scattered; a NaN or Inf throws
// std::runtime_error naming the stage, the law and the particle (the lowest one if
// several families fail).
class FamilyAssembler final : public ForceOperator {
 public:
  // params: one parameter vector per material (Particles::material indexes it), in the
  // order of law.param_names. particles and bonds must outlive the assembler.
  FamilyAssembler(const Particles& particles, const Bonds& bonds, const abi::LawDescriptor& law,
                  std::vector<std::vector<double>> params, AssemblerOptions options = {});

  // Recompute the moments (after bond factors alpha changed).
  void update_moments() override;
  void set_threads(int threads) override { options_.threads = threads; }

  void assemble(const double* u, double* forces, SparseMatrix* K) const override;
  // Cost linear in the bonds.
  void stiffness_product(const double* u, const double* v, double* Kv) const override;
  // From the tangent factors in O(bonds).
  void stiffness_diagonal(const double* u, double* diag) const override;
  // The row sums of the formed matrix (a temporary operator with a pattern if this one has none).
  std::vector<double> stiffness_row_sums(const double* u) const override;
  // Strain energy sum_p V_p W_p(u) from the law's energy kernel; has_energy() false
  // (and this throws std::logic_error) when the law has none.
  // Collocation with symmetric pair weights (Collocation::pair_symmetric) is the energy
  // assembly with other weights, so it has both. Also false for a law with pair parameters
  // (LawDescriptor::uses_pair_params) on a body whose particles carry different parameters,
  // and with surface correction factors (Bonds::surface_force): the forces have no potential there.
  bool has_energy() const override { return variant_.energy != nullptr && symmetric(); }
  // False under collocation assembly with unsymmetric pair weights, for pair parameters across
  // a material jump and with surface correction: the solver needs UMFPACK or GMRES then.
  bool symmetric() const override {
    return (options_.collocation == nullptr || options_.collocation->pair_symmetric) && !pair_jump_ &&
           !surface_corrected();
  }
  bool surface_corrected() const { return !inputs_.bonds->surface_force.empty(); }
  double strain_energy(const double* u) const override;
  std::vector<double> particle_outputs(const double* u) const override;
  std::vector<double> stresses(const double* u) const override;
  // The history at the end of a step to displacement u: the law's update kernel on every
  // family (a family with no intact bond keeps its committed values). The committed history
  // (options.history, options.particle_history) is not touched: the caller commits the
  // result once the step has converged. Throws std::runtime_error naming the particle when
  // the update gives a NaN or Inf; empty for a law without history.
  LawHistory updated_history(const double* u) const;
  // d forces / d (material m's parameter i) at displacement u, the committed history held
  // fixed: column m * law.n_params + i of the [dofs x materials * n_params] column-major
  // result, from the law's sensitivity kernel on every family (each family's parameters are
  // its center's: a family feeds the columns of its center's material), scaled and scattered
  // as the forces are. Throws std::invalid_argument when the law has no sensitivity kernel,
  // when it reads pair parameters across a material jump (a bond's pair mean then moves
  // with both materials' values, which the kernel's contract does not cover), and with
  // surface correction (its factors are computed from the parameters and not differentiated).
  Eigen::MatrixXd parameter_sensitivities(const double* u) const;

  // Throws if options.matrix was false.
  const SparsityPattern& pattern() const override;
  const FamilyColouring& colouring() const { return colouring_; }
  const FamilyInputs& inputs() const { return inputs_; }
  const abi::LawDescriptor& law() const override { return law_; }
  const abi::KernelVariant& variant() const override { return variant_; }
  const AssemblerOptions& options() const { return options_; }
  bool intact() const override { return options_.intact; }
  int dofs() const override { return inputs_.size() * inputs_.dim(); }
  double longest_bond() const override;
  const FamilyAssembler* bond_families() const override { return this; }

 private:
  template <class Body>
  void for_each_family(const char* stage, Body&& body) const;
  int thread_count() const;  // OpenMP threads for one pass over the families

  const abi::LawDescriptor& law_;
  const abi::KernelVariant& variant_;
  AssemblerOptions options_;
  bool pair_jump_ = false;  // the law uses pair parameters and the particles' parameters differ
  FamilyInputs inputs_;
  FamilyColouring colouring_;
  std::unique_ptr<SparsityPattern> pattern_;
};

}  // namespace pd

// Assembly over Gauss-point families (discretize/gauss_points.hpp): the generated kernels
// on bonds to Gauss points, mapped to the nodes through the MLS shape functions.
//
// Family i's bond vectors are linear in its local nodal displacements: with the local
// nodes n_0 = i, n_1 < n_2 < ... (every node in the MLS support of one of its points),
//   Y_0 := y_i = u_i (+ x_i),   Y_k = xi_k + sum_a P[k][a] u_{n_a} - u_i,
// P[0][a] = delta_a0 and P[k][a] = phi_{n_a}(x_{g_k}). The kernel's local forces f_loc
// (center and points, kernel_abi.hpp) and local tangent M = d f_loc / d y_loc therefore give
//   nodal forces   f_nodes = P^T f_loc              (chain rule, exact),
//   nodal tangent  K_nodes = P^T M P                (P does not depend on u; formed from the
//                                                    tangent factors without M, gauss_point_gather.hpp),
//   product        K v     = P^T jvp(P v),
// and the stiffness couples every two nodes of {i} U supports: the sparsity pattern is the
// family pattern of those node sets (reach_bonds), wider than the bond one by r_w on each
// side.
//
// Threads: the force, product, energy and stress passes run the families colour by colour
// (FamilyColouring over the cells whose points each family holds: two families of one
// colour share no Gauss point, so their per-point rows never collide); the per-point rows
// are then mapped to the nodes (P^T) and the points' displacements gathered (P u) by
// loops that write one entry each. Every entry receives its contributions in an order
// fixed by the colouring alone: the results are bitwise the same for any thread count.
// The matrix and its diagonal scatter into the MLS nodes of a family (reach delta + h +
// r_w), which the point colouring does not separate: they stay on one thread.
#pragma once

#include <memory>
#include <mutex>
#include <vector>

#include "assembly/family_colouring.hpp"
#include "assembly/force_operator.hpp"
#include "assembly/sparsity_pattern.hpp"
#include "discretize/gauss_points.hpp"
#include "kernel_abi.hpp"
#include "particles.hpp"

namespace pd {

class GaussPointAssembler final : public ForceOperator {
 public:
  // gp and particles must outlive the assembler; params: one vector per material.
  GaussPointAssembler(const Particles& particles, const GaussPoints& gp, const abi::LawDescriptor& law,
                      const abi::KernelVariant& variant, std::vector<std::vector<double>> params, bool matrix,
                      int threads = 0);

  // OpenMP threads of the coloured passes (0: OpenMP's default).
  void set_threads(int threads) override { threads_ = threads; }

  void update_moments() override;
  // Forces overwritten with f(u) (may be null); K (may be null) with -df/du in pattern().
  void assemble(const double* u, double* forces, SparseMatrix* K) const override;
  void stiffness_product(const double* u, const double* v, double* Kv) const override;
  // The paper's collocation form, eq. (3.15), for a pairwise law (n_states == 0; throws
  // otherwise): node i's force is the sum of the pairwise forces f(u_g - u_i, x_g - x_i)
  // beta_g V_g over its own Gauss bonds, f = 2 t_i<g> (the kernel's force state is half the
  // pairwise force), and nothing is returned to the points' nodes. Not momentum-balanced and
  // not symmetric (docs/paper002.md measures both); for comparison with the variational
  // form above, not reachable from a scene.
  void collocation_forces(const double* u, double* forces) const;
  void stiffness_diagonal(const double* u, double* diag) const override;
  // No collocation or surface correction reaches the Gauss families (the scene refuses them):
  // only pair parameters across a material jump break the potential.
  bool symmetric() const override { return !pair_jump_; }
  bool has_energy() const override { return variant_.energy != nullptr && symmetric(); }
  double strain_energy(const double* u) const override;
  // An upper bound on the Gershgorin row sums S_r = sum_c |K_rc| of the stiffness at u (null:
  // the reference configuration), without forming K: per family, |P^T M P| <= sum_i |c_i|
  // |B_i|^T |D_i| |B_i| + sum_s |a_s| |b_s|^T entrywise (the factored tangent of
  // nodal_matrix), whose row sums cost O(L n_phi d) per family instead of the matrix's
  // O(L n_phi^2 d^2) and need no pattern. For the stable step of explicit dynamics
  // (effects/time_step.hpp): a larger S_r gives a smaller, still stable, step.
  std::vector<double> stiffness_row_sums(const double* u) const override;
  // W of particle p's Gauss family alone (the law's energy kernel; throws without one).
  double family_energy_density(int p, const double* u) const;
  std::vector<double> particle_outputs(const double* u) const override;
  // Pairwise force-state sum sigma_i of eq. (2.13) over the Gauss family (assembly/peridynamic_stress.hpp's
  // family_stress on each family): [n*dim*dim].
  std::vector<double> family_stresses(const double* u) const;
  // A Gauss point has no family of its own, so t_g<i> is not defined: each family's own half
  // doubled (family_stresses, t_g<i> = -t_i<g>) is eq. (2.13) for a homogeneous deformation.
  std::vector<double> stresses(const double* u) const override { return family_stresses(u); }

  const SparsityPattern& pattern() const override;
  const abi::LawDescriptor& law() const override { return law_; }
  const abi::KernelVariant& variant() const override { return variant_; }
  bool intact() const override { return &variant_ == &law_.intact; }
  // The node sets each family's tangent couples, as Bonds (neighbor: the local nodes
  // n_1.. ascending; the other arrays empty): what the pattern is built from.
  // Built on first use (the matrix, the diagonal): a few ints per coupled pair.
  const Bonds& reach_bonds() const;
  const GaussPoints& points() const { return *gp_; }
  int dofs() const override { return particles_->size() * particles_->dim; }
  // Every Gauss bond lies within its particle's horizon: the largest horizon bounds them.
  double longest_bond() const override;

 private:
  class Gather;
  template <class Body>
  void for_each_family(const char* stage, Body&& body) const;
  // The same over the colouring, on thread_count() threads (bodies that write the
  // family's own slot and its points' rows only).
  template <class Body>
  void for_each_family_coloured(const char* stage, Body&& body) const;
  int thread_count() const;
  void gather_points(const double* u, double* ug) const;
  std::vector<double> point_displacements(const double* u) const;  // gather_points, empty without u
  void add_mapped(const double* per_point, double scale, double* out) const;

  const Particles* particles_;
  const GaussPoints* gp_;
  const abi::LawDescriptor& law_;
  const abi::KernelVariant& variant_;
  std::vector<std::vector<double>> params_;
  std::vector<double> moments_;
  mutable Bonds reach_;
  mutable std::once_flag reach_once_;
  std::unique_ptr<SparsityPattern> pattern_;
  std::unique_ptr<FamilyColouring> colouring_;
  // Transpose of the MLS map: for node a, the entries e of phi with phi_node[e] == a,
  // ascending (the order the serial point loop added them in).
  std::vector<int> node_entry_start_, node_entry_, entry_point_;
  int threads_ = 0;
  bool pair_jump_ = false;  // the law uses pair parameters and the particles' parameters differ
};

}  // namespace pd

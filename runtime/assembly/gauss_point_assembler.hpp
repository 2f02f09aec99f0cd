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
//                                                    tangent factors without M, gauss_point_assembler.cpp),
//   product        K v     = P^T jvp(P v),
// and the stiffness couples every two nodes of {i} U supports: the sparsity pattern is the
// family pattern of those node sets (reach_bonds), wider than the bond one by r_w on each
// side. Families are visited in index order on one thread: a family's writes reach
// delta + h + r_w, so the node colouring of FamilyColouring does not separate them.
#pragma once

#include <memory>
#include <mutex>
#include <vector>

#include "assembly/sparsity_pattern.hpp"
#include "discretize/gauss_points.hpp"
#include "kernel_abi.hpp"
#include "particles.hpp"

namespace pd {

class GaussPointAssembler {
 public:
  // gp and particles must outlive the assembler; params: one vector per material.
  GaussPointAssembler(const Particles& particles, const GaussPoints& gp, const abi::LawDescriptor& law,
                      const abi::KernelVariant& variant, std::vector<std::vector<double>> params, bool matrix);

  void update_moments();
  // Forces overwritten with f(u) (may be null); K (may be null) with -df/du in pattern().
  void assemble(const double* u, double* forces, SparseMatrix* K) const;
  void stiffness_product(const double* u, const double* v, double* Kv) const;
  void stiffness_diagonal(const double* u, double* diag) const;
  double strain_energy(const double* u) const;
  // W of particle p's Gauss family alone (the law's energy kernel; throws without one).
  double family_energy_density(int p, const double* u) const;
  std::vector<double> particle_outputs(const double* u) const;
  // Pairwise force-state sum sigma_i of eq. (2.13) over the Gauss family (post/peridynamic_stress.hpp's
  // family_stress on each family): [n*dim*dim].
  std::vector<double> family_stresses(const double* u) const;

  const SparsityPattern& pattern() const;
  // The node sets each family's tangent couples, as Bonds (neighbor: the local nodes
  // n_1.. ascending; the other arrays empty): what the pattern is built from.
  // Built on first use (the matrix, the diagonal): a few ints per coupled pair.
  const Bonds& reach_bonds() const;
  const GaussPoints& points() const { return *gp_; }
  int dofs() const { return particles_->size() * particles_->dim; }

 private:
  class Gather;
  template <class Body>
  void for_each_family(const char* stage, Body&& body) const;

  const Particles* particles_;
  const GaussPoints* gp_;
  const abi::LawDescriptor& law_;
  const abi::KernelVariant& variant_;
  std::vector<std::vector<double>> params_;
  std::vector<double> moments_;
  mutable Bonds reach_;
  mutable std::once_flag reach_once_;
  std::unique_ptr<SparsityPattern> pattern_;
};

}  // namespace pd

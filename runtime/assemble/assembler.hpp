// Global assembly of a generated law over all families: internal nodal forces, the
// stiffness K = -df/du in the precomputed sparsity, and the matrix-free product K v
// from the generated tangent-vector kernel. One code path serves all three; OpenMP
// splits families across threads and atomics resolve the shared entries.
#pragma once

#include <string>
#include <vector>

#include "assemble/sparsity.hpp"
#include "kernel_abi.hpp"
#include "particles.hpp"

namespace pd {

class Assembler {
 public:
  // params: one parameter vector per material (particle.material indexes it).
  // intact: use the variant with alpha folded to 1 (only valid when no bond is broken).
  Assembler(const Particles& particles, const Bonds& bonds, const abi::LawDescriptor& law,
            std::vector<std::vector<double>> params, bool intact);

  void update_moments();  // after the bond factors change
  // f(u): internal nodal forces, size n*dim (overwritten).
  void forces(const std::vector<double>& u, std::vector<double>& f) const;
  // K(u) = -df/du into K (pattern from sparsity()); also f(u) when f is not null.
  void stiffness(const std::vector<double>& u, SparseMatrix& K, std::vector<double>* f) const;
  // The law's per-particle outputs (dilatation, strain, ...): [n * law.n_outputs].
  std::vector<double> particle_outputs(const std::vector<double>& u) const;
  // out = K(u) v, matrix-free.
  void apply_stiffness(const std::vector<double>& u, const std::vector<double>& v, std::vector<double>& out) const;

  const Sparsity& sparsity() const { return sparsity_; }
  const abi::LawDescriptor& law() const { return law_; }
  const char* variant_name() const { return intact_ ? "intact (alpha folded to 1)" : "damaged (reads alpha)"; }
  // Throws naming the stage, law and particle if a value is NaN or Inf.
  void check_finite(const std::vector<double>& values, const std::string& stage) const;
  const std::vector<double>& moments() const { return moments_; }

 private:
  struct Gather;
  const Particles& particles_;
  const Bonds& bonds_;
  const abi::LawDescriptor& law_;
  const abi::KernelVariant& variant_;
  std::vector<std::vector<double>> params_;
  bool intact_;
  std::vector<double> moments_;  // [n * n_moments]
  Sparsity sparsity_;
};

}  // namespace pd

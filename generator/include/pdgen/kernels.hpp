// From a law to its kernel programs: moments, residual, tangent factors (the
// loop-aware chain rule through horizon sums), tangent-vector product, energy, outputs.
#pragma once

#include <string>
#include <vector>

#include "pdgen/form_kernel.hpp"
#include "pdgen/kernel_program.hpp"
#include "pdgen/law.hpp"

namespace pdgen {

struct LawKernelSet {
  int n_moments = 0;
  int n_states = 0;  // scalar states the force state depends on (the tangent's s index)
  std::vector<std::string> moment_names, state_names;
  KernelProgram moments, residual, tangent, jvp;
  // d(nodal forces)/d(material parameter i), one nodal-vector column per parameter, at fixed
  // history: the sensitivities a gradient or a calibration needs.
  KernelProgram sensitivity;
  FactorStructure factor_structure;  // which tangent factor entries the tangent kernel can make nonzero
  bool has_energy = false;
  KernelProgram energy;
  bool has_outputs = false;
  KernelProgram outputs;
  bool has_update = false;  // the law carries history: the update kernel writes its new values
  KernelProgram update;
};

// `prefix` starts every kernel's function name (e.g. "silling_plane_strain_intact").
LawKernelSet build_kernels(const Law& law, const std::string& prefix);

// The weight w(r, delta) of an influence function as a kernel `influence_<name>`.
KernelProgram influence_kernel(const InfluenceDef& influence);

}  // namespace pdgen

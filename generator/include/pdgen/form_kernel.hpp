// The form kernel: C++ that builds a family's dense local matrix from the tangent
// factors, specialised to one law's dimension, state count and structural zeros.
#pragma once

#include <string>
#include <vector>

#include "pdgen/kernel_program.hpp"

namespace pdgen {

// Which entries of the tangent factors (runtime/kernel_abi.hpp's TangentFactors) can be
// nonzero: false where the generator's simplified expression is the constant 0 for every
// bond. Row-major like the factors: direct[r*dim + c], left[s*dim + r], right[s*dim + c].
struct FactorStructure {
  int dim = 0, n_states = 0;
  std::vector<bool> direct, left, right;
};

// `name`'s definition and prototype (abi_text::Kernel::Form). per_bond counts the
// multiply-adds of one neighbour-block row entry summed over a bond's d x d block.
EmittedKernel emit_form_kernel(const std::string& name, const FactorStructure& structure);

}  // namespace pdgen

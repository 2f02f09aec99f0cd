// The last stage: formatting emitted kernels into the generated source files, one
// header/source pair per law file plus the law table. The stages before it run in
// the pdgen driver (generator/pdgen_main.cpp).
#pragma once

#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "pdgen/kernel_program.hpp"
#include "pdgen/law.hpp"

namespace pdgen {

// One emitted kernel and the descriptor slot it fills (d.<variant>.<kind>).
struct NamedKernel {
  std::string kind;      // moments, residual, tangent, jvp, energy, outputs
  std::string function;  // the C++ function name
  EmittedKernel emitted;
};

// The kernels of one variant of a law: "damaged" (reads alpha) or "intact".
struct EmittedVariant {
  std::string name;
  int n_moments = 0, n_states = 0;
  std::vector<NamedKernel> kernels;
};

// Stages 1-5 for one variant of a law ("damaged", or "intact" for law.with_alpha_folded()):
// its kernel programs (generator/law/kernels.cpp), then C++ for each and the dense form.
// Throws std::exception with the reason when a stage refuses the law.
EmittedVariant emit_variant(const Law& law, const std::string& variant);

// Collects laws and influence functions; files() formats them. Deterministic: the same
// additions give the same bytes.
class GeneratedFiles {
 public:
  void add_law(const std::string& file_stem, const Law& law, const std::vector<EmittedVariant>& variants);
  void add_influence(const InfluenceDef& influence, const NamedKernel& weight);
  // File name -> content.
  std::map<std::string, std::string> files() const;

 private:
  struct Stem {
    std::string decl, code;
    std::vector<std::string> descriptor_functions, influence_entries;
  };
  std::map<std::string, Stem> stems_;
};

}  // namespace pdgen

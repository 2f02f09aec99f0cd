// One variant of a law through the generator's stages (pdgen_main.cpp runs it for every
// registered law; the pdgen fuzz target for random ones).
#include <string>
#include <utility>
#include <vector>

#include "pdgen/files.hpp"
#include "pdgen/form_kernel.hpp"
#include "pdgen/kernels.hpp"

namespace pdgen {

EmittedVariant emit_variant(const Law& law, const std::string& variant) {
  const LawKernelSet k = build_kernels(law, law.name() + "_" + variant);
  EmittedVariant v{variant, k.n_moments, k.n_states, {}};
  std::vector<std::pair<std::string, const KernelProgram*>> programs{{"moments", &k.moments},
                                                                     {"residual", &k.residual},
                                                                     {"tangent", &k.tangent},
                                                                     {"jvp", &k.jvp},
                                                                     {"sensitivity", &k.sensitivity}};
  if (k.has_energy) programs.push_back({"energy", &k.energy});
  if (k.has_outputs) programs.push_back({"outputs", &k.outputs});
  if (k.has_update) programs.push_back({"update", &k.update});
  for (const auto& [kind, program] : programs)
    v.kernels.push_back({kind, program->name, emit_kernel(*program)});
  const std::string form = law.name() + "_" + variant + "_form";
  v.kernels.push_back({"form", form, emit_form_kernel(form, k.factor_structure)});
  return v;
}

}  // namespace pdgen

// The fixed-Poisson-ratio check of a law against a scene's material.
#include "material/admissible_poisson.hpp"

#include <fmt/core.h>

#include <cmath>

namespace pd {

double poisson_ratio_seen_by_law(const abi::LawDescriptor& law, const IsotropicElastic& elastic,
                                 PlaneAssumption plane) {
  return law.dim == 2 && plane == PlaneAssumption::Stress ? elastic.nu / (1 + elastic.nu) : elastic.nu;
}

std::optional<std::string> poisson_ratio_warning(const abi::LawDescriptor& law,
                                                 const IsotropicElastic& elastic, PlaneAssumption plane,
                                                 const std::string& material) {
  if (!law.has_fixed_poisson_ratio) return std::nullopt;
  const double seen = poisson_ratio_seen_by_law(law, elastic, plane);
  if (std::fabs(seen - law.poisson_ratio) <= 1e-3) return std::nullopt;
  const double nu = law.poisson_ratio;
  std::string admissible = fmt::format("nu = {:.4g}", nu);
  if (law.dim == 2)
    admissible = fmt::format("nu = {:.4g} in plane strain, {:.4g} in plane stress", nu, nu / (1 - nu));
  return fmt::format(
      "law {} has a fixed Poisson ratio ({}); material '{}' has nu = {:.4g}{}: the law matches its bulk "
      "modulus only, and the result is not linear elasticity with that nu",
      law.name, admissible, material, elastic.nu,
      law.dim == 2 ? (plane == PlaneAssumption::Stress ? " in plane stress" : " in plane strain") : "");
}

void warn_if_poisson_ratio_differs(const abi::LawDescriptor& law, const IsotropicElastic& elastic,
                                   PlaneAssumption plane, const std::string& material) {
  if (const auto w = poisson_ratio_warning(law, elastic, plane, material))
    fmt::print(stderr, "pd: warning: {}\n", *w);
}

}  // namespace pd

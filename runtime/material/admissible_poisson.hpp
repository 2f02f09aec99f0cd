// A law with a fixed Poisson ratio (bond-based: 1/4 in 3D and plane strain) matches
// only the bulk modulus of a material with another ratio: the run is then not linear
// elasticity with the scene's nu (37 % error in a shear test at nu = 0.33). The runtime
// warns and runs; the scene may mean it (e.g. a study of that error).
#pragma once

#include <optional>
#include <string>

#include "kernel_abi.hpp"
#include "material/elastic_constants.hpp"

namespace pd {

// The Poisson ratio of `elastic` as the law sees it: nu / (1 + nu) for a 2D law in
// plane stress (the plane-stress equivalent material), nu otherwise.
double poisson_ratio_seen_by_law(const abi::LawDescriptor& law, const IsotropicElastic& elastic,
                                 PlaneAssumption plane);

// A warning when the law fixes the Poisson ratio and the material's differs by more than
// 1e-3 (in the law's plane-strain form); nothing otherwise. `material` names it.
std::optional<std::string> poisson_ratio_warning(const abi::LawDescriptor& law,
                                                 const IsotropicElastic& elastic, PlaneAssumption plane,
                                                 const std::string& material);
// Prints that warning, if any, to stderr as "pd: warning: ...".
void warn_if_poisson_ratio_differs(const abi::LawDescriptor& law, const IsotropicElastic& elastic,
                                   PlaneAssumption plane, const std::string& material);

}  // namespace pd

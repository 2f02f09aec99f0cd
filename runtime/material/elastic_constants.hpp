// Isotropic elastic constants, the plane assumptions, and the mapping from a material
// to the parameter vector a generated law expects (by the law's parameter names).
#pragma once

#include <map>
#include <string>
#include <vector>

#include "kernel_abi.hpp"

namespace pd {

enum class PlaneAssumption { Strain, Stress, None /* 3D */ };

// The 3D isotropic constants of a material; any pair determines the rest.
struct IsotropicElastic {
  double E = 0, nu = 0, K = 0, G = 0, lambda = 0;
  static IsotropicElastic from_E_nu(double E, double nu);
  static IsotropicElastic from_K_G(double K, double G);
  // The 3D material whose plane-strain response equals the plane-stress response of
  // this one: nu* = nu / (1 + nu), E* = E (1 + 2 nu) / (1 + nu)^2. Laws written in
  // plane-strain form then solve plane-stress problems exactly.
  IsotropicElastic plane_stress_equivalent() const;
};

// The names in `extra` (a material's `parameters`) that the law does not take.
std::vector<std::string> unused_parameters(const abi::LawDescriptor& law,
                                           const std::map<std::string, double>& extra);

// Parameter values in the law's order. Elastic names are derived from `elastic`
// (after the plane-stress substitution when `plane` is Stress and the law is 2D):
// E, nu, K (3D bulk), G, mu (= G), lambda, kappa2 (plane-strain 2D bulk, lambda + G).
// Any other name must be in `extra`; a missing one throws std::invalid_argument
// naming the law and the parameter.
std::vector<double> law_parameters(const abi::LawDescriptor& law, const IsotropicElastic& elastic,
                                   PlaneAssumption plane, const std::map<std::string, double>& extra);

// d law_parameters(law, elastic, plane, extra) / d key, in closed form: key "E" or "nu" moves
// the material's elastic pair (through the plane-stress substitution when it applies) and
// every elastic name derived from it; any other key must be in `extra` and moves only the
// law's parameter of that name. Throws std::invalid_argument when the law reads nothing
// the key moves (a parameter it does not have).
std::vector<double> law_parameter_derivative(const abi::LawDescriptor& law, const IsotropicElastic& elastic,
                                             PlaneAssumption plane,
                                             const std::map<std::string, double>& extra,
                                             const std::string& key);

// Why `value` lies outside the range the law declares for its parameter `index`
// (LawDescriptor::param_ranges), or empty when it lies inside.
std::string parameter_range_violation(const abi::LawDescriptor& law, int index, double value);

}  // namespace pd

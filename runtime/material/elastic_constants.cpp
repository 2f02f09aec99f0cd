// Conversions between isotropic elastic constants and law parameters.
#include "material/elastic_constants.hpp"

#include <fmt/core.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace pd {

namespace {
void require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument(what);
}
}  // namespace

IsotropicElastic IsotropicElastic::from_E_nu(double E, double nu) {
  require(std::isfinite(E) && E > 0, "Young's modulus E must be positive, got " + std::to_string(E));
  require(std::isfinite(nu) && nu > -1.0 && nu < 0.5,
          "Poisson's ratio nu must lie in (-1, 0.5), got " + std::to_string(nu));
  IsotropicElastic m;
  m.E = E;
  m.nu = nu;
  m.G = E / (2 * (1 + nu));
  m.K = E / (3 * (1 - 2 * nu));
  m.lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
  return m;
}

IsotropicElastic IsotropicElastic::from_K_G(double K, double G) {
  require(std::isfinite(K) && K > 0, "bulk modulus K must be positive, got " + std::to_string(K));
  require(std::isfinite(G) && G > 0, "shear modulus G must be positive, got " + std::to_string(G));
  IsotropicElastic m;
  m.K = K;
  m.G = G;
  m.E = 9 * K * G / (3 * K + G);
  m.nu = (3 * K - 2 * G) / (2 * (3 * K + G));
  m.lambda = K - 2 * G / 3;
  return m;
}

IsotropicElastic IsotropicElastic::plane_stress_equivalent() const {
  return from_E_nu(E * (1 + 2 * nu) / ((1 + nu) * (1 + nu)), nu / (1 + nu));
}

std::vector<std::string> unused_parameters(const abi::LawDescriptor& law,
                                           const std::map<std::string, double>& extra) {
  std::vector<std::string> unused;
  for (const auto& [name, value] : extra) {
    bool taken = false;
    for (int i = 0; i < law.n_params; ++i) taken = taken || name == law.param_names[i];
    if (!taken) unused.push_back(name);
  }
  return unused;
}

std::vector<double> law_parameters(const abi::LawDescriptor& law, const IsotropicElastic& elastic,
                                   PlaneAssumption plane, const std::map<std::string, double>& extra) {
  const IsotropicElastic m =
      (law.dim == 2 && plane == PlaneAssumption::Stress) ? elastic.plane_stress_equivalent() : elastic;
  const std::map<std::string, double> derived{{"E", m.E},
                                              {"nu", m.nu},
                                              {"K", m.K},
                                              {"G", m.G},
                                              {"mu", m.G},
                                              {"lambda", m.lambda},
                                              {"kappa2", m.lambda + m.G}};
  std::vector<double> out;
  for (int i = 0; i < law.n_params; ++i) {
    const std::string name = law.param_names[i];
    if (auto it = extra.find(name); it != extra.end()) {
      out.push_back(it->second);
    } else if (auto d = derived.find(name); d != derived.end()) {
      out.push_back(d->second);
    } else {
      throw std::invalid_argument("law " + std::string(law.name) + " needs parameter '" + name +
                                  "': give it in the material's parameters");
    }
  }
  return out;
}

std::vector<double> law_parameter_derivative(const abi::LawDescriptor& law, const IsotropicElastic& elastic,
                                             PlaneAssumption plane,
                                             const std::map<std::string, double>& extra,
                                             const std::string& key) {
  std::vector<double> out(static_cast<std::size_t>(law.n_params), 0.0);
  bool moved = false;
  if (key != "E" && key != "nu") {
    require(extra.count(key) > 0, "material parameter '" + key + "' is not given in the material, so it " +
                                      "cannot be differentiated (E, nu, or a name under its parameters)");
    for (int i = 0; i < law.n_params; ++i)
      if (law.param_names[i] == key) out[static_cast<std::size_t>(i)] = 1.0, moved = true;
    require(moved, "law " + std::string(law.name) + " has no parameter '" + key + "'");
    return out;
  }
  // The material the law sees, (E', nu'), and d(E', nu')/d key.
  const double E = elastic.E, nu = elastic.nu;
  double Es = E, nus = nu, dE = key == "E" ? 1.0 : 0.0, dnu = key == "nu" ? 1.0 : 0.0;
  if (law.dim == 2 && plane == PlaneAssumption::Stress) {  // E' = E (1 + 2nu)/(1 + nu)^2, nu' = nu/(1 + nu)
    const double a = 1 + nu;
    Es = E * (1 + 2 * nu) / (a * a);
    nus = nu / a;
    dE = key == "E" ? (1 + 2 * nu) / (a * a) : -2 * E * nu / (a * a * a);
    dnu = key == "E" ? 0.0 : 1 / (a * a);
  }
  // d/dE' and d/dnu' of each derived constant, times the chain.
  const double b = 1 + nus, c = 1 - 2 * nus;
  const double dG = dE / (2 * b) - Es * dnu / (2 * b * b);
  const double dK = dE / (3 * c) + 2 * Es * dnu / (3 * c * c);
  const double dlambda = dE * nus / (b * c) + Es * dnu * (1 + 2 * nus * nus) / (b * b * c * c);
  const std::map<std::string, double> derived{{"E", dE},
                                              {"nu", dnu},
                                              {"K", dK},
                                              {"G", dG},
                                              {"mu", dG},
                                              {"lambda", dlambda},
                                              {"kappa2", dlambda + dG}};
  for (int i = 0; i < law.n_params; ++i) {
    const std::string name = law.param_names[i];
    if (extra.count(name)) continue;  // given directly: not moved by the elastic pair
    if (auto d = derived.find(name); d != derived.end()) {
      out[static_cast<std::size_t>(i)] = d->second;
      moved = moved || d->second != 0.0;
    }
  }
  require(moved, "law " + std::string(law.name) + " reads no parameter that '" + key + "' moves");
  return out;
}

std::string parameter_range_violation(const abi::LawDescriptor& law, int index, double value) {
  const abi::ParamRange range = law.param_ranges ? law.param_ranges[index] : abi::ParamRange::any;
  const bool inside = range == abi::ParamRange::any || (range == abi::ParamRange::positive && value > 0) ||
                      (range == abi::ParamRange::non_negative && value >= 0) ||
                      (range == abi::ParamRange::unit_interval && value >= 0 && value <= 1);
  if (inside) return {};
  const char* wanted = range == abi::ParamRange::positive       ? "> 0"
                       : range == abi::ParamRange::non_negative ? ">= 0"
                                                                : "in [0, 1]";
  return fmt::format("law {} needs parameter '{}' {}, got {:g}", law.name, law.param_names[index], wanted,
                     value);
}

}  // namespace pd

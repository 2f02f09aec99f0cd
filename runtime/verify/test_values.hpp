// The parameter values a law declares for its automatic tests (law.param(name, value)).
#pragma once

#include <cmath>
#include <map>
#include <string>

#include "kernel_abi.hpp"

namespace pd::verify {

// Name -> test value of every parameter the law gives one; elastic names are derived
// from the material (material/elastic_constants.hpp) and have none.
inline std::map<std::string, double> declared_test_values(const abi::LawDescriptor& law) {
  std::map<std::string, double> out;
  for (int i = 0; i < law.n_params; ++i)
    if (law.param_test_values != nullptr && !std::isnan(law.param_test_values[i]))
      out[law.param_names[i]] = law.param_test_values[i];
  return out;
}

}  // namespace pd::verify

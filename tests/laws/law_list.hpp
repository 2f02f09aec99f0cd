// Every generated law, as the parameter list of a law-parameterised test.
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "kernel_abi.hpp"

namespace pd::test {

inline std::vector<const abi::LawDescriptor*> all_law_descriptors() {
  std::vector<const abi::LawDescriptor*> v;
  for (const auto& l : abi::all_laws()) v.push_back(&l);
  return v;
}
inline std::string law_name(const testing::TestParamInfo<const abi::LawDescriptor*>& info) {
  return info.param->name;
}

}  // namespace pd::test

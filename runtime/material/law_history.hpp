// A law's internal variables named for messages and the run log.
#pragma once

#include <string>

#include "kernel_abi.hpp"

namespace pd {

// "plastic_extension per bond", "eqps per particle", or both joined by "; " (empty for a
// law without history).
std::string describe_history(const abi::LawDescriptor& law);

}  // namespace pd

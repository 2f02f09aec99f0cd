// Per-particle moments (weighted volume, shape tensor, ...): deformation-independent sums.
#pragma once

#include "assembly/family_gather.hpp"

namespace pd {

// Runs the kernel's moments() for every particle into inputs.moments. Call once at
// setup and again whenever a bond factor alpha changes (a moment sums over intact
// bonds). Throws naming the particle when a moment is not finite (e.g. a particle
// whose bonds are all broken has a zero weighted volume).
void compute_moments(FamilyInputs& inputs, const abi::LawDescriptor& law, const abi::KernelVariant& variant);

}  // namespace pd

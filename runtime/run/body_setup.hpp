// What every run builds first from a scene: the law and influence, the particles, the
// bonds (cut by the pre-cracks), the per-material law parameters, and the checks that
// no particle is alone and no family is degenerate. Shared by the static and the
// dynamic drivers; it also fills the summary's scene, law and count fields.
#pragma once

#include <vector>

#include "discretize/family_quality.hpp"
#include "input/scene.hpp"
#include "kernel_abi.hpp"
#include "particles.hpp"
#include "run/simulation.hpp"

namespace pd {

struct BodySetup {
  const abi::LawDescriptor* law = nullptr;
  const abi::InfluenceDescriptor* influence = nullptr;
  Particles particles;
  Bonds bonds;
  std::vector<std::vector<double>> params;  // per material
  FamilyQualityReport quality;
};

BodySetup set_up_body(const Scene& scene, RunSummary& summary);

}  // namespace pd

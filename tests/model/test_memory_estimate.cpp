// The memory estimate made before discretising (runtime/cli/memory_check): its bond count
// against the bonds the discretisation really finds, and the refusal's content.
#include <gtest/gtest.h>

#include "cli/memory_check.hpp"
#include "discretize/discretization.hpp"
#include "input/scene.hpp"
#include "kernel_abi.hpp"

namespace {
pd::Scene scene(int count, double ratio, int dim) {
  const std::string box = dim == 2 ? "{min: [0, 0], max: [1, 1]}" : "{min: [0, 0, 0], max: [1, 1, 1]}";
  return pd::parse_scene(
      "dimension: " + std::to_string(dim) + "\ndomain: {box: " + box + ", count: " + std::to_string(count) +
          "}\nhorizon: {ratio: " + std::to_string(ratio) +
          "}\nlaw: " + (dim == 2 ? "silling_plane_strain" : "lps_3d") + "\nmaterials: [{E: 1, nu: 0.25}]\n",
      "m.yaml");
}
}  // namespace

TEST(MemoryEstimate, CountsWhatTheDiscretisationFinds) {
  for (auto [count, ratio, dim] : {std::tuple{60, 3.0, 2}, {40, 4.0, 2}, {12, 3.0, 3}}) {
    const pd::Scene s = scene(count, ratio, dim);
    const pd::cli::MemoryEstimate e = pd::cli::estimate_memory(s);
    const pd::Particles p = pd::discretize(s);
    const pd::Bonds b = pd::find_bonds(p, s.delta(), pd::abi::find_influence(s.influence)->weight);
    EXPECT_EQ(e.particles, p.size());
    // The interior families are full; those near the boundary are cut, so the estimate is
    // an upper bound on the count, within the boundary layer's share.
    EXPECT_GE(e.bonds, b.bond_count()) << count << " " << ratio << " " << dim;
    EXPECT_LE(e.bonds, 1.6 * b.bond_count()) << count << " " << ratio << " " << dim;
  }
}

TEST(MemoryEstimate, RefusesWhatCannotFitWithBothNumbers) {
  const pd::Scene small = scene(10, 3.0, 2);
  EXPECT_FALSE(pd::cli::memory_refusal(small, 1e9));
  EXPECT_FALSE(pd::cli::memory_refusal(small, std::nullopt));
  const auto refusal = pd::cli::memory_refusal(small, 1000.0);  // 1000 bytes
  ASSERT_TRUE(refusal);
  EXPECT_NE(refusal->find("m.yaml: domain: the scene needs at least"), std::string::npos) << *refusal;
  EXPECT_NE(refusal->find("100 particles"), std::string::npos) << *refusal;
  EXPECT_NE(refusal->find("9.31e-07 GiB available"), std::string::npos) << *refusal;
}

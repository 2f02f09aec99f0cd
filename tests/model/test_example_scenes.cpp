// Every example scene in scenes/ reads, discretises and finds its boundary node sets.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "discretize/discretization.hpp"

namespace {
// tests/model/<this file> -> the repository's scenes/ folder.
// From the build (tests/CMakeLists.txt): __FILE__ is relative under a ccache base_dir.
const std::filesystem::path kScenes = std::filesystem::path(PD_SOURCE_DIR) / "scenes";
}  // namespace

TEST(ExampleScenes, EveryScenePartitionsIntoNonEmptyNodeSets) {
  ASSERT_TRUE(std::filesystem::is_directory(kScenes)) << kScenes;
  int scenes = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(kScenes)) {
    if (entry.path().extension() != ".yaml") continue;
    ++scenes;
    SCOPED_TRACE(entry.path().string());
    pd::Scene s;
    ASSERT_NO_THROW(s = pd::read_scene(entry.path().string()));
    const pd::Particles p = pd::discretize(s);
    EXPECT_GT(p.size(), 0);
    for (const auto& bc : s.boundary) EXPECT_FALSE(pd::region_particles(bc.region, p, s).empty()) << bc.where;
    for (const auto& probe : s.probes)
      EXPECT_FALSE(pd::region_particles(probe.region, p, s).empty()) << probe.where;
  }
  EXPECT_GE(scenes, 4);
}

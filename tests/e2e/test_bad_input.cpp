// Bad input found while reading or after it: each ends with a message naming the file,
// line and key (or the particles and the missing constraint), before any solve.
#include <gtest/gtest.h>

#include <regex>

#include "input/scene.hpp"
#include "input/yaml_keys.hpp"
#include "run/simulation.hpp"

namespace {
const std::string kBase = R"(dimension: 2
domain:
  box: {min: [0, 0], max: [1, 1]}
  spacing: 0.1
law: silling_plane_strain
materials: [{E: 1, nu: 0.2}]
boundary:
  - region: {side: bottom}
    fixed: [x, y]
)";

std::string failure(const std::string& yaml) {
  try {
    pd::Simulation sim(pd::parse_scene(yaml, "b.yaml"), [](const std::string&) {});
    sim.run(false);
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}
void expect_message(const std::string& yaml, const std::string& pattern) {
  const std::string msg = failure(yaml);
  EXPECT_TRUE(std::regex_search(msg, std::regex(pattern))) << "got: " << msg << "\nexpected: " << pattern;
}
}  // namespace

TEST(BadInput, BaseSceneSolves) { EXPECT_EQ(failure(kBase), ""); }

TEST(BadInput, HorizonSmallerThanTheSpacing) {
  expect_message(kBase + "horizon: {length: 0.05}\n",
                 R"(^b\.yaml:10: horizon: the horizon must be at least one spacing)");
}

TEST(BadInput, EmptyNodeSetOfABoundaryCondition) {
  expect_message(kBase + "  - region: {box: {min: [3, 3], max: [4, 4]}}\n    fixed: [x]\n",
                 R"(^b\.yaml:10: boundary\[1\]: the region holds no particle)");
}

TEST(BadInput, ImpossibleGeometry) {
  expect_message(std::regex_replace(kBase, std::regex("  spacing: 0.1\n"),
                                    "  spacing: 0.1\n  holes: [{circle: {center: [0.5, 0.5], radius: 2}}]\n"),
                 R"(^b\.yaml: domain: the domain holds no particle)");
  expect_message(std::regex_replace(kBase, std::regex("max: \\[1, 1\\]"), "max: [1, -1]"),
                 R"(^b\.yaml:3: domain\.box: max must exceed min)");
}

TEST(BadInput, UnderConstrainedBody) {
  const std::string free_x = std::regex_replace(kBase, std::regex("fixed: \\[x, y\\]"), "fixed: [y]");
  expect_message(free_x, R"(under-constrained: no particle has its x displacement prescribed)");
}

TEST(BadInput, ClusterCutOffByCracks) {
  // A closed square crack around the four particles at (0.45 | 0.55, 0.45 | 0.55).
  expect_message(
      kBase +
          "cracks:\n  - segment: [[0.41, 0.41], [0.59, 0.41]]\n  - segment: [[0.59, 0.41], [0.59, 0.59]]\n"
          "  - segment: [[0.59, 0.59], [0.41, 0.59]]\n  - segment: [[0.41, 0.59], [0.41, 0.41]]\n",
      R"(a cluster of 4 particle\(s\) joined by intact bonds .* is disconnected from the rest of the body and under-constrained: no particle has its x)");
}

// A key given twice in one map is an error naming both lines (yaml-cpp alone keeps the
// first value and drops the second without a word).
#include <gtest/gtest.h>

#include <regex>
#include <string>

#include "input/scene.hpp"
#include "input/yaml_keys.hpp"

namespace {
const std::string kHead = "dimension: 2\ndomain:\n  box: {min: [0, 0], max: [1, 1]}\n  spacing: 0.25\n";
const std::string kTail = "boundary:\n  - region: {side: bottom}\n    fixed: [x, y]\n";

std::string error_of(const std::string& yaml) {
  try {
    pd::parse_scene(yaml, "dup.yaml");
  } catch (const pd::SceneError& e) {
    return e.what();
  }
  return "(no error)";
}
}  // namespace

TEST(DuplicateKeys, TheSceneWithoutDuplicatesReads) {
  EXPECT_EQ(error_of(kHead + "law: silling_plane_strain\nmaterials: [{E: 1, nu: 0.25}]\n" + kTail),
            "(no error)");
}

TEST(DuplicateKeys, LawTwiceAtTopLevelNamesBothLines) {
  // law on lines 5 and 7
  const std::string yaml =
      kHead + "law: silling_plane_strain\nmaterials: [{E: 1, nu: 0.25}]\nlaw: lps_plane_strain\n" + kTail;
  const std::string msg = error_of(yaml);
  EXPECT_TRUE(
      std::regex_search(msg, std::regex(R"(^dup\.yaml:7: law: duplicate key 'law' \(first given on line 5)")))
      << msg;
}

TEST(DuplicateKeys, YoungsModulusTwiceInABlockMaterial) {
  const std::string yaml =
      kHead + "law: silling_plane_strain\nmaterials:\n  - E: 1\n    nu: 0.25\n    E: 2\n" + kTail;
  const std::string msg = error_of(yaml);
  EXPECT_TRUE(std::regex_search(
      msg, std::regex(R"(^dup\.yaml:9: materials\[0\]\.E: duplicate key 'E' \(first given on line 7)")))
      << msg;
}

TEST(DuplicateKeys, YoungsModulusTwiceInAFlowMaterial) {
  const std::string yaml = kHead + "law: silling_plane_strain\nmaterials: [{E: 1, nu: 0.25, E: 2}]\n" + kTail;
  const std::string msg = error_of(yaml);
  EXPECT_TRUE(std::regex_search(
      msg, std::regex(R"(^dup\.yaml:6: materials\[0\]\.E: duplicate key 'E' \(first given on line 6)")))
      << msg;
}

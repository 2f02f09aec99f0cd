// The scene reader: a valid scene round-trips; every kind of bad input gives an
// error naming the file, the line and the key.
#include <gtest/gtest.h>

#include <regex>
#include <set>

#include "input/scene.hpp"
#include "input/scene_rules.hpp"
#include "input/yaml_keys.hpp"

namespace {
const char* kValid = R"(dimension: 2
domain:
  box: {min: [0, 0], max: [10, 5]}
  spacing: 0.5
  perturbation: {amplitude: 0.1, seed: 7}
  holes:
    - circle: {center: [5, 2.5], radius: 1}
horizon: {ratio: 3.5}
law: silling_plane_strain
influence: cubic
materials:
  - {name: rock, E: 1000, nu: 0.25, plane: stress}
boundary:
  - region: {side: bottom}
    fixed: [x, y]
  - region: {side: top}
    traction: [0, -0.001]
cracks:
  - segment: [[1, 2], [3, 2]]
    pressure: 0.1
solver: {linear: cholmod, load_steps: 2}
probes:
  - name: p
    region: {box: {min: [4, 4], max: [6, 5]}}
    component: y
)";

std::string error_of(const std::string& yaml) {
  try {
    pd::parse_scene(yaml, "s.yaml");
  } catch (const pd::SceneError& e) {
    return e.what();
  }
  return "";
}

std::string replace(std::string s, const std::string& from, const std::string& to) {
  const auto p = s.find(from);
  EXPECT_NE(p, std::string::npos) << from;
  return s.replace(p, from.size(), to);
}
}  // namespace

TEST(SceneReader, ReadsEveryPartOfAValidScene) {
  const pd::Scene s = pd::parse_scene(kValid, "s.yaml");
  EXPECT_EQ(s.dim, 2);
  EXPECT_DOUBLE_EQ(s.h, 0.5);
  EXPECT_DOUBLE_EQ(s.delta(), 1.75);
  EXPECT_DOUBLE_EQ(s.perturbation, 0.1);
  EXPECT_EQ(s.seed, 7u);
  ASSERT_EQ(s.holes.size(), 1u);
  EXPECT_EQ(s.influence, "cubic");
  ASSERT_EQ(s.materials.size(), 1u);
  EXPECT_EQ(s.materials[0].plane, pd::PlaneAssumption::Stress);
  EXPECT_NEAR(s.materials[0].elastic.G, 400.0, 1e-12);
  ASSERT_EQ(s.boundary.size(), 2u);
  EXPECT_TRUE(s.boundary[0].components[0] && s.boundary[0].components[1]);
  EXPECT_EQ(s.boundary[1].kind, pd::BoundaryCondition::Kind::Traction);
  EXPECT_DOUBLE_EQ(s.boundary[1].values[1], -0.001);
  ASSERT_EQ(s.cracks.size(), 1u);
  EXPECT_DOUBLE_EQ(s.cracks[0].pressure, 0.1);
  EXPECT_EQ(s.solver.linear, pd::LinearMethod::cholmod);
  EXPECT_EQ(s.solver.load_steps, 2);
  EXPECT_EQ(s.output.directory, "out");  // default
  ASSERT_EQ(s.probes.size(), 1u);
  EXPECT_EQ(s.probes[0].component, 1);
}

TEST(SceneReader, ErrorsNameFileLineAndKey) {
  struct Case {
    std::string from, to, expect;  // expect: regex on the message
  };
  const std::vector<Case> cases{
      {"spacing: 0.5", "spacing: -1", R"(^s\.yaml:4: domain\.spacing: spacing must be positive)"},
      {"spacing: 0.5", "spacing: abc", R"(^s\.yaml:4: domain\.spacing: expected a number)"},
      {"influence: cubic", "influence: cubik",
       R"(^s\.yaml:10: influence: unknown influence function 'cubik')"},
      {"law: silling_plane_strain", "law: nope", R"(^s\.yaml:9: law: unknown law 'nope')"},
      {"law: silling_plane_strain", "law: silling_3d", R"(^s\.yaml:9: law: law silling_3d is 3D)"},
      {"horizon: {ratio: 3.5}", "horizon: {ratio: 3.5, colour: red}",
       R"(^s\.yaml:8: horizon\.colour: unknown key 'colour')"},
      {"nu: 0.25", "nu: 0.5", R"(^s\.yaml:12: materials\[0\]: Poisson's ratio)"},
      {"fixed: [x, y]", "fixed: [x, w]", R"(^s\.yaml:15: boundary\[0\]\.fixed: 'w' is not a component)"},
      {"    traction: [0, -0.001]", "    traction: [0, -0.001]\n    fixed: [x]",
       R"(^s\.yaml:16: boundary\[1\]: give exactly one of)"},
      {"linear: cholmod", "linear: magic", R"(^s\.yaml:21: solver\.linear: 'magic' is not one of)"},
      {"segment: [[1, 2], [3, 2]]", "segment: [[1, 2]]",
       R"(^s\.yaml:19: cracks\[0\]\.segment: a 2D crack is a segment)"},
      {"dimension: 2", "dimension: 4", R"(^s\.yaml:1: dimension: dimension must be 2 or 3)"},
      {"box: {min: [0, 0], max: [10, 5]}", "box: {min: [0, 0], max: [10]}",
       R"(^s\.yaml:3: domain\.box\.max: expected 2 coordinates)"},
  };
  for (const Case& c : cases) {
    const std::string msg = error_of(replace(kValid, c.from, c.to));
    EXPECT_TRUE(std::regex_search(msg, std::regex(c.expect))) << "got: " << msg << "\nexpected: " << c.expect;
  }
}

TEST(SceneReader, MissingRequiredKeysAndSyntaxErrors) {
  EXPECT_TRUE(std::regex_search(error_of("dimension: 2\n"),
                                std::regex(R"(s\.yaml:1: \(top level\): missing required key 'domain')")))
      << error_of("dimension: 2\n");
  EXPECT_TRUE(
      std::regex_search(error_of("domain: [1, 2\n"), std::regex(R"(^s\.yaml:\d+: YAML syntax error)")))
      << error_of("domain: [1, 2\n");
  EXPECT_TRUE(
      std::regex_search(error_of("- 1\n- 2\n"), std::regex(R"(^s\.yaml:1: \(top level\): expected a map)")));
  EXPECT_THROW(pd::read_scene("/nonexistent/scene.yaml"), pd::SceneError);
}

// Each names table spells every value once, and reads back what it prints.
template <class E>
void expect_names_round_trip() {
  std::set<std::string_view> words;
  for (const auto& n : pd::enum_names<E>::table) {
    EXPECT_TRUE(words.insert(n.name).second) << n.name;
    EXPECT_EQ(pd::parse_name<E>(pd::name_of(n.value)), n.value) << n.name;
  }
  EXPECT_EQ(pd::parse_name<E>("no such word"), std::nullopt);
}

TEST(SceneVocabulary, NamesTablesRoundTrip) {
  expect_names_round_trip<pd::Quadrature>();
  expect_names_round_trip<pd::LinearMethod>();
  expect_names_round_trip<pd::Preconditioner>();
  expect_names_round_trip<pd::Backend>();
  expect_names_round_trip<pd::NonlinearMethod>();
  expect_names_round_trip<pd::DynamicsMethod>();
  expect_names_round_trip<pd::Placement>();
  expect_names_round_trip<pd::ObqSpace>();
  expect_names_round_trip<pd::CrackTips>();
  expect_names_round_trip<pd::Region::Side>();
  EXPECT_EQ(pd::name_list<pd::Placement>(), "cell, node");
}

TEST(SceneRules, EachRuleHasItsOwnName) {
  std::set<std::string_view> names;
  for (const pd::SceneRule& rule : pd::scene_rules())
    EXPECT_TRUE(names.insert(rule.name).second) << rule.name;
  EXPECT_GE(names.size(), 10u);
}

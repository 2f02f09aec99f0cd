// The quadrature table (input/quadrature.hpp: kQuadratureRules) is the one place a rule's
// compatibilities are written. Held to it here: it lists every rule of the enum once, the
// scene format documents every rule, and the scene reader, the dynamic driver and the model
// accept exactly what the table says for every rule and every feature -- so a new rule is
// a row, and a wrong row fails here.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "input/quadrature.hpp"
#include "input/scene.hpp"
#include "input/yaml_keys.hpp"
#include "model/model.hpp"
#include "run/dynamic_run.hpp"
#include "run/dynamic_simulation.hpp"

namespace {
std::string box_scene(const std::string& name, const std::string& domain_extra,
                      const std::string& rest = "") {
  return "dimension: 2\n"
         "domain:\n"
         "  box: {min: [0, 0], max: [1, 1]}\n"
         "  count: 12\n"
         "  quadrature: " +
         name + "\n" + domain_extra +
         "horizon: {ratio: 3}\n"
         "law: lps_plane_strain\n"
         "influence: const\n"
         "materials: [{name: m, E: 1, nu: 0.25, density: 1}]\n"
         "boundary:\n  - region: {side: left}\n    fixed: [x, y]\n" +
         rest;
}

std::string blocks_scene(const std::string& name) {
  return "dimension: 2\n"
         "domain:\n"
         "  quadrature: " +
         name +
         "\n"
         "  blocks:\n"
         "    - {box: {min: [0, 0], max: [0.5, 1]}, spacing: 0.05}\n"
         "    - {box: {min: [0.5, 0], max: [1, 1]}, spacing: 0.1}\n"
         "horizon: {ratio: 3}\n"
         "law: lps_plane_strain\n"
         "influence: const\n"
         "materials: [{name: m, E: 1, nu: 0.25}]\n";
}

// Whether the reader accepts the text; a refusal must be a SceneError naming the file.
bool accepted(const std::string& text) {
  try {
    pd::parse_scene(text, "q.yaml");
    return true;
  } catch (const pd::SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("q.yaml"), std::string::npos) << e.what();
    return false;
  }
}
}  // namespace

TEST(QuadratureRules, TheTableListsEveryRuleOnceInTheNamesOrder) {
  const auto& names = pd::enum_names<pd::Quadrature>::table;
  ASSERT_EQ(pd::kQuadratureRules.size(), names.size());
  for (std::size_t i = 0; i < names.size(); ++i) {
    EXPECT_EQ(pd::kQuadratureRules[i].id, names[i].value) << names[i].name;
    EXPECT_EQ(&pd::quadrature_rule(names[i].value), &pd::kQuadratureRules[i]);
  }
}

TEST(QuadratureRules, TheSceneFormatDocumentsEveryRule) {
  std::ifstream in(std::string(PD_SOURCE_DIR) + "/docs/scene_format.md");
  ASSERT_TRUE(in) << "docs/scene_format.md";
  std::stringstream text;
  text << in.rdbuf();
  for (const auto& n : pd::enum_names<pd::Quadrature>::table) {
    std::string quoted(1, '`');
    quoted.append(n.name).push_back('`');
    EXPECT_NE(text.str().find(quoted), std::string::npos) << n.name;
  }
}

TEST(QuadratureRules, TheReaderAcceptsExactlyWhatTheTableSays) {
  for (const pd::QuadratureRule& rule : pd::kQuadratureRules) {
    const std::string name(pd::name_of(rule.id));
    SCOPED_TRACE(name);
    EXPECT_TRUE(accepted(box_scene(name, "")));
    EXPECT_EQ(accepted(box_scene(name, "  compensation: true\n")), rule.scales_volumes);
    EXPECT_EQ(accepted(box_scene(name, "  surface_correction: terms\n")), rule.scales_volumes);
    EXPECT_EQ(accepted(box_scene(name, "  gauss_points: {per_axis: 2}\n")), rule.gauss_points);
    EXPECT_EQ(accepted(box_scene(name, "  obq_space: paper001\n")), rule.own_weights);
    EXPECT_EQ(accepted(box_scene(name, "  obq_symmetric: true\n")), rule.own_weights);
    EXPECT_EQ(accepted(blocks_scene(name)), rule.blocks);
  }
}

TEST(QuadratureRules, TheDynamicDriverAcceptsExactlyTheRulesWithDynamics) {
  for (const pd::QuadratureRule& rule : pd::kQuadratureRules) {
    const std::string name(pd::name_of(rule.id));
    SCOPED_TRACE(name);
    const pd::Scene scene =
        pd::parse_scene(box_scene(name, "", "dynamics: {method: explicit, steps: 1}\n"), "q.yaml");
    bool ran = true;
    try {
      pd::check_dynamic_scene(scene);
    } catch (const std::invalid_argument& e) {
      ran = false;
      EXPECT_NE(std::string(e.what()).find("domain.quadrature: " + name), std::string::npos) << e.what();
    }
    EXPECT_EQ(ran, rule.dynamics);
  }
}

// The model's first phase builds collocation weights exactly for the rules with their own
// weights, and refuses a body with a hole exactly for those that integrate over the box.
TEST(QuadratureRules, TheModelBuildsWhatTheTableSays) {
  for (const pd::QuadratureRule& rule : pd::kQuadratureRules) {
    const std::string name(pd::name_of(rule.id));
    SCOPED_TRACE(name);
    const pd::DiscretizedBody body(pd::parse_scene(box_scene(name, ""), "q.yaml"));
    EXPECT_EQ(body.collocation != nullptr, rule.own_weights);
    const pd::Scene holed = pd::parse_scene(
        box_scene(name, "  holes: [{circle: {center: [0.5, 0.5], radius: 0.2}}]\n"), "q.yaml");
    bool built = true;
    try {
      const pd::DiscretizedBody b(holed);
    } catch (const std::invalid_argument& e) {
      built = false;
      EXPECT_NE(std::string(e.what()).find("without holes"), std::string::npos) << e.what();
    }
    EXPECT_EQ(built, !rule.cut_box_body);
  }
}

// What the table allows works: the mechanism behind each allowed pairing builds (and a
// dynamic step runs), so a row that claims too much fails here, not in a user's run.
TEST(QuadratureRules, WhatTheTableAllowsBuildsAndRuns) {
  for (const pd::QuadratureRule& rule : pd::kQuadratureRules) {
    const std::string name(pd::name_of(rule.id));
    SCOPED_TRACE(name);
    if (rule.blocks) {
      EXPECT_NO_THROW(pd::DiscretizedBody(pd::parse_scene(blocks_scene(name), "q.yaml")));
    }
    if (rule.scales_volumes) {
      EXPECT_NO_THROW(
          pd::DiscretizedBody(pd::parse_scene(box_scene(name, "  compensation: true\n"), "q.yaml")));
      EXPECT_NO_THROW(
          pd::DiscretizedBody(pd::parse_scene(box_scene(name, "  surface_correction: terms\n"), "q.yaml")));
    }
    if (rule.gauss_points) {
      EXPECT_NO_THROW(
          pd::DiscretizedBody(pd::parse_scene(box_scene(name, "  gauss_points: {per_axis: 2}\n"), "q.yaml")));
    }
    if (rule.dynamics) {
      const pd::Scene scene = pd::parse_scene(
          box_scene(name, "", "dynamics: {method: explicit, steps: 2, threads: 1}\n"), "q.yaml");
      pd::DynamicSimulation sim(scene, [](const std::string&) {});
      EXPECT_EQ(sim.run(false).dynamics->last_step, 2);
    }
  }
}

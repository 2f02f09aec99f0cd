// load_steps.csv (docs/scene_format.md, output): with several load steps and probes, a row
// per load step that stands, with its load factor and every probe's value there. The bar is
// elastic, so its state at a load does not depend on the path that led there: each row must
// match a separate run that goes straight to that load (a row written from another step's
// state, a load factor off the path or a shifted column does not).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "run_pd.hpp"

namespace {
std::vector<std::vector<std::string>> read_csv(const std::filesystem::path& p) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(pdtest::slurp(p));
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> cells;
    std::istringstream cs(line);
    for (std::string c; std::getline(cs, c, ',');) cells.push_back(c);
    rows.push_back(cells);
  }
  return rows;
}

const char* kBar =
    "dimension: 2\ndomain: {box: {min: [0, 0], max: [1, 0.25]}, spacing: 0.05}\n"
    "law: silling_plane_strain\ninfluence: const\n"
    "materials: [{E: 1.0, nu: 0.25}]\n"
    "boundary:\n"
    "  - {region: {all: true}, fixed: [y]}\n"
    "  - {region: {side: left}, fixed: [x]}\n"
    "  - {region: {side: right}, displacement: {x: 0.01}}\n"
    "solver: {load_steps: 4, load_path: [0, 1, -1]}\n"
    "probes:\n"
    "  - {name: mid_u, component: x, region: {box: {min: [0.4, 0], max: [0.6, 0.25]}}}\n"
    "  - {name: mid_stress, quantity: stress, component: xx, region: {box: {min: [0.4, 0], max: [0.6, "
    "0.25]}}}\n";

// The scene with the right end pulled to `displacement` and the given solver line.
std::string bar_scene(double displacement, const std::string& solver) {
  std::string scene = kBar;
  const std::string pull = "displacement: {x: 0.01}", path = "solver: {load_steps: 4, load_path: [0, 1, -1]}";
  scene.replace(scene.find(pull), pull.size(), "displacement: {x: " + std::to_string(displacement) + "}");
  scene.replace(scene.find(path), path.size(), solver);
  return scene;
}

std::vector<std::vector<std::string>> run_bar(const std::string& name, const std::string& scene) {
  const auto dir = pdtest::fresh_directory(name);
  std::ofstream(dir / "bar.yaml") << scene;
  const auto r = pdtest::run_pd({"run", (dir / "bar.yaml").string(), "--out", (dir / "out").string()});
  EXPECT_EQ(r.status, 0) << r.err;
  return read_csv(dir / "out" / "load_steps.csv");
}
}  // namespace

TEST(LoadStepsFile, ARowPerLoadStepWithTheLoadAndEveryProbe) {
  const auto rows = run_bar("load_steps", kBar);
  ASSERT_EQ(rows.size(), 5u);
  EXPECT_EQ(rows[0], (std::vector<std::string>{"step", "load", "mid_u", "mid_stress"}));
  // The path 0 -> 1 -> -1 at the pseudo-times 1/4, 2/4, 3/4, 1.
  const double loads[] = {0.5, 1.0, 0.0, -1.0};
  for (int k = 0; k < 4; ++k) {
    const std::vector<std::string>& row = rows[static_cast<std::size_t>(k + 1)];
    ASSERT_EQ(row.size(), 4u);
    EXPECT_EQ(std::stoi(row[0]), k + 1);
    EXPECT_NEAR(std::stod(row[1]), loads[k], 1e-15);
    if (loads[k] == 0.0) {  // back at the start: an elastic body carries nothing
      EXPECT_LT(std::abs(std::stod(row[2])), 1e-12) << "step " << k + 1;
      EXPECT_LT(std::abs(std::stod(row[3])), 1e-12) << "step " << k + 1;
      continue;
    }
    // Straight to the same pull in two steps (the default path, 0 -> 1).
    const auto direct = run_bar("load_steps_direct" + std::to_string(k),
                                bar_scene(0.01 * loads[k], "solver: {load_steps: 2}"));
    ASSERT_EQ(direct.size(), 3u);
    for (std::size_t c = 2; c < 4; ++c) {
      const double expected = std::stod(direct[2][c]);
      EXPECT_NE(expected, 0.0);
      EXPECT_NEAR(std::stod(row[c]), expected, 1e-7 * std::abs(expected))
          << "step " << k + 1 << ", " << rows[0][c];
    }
  }
}

TEST(LoadStepsFile, OneLoadStepWritesNone) {
  const auto dir = pdtest::fresh_directory("load_steps_one");
  std::ofstream(dir / "bar.yaml") << bar_scene(0.01, "solver: {load_steps: 1}");
  const auto r = pdtest::run_pd({"run", (dir / "bar.yaml").string(), "--out", (dir / "out").string()});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(std::filesystem::exists(dir / "out" / "summary.json"));
  EXPECT_FALSE(std::filesystem::exists(dir / "out" / "load_steps.csv"));
}

// With solver.duration the file gains a time column: load step i of K ends at i / K of the
// duration (pseudo-time is spread evenly over the steps). A viscoelastic bar ramped in the
// first step and held for three: the held end's load stays 1 while the reaction of the
// pulled face relaxes, so the mean stress falls step after step at constant load.
TEST(LoadStepsFile, ADurationAddsTheTimeOfEveryStep) {
  const std::string scene =
      "dimension: 2\ndomain: {box: {min: [0, 0], max: [2, 0.5]}, count: 12}\n"
      "horizon: {ratio: 3.0}\nlaw: viscoelastic_plane_strain\n"
      "materials: [{E: 200, nu: 0.3, parameters: {lambda_i: 0.6, tau_b: 1.0}}]\n"
      "boundary:\n"
      "  - {region: {side: left}, fixed: [x, y]}\n"
      "  - {region: {side: right}, displacement: {x: 0.01}}\n"
      "solver: {load_steps: 4, load_path: [0, 1, 1, 1, 1], duration: 2.5}\n"
      "probes:\n"
      "  - {name: mid_stress, quantity: stress, component: xx, region: {box: {min: [0.8, 0], max: [1.2, "
      "0.5]}}}\n";
  const auto rows = run_bar("load_steps_time", scene);
  ASSERT_EQ(rows.size(), 5u);
  EXPECT_EQ(rows[0], (std::vector<std::string>{"step", "load", "time", "mid_stress"}));
  for (int k = 0; k < 4; ++k) {
    const std::vector<std::string>& row = rows[static_cast<std::size_t>(k + 1)];
    ASSERT_EQ(row.size(), 4u);
    EXPECT_EQ(std::stoi(row[0]), k + 1);
    EXPECT_NEAR(std::stod(row[1]), 1.0, 1e-15);  // the ramp fills the first of four segments
    EXPECT_NEAR(std::stod(row[2]), 2.5 * (k + 1) / 4, 1e-15) << "step " << k + 1;
    if (k > 0) {  // each hold step relaxes the pulled bar further
      EXPECT_LT(std::stod(row[3]), std::stod(rows[static_cast<std::size_t>(k)][3]) * (1 - 1e-3))
          << "step " << k + 1;
    }
  }
}

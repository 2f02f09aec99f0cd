// The log of `pd run` (issue 21, conventions): no empty line and no line twice, for a static
// and a dynamic scene. Before: a dynamic run's summary ended with "probes:" over nothing and
// an empty line.
#include <gtest/gtest.h>

#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include "run_pd.hpp"

namespace {
void expect_clean_log(const std::string& log) {
  std::istringstream in(log);
  std::set<std::string> seen;
  int n = 0;
  for (std::string line; std::getline(in, line); ++n) {
    EXPECT_FALSE(line.empty()) << "an empty line after line " << n << " of\n" << log;
    EXPECT_TRUE(seen.insert(line).second) << "line twice: '" << line << "' in\n" << log;
  }
  EXPECT_GT(n, 5);
}
}  // namespace

TEST(RunLog, AStaticRunHasNoEmptyOrRepeatedLine) {
  const auto dir = pdtest::fresh_directory("log_static");
  const auto r = pdtest::run_pd(
      {"run", std::string(PD_SOURCE_SCENES) + "/uniaxial.yaml", "--out", (dir / "out").string()});
  ASSERT_EQ(r.status, 0) << r.err;
  expect_clean_log(r.out);
}

TEST(RunLog, ADynamicRunHasNoEmptyOrRepeatedLine) {
  const auto dir = pdtest::fresh_directory("log_dynamic");
  std::ofstream(dir / "bar.yaml")
      << "dimension: 2\ndomain: {box: {min: [0, 0], max: [1, 0.1]}, spacing: 0.025}\n"
         "law: silling_plane_strain\ninfluence: const\n"
         "materials: [{name: bar, E: 1.0, nu: 0.0, density: 1.0}]\n"
         "boundary:\n  - {region: {all: true}, fixed: [y]}\n"
         "dynamics: {method: explicit, steps: 20, output_every: 10, threads: 1}\n";
  const auto r = pdtest::run_pd({"run", (dir / "bar.yaml").string(), "--out", (dir / "out").string()});
  ASSERT_EQ(r.status, 0) << r.err;
  expect_clean_log(r.out);
}

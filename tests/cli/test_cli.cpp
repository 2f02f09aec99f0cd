// The command line's conventions: --version, --help for every command, and unknown
// options, stray arguments and unknown commands refused by name with exit code 2.
#include <gtest/gtest.h>

#include <regex>

#include "run_pd.hpp"

using pdtest::run_pd;

namespace {
const std::regex kVersion(R"(^pd \d+\.\d+\.\d+ \(commit ([0-9a-f]{12}(-dirty)?|unknown)\)$)");
const char* kCommands[] = {"laws", "check-law", "run", "study"};
}  // namespace

TEST(Cli, VersionPrintsTheVersionAndTheCommit) {
  const auto r = run_pd({"--version"});
  EXPECT_EQ(r.status, 0);
  std::string line = r.out.substr(0, r.out.find('\n'));
  EXPECT_TRUE(std::regex_match(line, kVersion)) << r.out;
}

TEST(Cli, EveryCommandHasHelp) {
  for (const char* c : kCommands) {
    const auto r = run_pd({c, "--help"});
    EXPECT_EQ(r.status, 0) << c;
    EXPECT_NE(r.out.find(std::string("Usage: pd ") + c), std::string::npos) << c << ":\n" << r.out;
    EXPECT_EQ(r.err, "") << c;
  }
  const auto top = run_pd({"--help"});
  EXPECT_EQ(top.status, 0);
  for (const char* c : kCommands) EXPECT_NE(top.out.find(c), std::string::npos) << c;
}

TEST(Cli, UnknownOptionsAreRefusedByName) {
  for (const char* c : kCommands) {
    const auto r = run_pd({c, "x.yaml", "--bogus-option"});
    EXPECT_EQ(r.status, 2) << c;
    EXPECT_NE(r.err.find("--bogus-option"), std::string::npos) << c << ":\n" << r.err;
  }
}

TEST(Cli, StrayArgumentsAreRefusedByName) {
  const auto run = run_pd({"run", "a.yaml", "stray.yaml"});
  EXPECT_EQ(run.status, 2);
  EXPECT_NE(run.err.find("stray.yaml"), std::string::npos) << run.err;
  const auto laws = run_pd({"laws", "extra"});
  EXPECT_EQ(laws.status, 2);
  EXPECT_NE(laws.err.find("extra"), std::string::npos) << laws.err;
}

TEST(Cli, AMissingOrMalformedValueIsBadUsage) {
  const auto no_scene = run_pd({"run"});
  EXPECT_EQ(no_scene.status, 2);
  EXPECT_NE(no_scene.err.find("SCENE is required"), std::string::npos) << no_scene.err;
  const auto no_out = run_pd({"run", "a.yaml", "--out"});
  EXPECT_EQ(no_out.status, 2);
  EXPECT_NE(no_out.err.find("--out"), std::string::npos) << no_out.err;
  // An empty directory is no directory: refused before the scene is read (a.yaml does not exist).
  for (const char* command : {"run", "study"}) {
    const auto empty_out = run_pd({command, "a.yaml", "--out", ""});
    EXPECT_EQ(empty_out.status, 2) << command << ": " << empty_out.err;
    EXPECT_NE(empty_out.err.find("--out"), std::string::npos) << empty_out.err;
    EXPECT_NE(empty_out.err.find("an empty path is not a directory"), std::string::npos) << empty_out.err;
  }
  const auto seed = run_pd({"check-law", "silling_plane_strain", "--seed", "many"});
  EXPECT_EQ(seed.status, 2);
  EXPECT_NE(seed.err.find("--seed"), std::string::npos) << seed.err;
}

TEST(Cli, AnUnknownCommandOrNoCommand) {
  const auto r = run_pd({"frobnicate"});
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("unknown command 'frobnicate'"), std::string::npos) << r.err;
  const auto none = run_pd({});
  EXPECT_EQ(none.status, 2);
  EXPECT_NE(none.err.find("run"), std::string::npos) << none.err;
}

TEST(Cli, TheRunLogAndSummaryNameTheVersion) {
  const auto dir = pdtest::fresh_directory("version");
  {
    std::ofstream scene(dir / "s.yaml");
    scene << "dimension: 2\ndomain: {box: {min: [0, 0], max: [1, 1]}, count: 6}\nlaw: silling_plane_strain\n"
             "materials: [{E: 1, nu: 0.25}]\nboundary:\n  - {region: {side: bottom}, fixed: [x, y]}\n"
             "  - {region: {side: top}, traction: [0, 0.01]}\noutput: {vtu: false, csv: false}\n";
  }
  const auto r = run_pd({"run", (dir / "s.yaml").string(), "--out", (dir / "out").string()});
  ASSERT_EQ(r.status, 0) << r.err;
  const auto version = run_pd({"--version"}).out;
  EXPECT_EQ(r.out.substr(0, r.out.find('\n') + 1), version);
  const std::string summary = pdtest::slurp(dir / "out" / "summary.json");
  std::smatch m;
  ASSERT_TRUE(std::regex_search(summary, m,
                                std::regex(R"re("pd": \{\s*"version": "([^"]+)",\s*"commit": "([^"]+)")re")))
      << summary;
  EXPECT_EQ("pd " + m[1].str() + " (commit " + m[2].str() + ")\n", version);
  std::filesystem::remove_all(dir);
}

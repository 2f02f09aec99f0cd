// The malformed-input runner: every scene in tests/cli/malformed/ (written by its
// make_cases.py) is run by the real `pd run` into a fresh output directory. A case ends
// with its expectation:
//   rejected: exit code 2, stderr "pd run: <message>", and nothing in the output directory;
//   warned:   exit code 0, "  warning: <message>" in the log and the same in summary.json;
//   accepted: exit code 0 and no warning (the control: the base scene is valid).
// Also the hostile scene paths: a directory, a device, a missing file.
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <string>
#include <vector>

#include "run_pd.hpp"

namespace fs = std::filesystem;

namespace {
struct Case {
  std::string name;
  fs::path file;
  std::string expect;   // rejected | warned | accepted
  std::string message;  // a regex; {file} stands for the scene's path
};

void PrintTo(const Case& c, std::ostream* os) { *os << c.file; }  // gtest: name the case, not its bytes

std::string escape_regex(const std::string& s) {
  return std::regex_replace(s, std::regex(R"([.^$|()\[\]{}*+?\\])"), R"(\$&)");
}

std::string trailing_value(const std::string& text, const std::string& key) {
  std::smatch m;
  return std::regex_search(text, m, std::regex("(^|\n)# " + key + ": ([^\n]*)")) ? m[2].str() : "";
}

std::vector<Case> cases() {
  std::vector<Case> out;
  for (const auto& e : fs::directory_iterator(PD_MALFORMED_DIR))
    if (e.path().extension() == ".yaml") {
      const std::string text = pdtest::slurp(e.path());
      out.push_back({e.path().stem().string(), e.path(), trailing_value(text, "expect"),
                     trailing_value(text, "message")});
    }
  std::sort(out.begin(), out.end(), [](const Case& a, const Case& b) { return a.name < b.name; });
  return out;
}

std::string expected(const Case& c) {
  std::string m = c.message;
  const auto p = m.find("{file}");
  if (p != std::string::npos) m.replace(p, 6, escape_regex(c.file.string()));
  return m;
}

// The files a run left in `dir` (none when it does not exist).
std::vector<std::string> left_behind(const fs::path& dir) {
  std::vector<std::string> files;
  if (fs::exists(dir))
    for (const auto& e : fs::recursive_directory_iterator(dir)) files.push_back(e.path().filename().string());
  return files;
}

class Malformed : public testing::TestWithParam<Case> {};
}  // namespace

TEST(MalformedRunner, FindsTheCases) { EXPECT_GE(cases().size(), 40u); }

TEST_P(Malformed, IsHandledAsDocumented) {
  const Case& c = GetParam();
  ASSERT_TRUE(c.expect == "rejected" || c.expect == "warned" || c.expect == "accepted")
      << c.file << ": no '# expect:'";
  const fs::path dir = pdtest::fresh_directory("malformed_" + c.name);
  const fs::path out = dir / "out";
  const auto r = pdtest::run_pd({"run", c.file.string(), "--out", out.string()});
  if (c.expect == "rejected") {
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_TRUE(std::regex_search(r.err, std::regex("^pd run: " + expected(c))))
        << "got: " << r.err << "expected: " << expected(c);
    EXPECT_EQ(left_behind(out), std::vector<std::string>{}) << "a rejected scene left files behind";
  } else {
    ASSERT_EQ(r.status, 0) << r.err;
    const std::string summary = pdtest::slurp(out / "summary.json");
    if (c.expect == "warned") {
      EXPECT_TRUE(std::regex_search(r.out, std::regex("\n  warning: " + expected(c)))) << r.out;
      EXPECT_TRUE(std::regex_search(summary, std::regex("\"warnings\": \\[\\s*\"" + expected(c)))) << summary;
    } else {
      EXPECT_EQ(r.out.find("warning"), std::string::npos) << r.out;
      EXPECT_EQ(summary.find("\"warnings\""), std::string::npos) << summary;
    }
  }
  fs::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(Cases, Malformed, testing::ValuesIn(cases()),
                         [](const testing::TestParamInfo<Case>& param) { return param.param.name; });

TEST(MalformedRunner, HostileScenePaths) {
  const fs::path dir = pdtest::fresh_directory("hostile");
  fs::create_directories(dir / "cases");
  const std::vector<std::pair<std::string, std::string>> paths{
      {(dir / "cases").string(), "is a directory, not a scene file"},
      {"/dev/null", "not a regular file"},
      {(dir / "missing.yaml").string(), "no such scene file"},
  };
  for (const auto& [path, message] : paths) {
    const auto r = pdtest::run_pd({"run", path, "--out", (dir / "out").string()});
    EXPECT_EQ(r.status, 2) << path;
    EXPECT_EQ(r.err.rfind("pd run: " + path + ": " + message, 0), 0u) << r.err;
    EXPECT_EQ(left_behind(dir / "out"), std::vector<std::string>{}) << path;
  }
  fs::remove_all(dir);
}

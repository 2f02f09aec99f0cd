// The emitted kernels as text: no kernel evaluates the same sqrt or pow twice, and
// every kernel is headed by its operation counts.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

namespace {
std::string read(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}
}  // namespace

TEST(GeneratedCode, NoKernelRepeatsASqrtOrPowCall) {
  int kernels = 0;
  for (const auto& entry : std::filesystem::directory_iterator(PD_GENERATED_DIR)) {
    if (entry.path().extension() != ".cpp") continue;
    std::istringstream in(read(entry.path()));
    std::string line, kernel;
    std::set<std::string> calls;
    const std::regex call(R"(std::(sqrt|pow)\([^;]*)");
    while (std::getline(in, line)) {
      if (line.rfind("// ", 0) == 0 && line.find(": per bond ") != std::string::npos) {
        kernel = line;
        calls.clear();
        ++kernels;
        continue;
      }
      for (std::sregex_iterator it(line.begin(), line.end(), call), end; it != end; ++it)
        EXPECT_TRUE(calls.insert(it->str()).second)
            << entry.path().filename() << " " << kernel << "\n  repeats " << it->str();
    }
  }
  EXPECT_GT(kernels, 10);
}

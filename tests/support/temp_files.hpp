// Scratch directories and file reading shared by the tests that run `pd` as a process.
#pragma once

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace pd::test {

// A path in the temp dir unique to this process, with nothing there: two builds testing
// at once (or two ctest jobs of one binary) never share a scratch name.
inline std::filesystem::path scratch_path(const std::string& name) {
  const std::filesystem::path p =
      std::filesystem::temp_directory_path() / (name + "_" + std::to_string(getpid()));
  std::filesystem::remove_all(p);
  return p;
}

// An empty directory in the temp dir, unique to this process.
inline std::filesystem::path fresh_directory(const std::string& name) {
  const std::filesystem::path dir = scratch_path(name);
  std::filesystem::create_directories(dir);
  return dir;
}

inline std::string read_text(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace pd::test

// pdgen: the build-time generator driver. Its stages, each in its own files:
//   laws/*.cpp (DSL, registered via PDGEN_LAW)       generator/law/law.cpp
//   -> horizon sums classified (moment/state)         generator/law/law.cpp
//   -> derivatives, chain rule through sums           generator/diff/, generator/law/kernels.cpp
//   -> lowering to binary IR, hash-consed             generator/emit/lower.cpp
//   -> scheduling, CSE, hoisting, C++ text            generator/emit/emitter.cpp
//   -> files and law table                            generator/emit/files.cpp
// Usage: pdgen --out DIR   (rewrites a file only when its content changes)
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

#include "pdgen/files.hpp"

int main(int argc, char** argv) {
  std::string out_dir;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--out" && i + 1 < argc) {
      out_dir = argv[++i];
    } else {
      std::cerr << "usage: pdgen --out DIR\n";
      return 2;
    }
  }
  if (out_dir.empty()) {
    std::cerr << "usage: pdgen --out DIR\n";
    return 2;
  }
  try {
    const auto files = pdgen::generate_all_files();
    std::filesystem::create_directories(out_dir);
    int written = 0;
    for (const auto& [name, content] : files) {
      const std::filesystem::path path = std::filesystem::path(out_dir) / name;
      std::ifstream in(path, std::ios::binary);
      std::ostringstream old;
      if (in) old << in.rdbuf();
      if (in && old.str() == content) continue;
      const std::filesystem::path tmp = path.string() + ".tmp";
      {
        std::ofstream f(tmp, std::ios::binary);
        f << content;
        if (!f) throw std::runtime_error("cannot write " + tmp.string());
      }
      std::filesystem::rename(tmp, path);
      ++written;
    }
    std::cout << "pdgen: " << files.size() << " files, " << written << " rewritten in " << out_dir << "\n";
  } catch (const std::exception& e) {
    std::cerr << "pdgen: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}

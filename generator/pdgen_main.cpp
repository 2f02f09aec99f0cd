// pdgen: the build-time generator driver. It runs the stages, each in its own files:
//   laws/*.cpp (DSL, registered via PDGEN_LAW)       generator/law/law.cpp
//   -> horizon sums classified (moment/state)         generator/law/law.cpp
//   -> derivatives, chain rule through sums           generator/diff/, generator/law/kernels.cpp
//   -> lowering to binary IR, hash-consed             generator/emit/lower.cpp
//   -> scheduling, CSE, hoisting, C++ text            generator/emit/emitter.cpp
//   -> dense local matrix from the factors             generator/emit/form_kernel.cpp
//   -> files and law table                            generator/emit/files.cpp
// Usage: pdgen --out DIR   (rewrites a file only when its content changes, and removes
// the .cpp/.hpp files in DIR it no longer emits, e.g. those of a deleted law)
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>

#include "pdgen/files.hpp"
#include "pdgen/kernels.hpp"

namespace {
using namespace pdgen;

// Every registered law and influence function through every stage. A failing law is
// reported with its file and name.
GeneratedFiles generate() {
  GeneratedFiles files;
  std::set<std::string> law_names;
  for (const LawEntry& e : law_registry()) {
    law_under_construction().clear();
    try {
      const Law law = e.build();
      if (!law.has_force()) throw std::invalid_argument("the law declares no force state: call law.force(t)");
      std::vector<HistoryDef> all_history = law.history();
      all_history.insert(all_history.end(), law.particle_history().begin(), law.particle_history().end());
      for (const HistoryDef& h : all_history)
        if (!h.has_update)
          throw std::invalid_argument("history '" + h.name +
                                      "' is declared but never updated: call law.update");
      if (!law_names.insert(law.name()).second)
        throw std::invalid_argument("law '" + law.name() + "' is registered twice");
      files.add_law(e.file_stem, law,
                    {emit_variant(law, "damaged"), emit_variant(law.with_alpha_folded(), "intact")});
    } catch (const std::exception& ex) {
      const std::string& name = law_under_construction();
      throw std::invalid_argument(e.source + ": " + (name.empty() ? "" : "law '" + name + "': ") + ex.what());
    }
  }
  for (const InfluenceDef& inf : influence_registry()) {
    const KernelProgram p = influence_kernel(inf);
    files.add_influence(inf, {"weight", p.name, emit_kernel(p)});
  }
  return files;
}

// Writes the files whose content changed (through a temporary and a rename) and removes
// the generated sources in `dir` that are no longer emitted. Returns the count written.
int write_files(const std::filesystem::path& dir, const std::map<std::string, std::string>& files) {
  std::filesystem::create_directories(dir);
  int written = 0;
  for (const auto& [name, content] : files) {
    const std::filesystem::path path = dir / name;
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
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    const std::string ext = entry.path().extension().string();
    if ((ext == ".cpp" || ext == ".hpp") && !files.count(entry.path().filename().string())) {
      std::filesystem::remove(entry.path());
      std::cout << "pdgen: removed " << entry.path().string() << " (no longer emitted)\n";
    }
  }
  return written;
}
}  // namespace

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
    const auto files = generate().files();
    const int written = write_files(out_dir, files);
    std::cout << "pdgen: " << files.size() << " files, " << written << " rewritten in " << out_dir << "\n";
  } catch (const std::exception& e) {
    std::cerr << "pdgen: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}

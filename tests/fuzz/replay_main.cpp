// Replays every file of a fuzz corpus through the fuzz target (for builds without
// libFuzzer): a regression test that the corpus parses or fails cleanly.
//
//   fuzz_<target>_replay CORPUS_DIR [--expect VERDICTS]
//
// VERDICTS lists seeds whose outcome is known, one per line, `parse NAME` or `refuse NAME`
// (NAME relative to CORPUS_DIR; `#` starts a comment): a VTK-written file or a real
// checkpoint must still parse, a seed kept for the bug it exposed must still be refused.
// A clean refusal is a pass for any other input, so without the list a reader that began
// refusing every valid file would pass the replay unnoticed. PD_FUZZ_REPLAY_VERBOSE=1
// prints each input's outcome (to write a list).
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "fuzz_verdict.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

namespace {

std::string read_bytes(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// NAME -> true (must parse) / false (must be refused); exits on a malformed list.
std::map<std::string, bool> read_verdicts(const char* path) {
  std::ifstream in(path);
  if (!in) {
    std::fprintf(stderr, "%s: cannot open\n", path);
    std::exit(2);
  }
  std::map<std::string, bool> verdicts;
  std::string line;
  for (int n = 1; std::getline(in, line); ++n) {
    if (const auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
    std::istringstream words(line);
    std::string verdict, name, extra;
    if (!(words >> verdict)) continue;
    if ((verdict != "parse" && verdict != "refuse") || !(words >> name) || (words >> extra)) {
      std::fprintf(stderr, "%s:%d: expected `parse NAME` or `refuse NAME`\n", path, n);
      std::exit(2);
    }
    verdicts[name] = verdict == "parse";
  }
  return verdicts;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2 && !(argc == 4 && std::string(argv[2]) == "--expect")) {
    std::fprintf(stderr, "usage: %s CORPUS_DIR [--expect VERDICTS]\n", argv[0]);
    return 2;
  }
  const std::filesystem::path corpus = argv[1];
  std::map<std::string, bool> expected = argc == 4 ? read_verdicts(argv[3]) : std::map<std::string, bool>{};
  const bool verbose = std::getenv("PD_FUZZ_REPLAY_VERBOSE") != nullptr;
  int files = 0, parsed = 0, wrong = 0;
  for (const auto& e : std::filesystem::recursive_directory_iterator(corpus)) {
    if (!e.is_regular_file()) continue;
    const std::string t = read_bytes(e.path());
    pdfuzz::accepted = false;
    LLVMFuzzerTestOneInput(reinterpret_cast<const uint8_t*>(t.data()), t.size());
    ++files;
    parsed += pdfuzz::accepted;
    const std::string name = e.path().lexically_relative(corpus).generic_string();
    if (verbose) std::printf("%s %s\n", pdfuzz::accepted ? "parse" : "refuse", name.c_str());
    const auto it = expected.find(name);
    if (it == expected.end()) continue;
    if (it->second != pdfuzz::accepted) {
      std::fprintf(stderr, "%s: %s, but it must be %s\n", e.path().c_str(),
                   pdfuzz::accepted ? "parsed" : "refused", it->second ? "parsed" : "refused");
      ++wrong;
    }
    expected.erase(it);
  }
  for (const auto& [name, must_parse] : expected) {
    std::fprintf(stderr, "%s: listed as `%s` but not in the corpus\n", (corpus / name).c_str(),
                 must_parse ? "parse" : "refuse");
    ++wrong;
  }
  std::printf("replayed %d inputs: %d parsed, %d refused; %d against the verdicts\n", files, parsed,
              files - parsed, wrong);
  return files > 0 && wrong == 0 ? 0 : 1;
}

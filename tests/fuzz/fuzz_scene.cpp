// Fuzz target for the scene reader (libFuzzer): any input must either parse into a
// scene or raise SceneError -- never crash, hang, leak or trip a sanitizer. Parsed
// scenes are also discretised when small, which exercises the geometry code.
//
// Built with clang as `fuzz_scene` (CMake option PD_FUZZ, see tests/CMakeLists.txt);
// `scripts/fuzz.sh [seconds]` runs it. Without libFuzzer the same entry point is
// compiled into `fuzz_scene_replay`, which replays tests/fuzz/corpus/ as a ctest.
#include <cstddef>
#include <cstdint>
#include <string>

#include "discretize/discretization.hpp"
#include "fuzz_verdict.hpp"
#include "input/scene.hpp"
#include "input/yaml_keys.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const pd::Scene s = pd::parse_scene(text, "fuzz.yaml");
    double cells = 1;
    for (int i = 0; i < s.dim; ++i) cells *= (s.hi[i] - s.lo[i]) / s.h + 1;
    if (cells < 2e4) pd::discretize(s);
    pdfuzz::accepted = true;
  } catch (const pd::SceneError&) {
  }
  return 0;
}

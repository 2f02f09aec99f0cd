// Fuzz target for the particle .vtu reader (`domain.particles: body.vtu`: libxml2, base64,
// raw appended data, UInt32/UInt64 headers, zlib blocks): any input must either parse
// into a point cloud that keeps the reader's promises (finite positions, positive
// volumes) or raise SceneError -- never crash, hang, leak, trip a sanitizer or allocate
// what a block header merely claims. Each input is read as a 2D and as a 3D body.
//
// Built with clang as `fuzz_particle_vtu` (PD_FUZZ); without libFuzzer the same entry
// point replays tests/fuzz/corpus/particle_vtu/ as a ctest (replay_main.cpp).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "fuzz_verdict.hpp"
#include "input/particle_vtu.hpp"
#include "input/yaml_keys.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  for (const int dim : {2, 3}) {
    try {
      const pd::ParticleFile f = pd::parse_particle_vtu(bytes, "fuzz.vtu", dim);
      if (f.size() == 0 || f.x.size() != static_cast<std::size_t>(f.size() * dim)) std::abort();
      for (const double x : f.x)
        if (!std::isfinite(x)) std::abort();
      for (const double v : f.volume)
        if (!(v > 0) || !std::isfinite(v)) std::abort();
      pdfuzz::accepted = true;
    } catch (const pd::SceneError&) {
    }
  }
  return 0;
}

// Fuzz target for the particle CSV reader (`domain.particles: body.csv`): any input must
// either parse into a point cloud that keeps the reader's promises (finite positions,
// positive volumes, one material entry per particle) or raise SceneError -- never crash,
// hang, leak or trip a sanitizer. Each input is read as a 2D and as a 3D body, and its
// material column is resolved against a two-material scene.
//
// Built with clang as `fuzz_particle_csv` (PD_FUZZ); without libFuzzer the same entry
// point replays tests/fuzz/corpus/particle_csv/ as a ctest (replay_main.cpp).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "fuzz_verdict.hpp"
#include "input/particle_file.hpp"
#include "input/yaml_keys.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  for (const int dim : {2, 3}) {
    try {
      const pd::ParticleFile f = pd::parse_particle_csv(text, "fuzz.csv", dim);
      if (f.size() == 0 || f.x.size() != static_cast<std::size_t>(f.size() * dim) ||
          f.material.size() != f.volume.size() || f.line.size() != f.volume.size())
        std::abort();  // a cloud the reader promised never to return
      for (const double x : f.x)
        if (!std::isfinite(x)) std::abort();
      for (const double v : f.volume)
        if (!(v > 0) || !std::isfinite(v)) std::abort();
      pd::particle_materials(f, {"steel", "glass"});
      pdfuzz::accepted = true;
    } catch (const pd::SceneError&) {
    }
  }
  return 0;
}

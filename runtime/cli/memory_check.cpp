#include "cli/memory_check.hpp"

#include <fmt/core.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "kernel_abi.hpp"

namespace pd::cli {

MemoryEstimate estimate_memory(const Scene& scene) {
  const int d = scene.dim;
  MemoryEstimate e;
  e.particles = 1;
  for (int i = 0; i < d; ++i) e.particles *= std::floor((scene.hi[i] - scene.lo[i]) / scene.h + 0.5);
  // Lattice sites within delta of a site, the centre excluded: the horizon ball's volume in h units.
  const double r = scene.delta() / scene.h;
  const double per_family = std::max(0.0, (d == 2 ? M_PI * r * r : 4.0 / 3.0 * M_PI * r * r * r) - 1);
  e.bonds = e.particles * per_family;
  // Bonds (particles.hpp): neighbor (int), xi (d doubles), length, w, alpha; particles:
  // x (d doubles), volume, material (int), offsets (int), delta, and u, r, du (d doubles each).
  const double per_bond = 4 + 8.0 * (d + 3), per_particle = 8.0 * d + 8 + 4 + 4 + 8 + 3 * 8.0 * d;
  e.bytes = e.bonds * per_bond + e.particles * per_particle;
  // A law with states couples every two particles of a family: a row holds about the
  // sites within 2 delta. A law without states couples a family's center with each
  // neighbour only (Coupling::pairwise): the sites within delta.
  const abi::LawDescriptor* law = abi::find_law(scene.law);
  const double reach = law != nullptr && law->n_states == 0 ? 1.0 : std::pow(2.0, d);
  if (!scene.dynamics && scene.solver.linear != LinearMethod::matrix_free)
    e.tangent_nonzeros = e.particles * (reach * per_family + 1) * d * d;
  return e;
}

std::optional<double> available_memory() {
  std::ifstream in("/proc/meminfo");
  std::string key;
  double kb = 0;
  std::string unit;
  while (in >> key >> kb >> unit)
    if (key == "MemAvailable:") return kb * 1024;
  return std::nullopt;
}

namespace {
std::string gib(double bytes) { return fmt::format("{:.3g} GiB", bytes / (1024.0 * 1024 * 1024)); }
}  // namespace

std::optional<std::string> memory_refusal(const Scene& scene, std::optional<double> available) {
  if (!available) return std::nullopt;
  const MemoryEstimate e = estimate_memory(scene);
  if (e.bytes <= *available) return std::nullopt;
  return fmt::format(
      "{}: domain: the scene needs at least {} of memory for its particles and bonds alone ({:.3g} "
      "particles, "
      "{:.3g} bonds at delta/h = {:.4g}{}), and this machine has {} available (MemAvailable in "
      "/proc/meminfo): "
      "coarsen domain.spacing/count or reduce the horizon",
      scene.file, gib(e.bytes), e.particles, e.bonds / 2, scene.delta() / scene.h,
      e.tangent_nonzeros > 0
          ? fmt::format("; an assembled tangent would add about {:.3g} nonzeros", e.tangent_nonzeros)
          : std::string(),
      gib(*available));
}

}  // namespace pd::cli

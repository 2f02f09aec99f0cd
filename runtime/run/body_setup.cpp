#include "run/body_setup.hpp"

#include <fmt/core.h>

#include <stdexcept>

#include "discretize/discretization.hpp"
#include "material/elastic_constants.hpp"

namespace pd {

BodySetup set_up_body(const Scene& scene, RunSummary& summary) {
  BodySetup b;
  b.law = abi::find_law(scene.law);
  b.influence = abi::find_influence(scene.influence);
  if (!b.law || !b.influence) throw std::invalid_argument("unknown law or influence function");
  b.particles = discretize(scene);
  b.bonds = find_bonds(b.particles, scene.delta(), b.influence->weight);
  summary.scene = scene.file;
  summary.law = b.law->name;
  summary.influence = b.influence->name;
  summary.particles = b.particles.size();
  summary.bonds = b.bonds.bond_count() / 2;
  std::vector<int> crossed;
  summary.broken_bonds = cut_bonds(scene.cracks, b.particles, b.bonds, &crossed) / 2;
  summary.warnings = scene.warnings;
  for (std::size_t c = 0; c < scene.cracks.size(); ++c)
    if (crossed[c] == 0)
      summary.warnings.push_back(scene.cracks[c].where + ": the crack crosses no bond (it lies outside the body, in a hole, "
                                 "or between particles closer than a spacing): it has no effect");
  const Particles& p = b.particles;
  for (int i = 0; i < p.size(); ++i)
    if (b.bonds.family_size(i) == 0)
      throw std::runtime_error(fmt::format("particle {} at ({:.6g}, {:.6g}) has no neighbour within the horizon", i,
                                           p.x[i * p.dim], p.x[i * p.dim + 1]));
  b.quality = check_family_quality(p, b.bonds, b.influence->weight, b.influence->name, scene.h);
  for (const MaterialSpec& m : scene.materials) b.params.push_back(law_parameters(*b.law, m.elastic, m.plane, m.parameters));
  return b;
}

}  // namespace pd

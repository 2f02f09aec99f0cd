#include "run/body_setup.hpp"

#include <fmt/core.h>

#include <stdexcept>

#include "discretize/discretization.hpp"
#include "discretize/partial_volume.hpp"
#include "material/elastic_constants.hpp"

namespace pd {

BodySetup set_up_body(const Scene& scene, RunSummary& summary) {
  BodySetup b;
  b.law = abi::find_law(scene.law);
  b.influence = abi::find_influence(scene.influence);
  if (!b.law || !b.influence) throw std::invalid_argument("unknown law or influence function");
  b.particles = discretize(scene);
  b.bonds = find_quadrature_bonds(b.particles, scene.delta(), scene.h, scene.quadrature, b.influence->weight);
  summary.scene = scene.file;
  summary.law = b.law->name;
  summary.influence = b.influence->name;
  summary.particles = b.particles.size();
  summary.bonds = b.bonds.bond_count() / 2;
  summary.broken_bonds = cut_bonds(scene.cracks, b.particles, b.bonds) / 2;
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

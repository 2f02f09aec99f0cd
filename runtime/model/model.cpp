// build_model: scene -> particles, bonds, law parameters, family checks.
#include "model/model.hpp"

#include <fmt/core.h>

#include <stdexcept>

#include "discretize/discretization.hpp"
#include "input/yaml_keys.hpp"  // SceneError
#include "discretize/partial_volume.hpp"
#include "material/admissible_poisson.hpp"
#include "material/elastic_constants.hpp"

namespace pd {

Model build_model(const Scene& scene) {
  Model m;
  m.law = abi::find_law(scene.law);
  m.influence = abi::find_influence(scene.influence);
  if (!m.law || !m.influence) throw std::invalid_argument("unknown law or influence function");
  m.particles = discretize(scene);
  m.bonds = find_quadrature_bonds(m.particles, scene.delta(), scene.h, scene.quadrature, m.influence->weight);
  m.bond_count = m.bonds.bond_count() / 2;
  std::vector<int> crossed;
  m.cut_by_cracks = cut_bonds(scene.cracks, m.particles, m.bonds, &crossed) / 2;
  m.warnings = scene.warnings;
  for (std::size_t c = 0; c < scene.cracks.size(); ++c)
    if (crossed[c] == 0)
      m.warnings.push_back(scene.cracks[c].where + ": the crack crosses no bond (it lies outside the body, in a hole, "
                           "or between particles closer than a spacing): it has no effect");
  const Particles& p = m.particles;
  for (int i = 0; i < p.size(); ++i)
    if (m.bonds.family_size(i) == 0)
      throw SceneError(fmt::format("particle {} at ({:.6g}, {:.6g}) has no neighbour within the horizon", i,
                                           p.x[i * p.dim], p.x[i * p.dim + 1]));
  m.quality = check_family_quality(p, m.bonds, m.influence->weight, m.influence->name, scene.h);
  for (const MaterialSpec& mat : scene.materials)
    m.params.push_back(law_parameters(*m.law, mat.elastic, mat.plane, mat.parameters));
  if (scene.quadrature == Quadrature::Obq)
    m.collocation = std::make_unique<Collocation>(make_obq_collocation(m.particles, m.bonds, m.collocation_description));
  for (const MaterialSpec& mat : scene.materials) warn_if_poisson_ratio_differs(*m.law, mat.elastic, mat.plane, mat.name);
  return m;
}

ProblemSize Model::size(const Scene& scene, double short_family_size) const {
  return {particles.size(), 2.0 * static_cast<double>(bond_count) / particles.size(), particles.dim,
          scene.delta() / scene.h, short_family_size};
}

AssemblerOptions attach_assembler(Model& model, const Scene& scene, bool matrix, int threads) {
  AssemblerOptions options;
  // A scene with damage needs the damaged variant from the start: bonds may break.
  options.intact = model.cut_by_cracks == 0 && !scene.damage;
  options.matrix = matrix;
  options.threads = threads;
  options.collocation = model.collocation.get();
  model.assembler = std::make_unique<FamilyAssembler>(model.particles, model.bonds, *model.law, model.params, options);
  return options;
}

}  // namespace pd

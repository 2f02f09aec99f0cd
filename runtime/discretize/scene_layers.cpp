// From a scene's `method: fictitious_layer` conditions to the DofMap's ties.
#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

#include "discretize/discretization.hpp"
#include "discretize/fictitious_layer.hpp"
#include "fields/analytic.hpp"
#include "input/yaml_keys.hpp"

namespace pd {

namespace {

// Fills the traction variant's 2D constants (sigma_nn = M eps_nn + lambda eps_tt) of the
// material as the scene's plane assumption reads it.
void plane_constants(const MaterialSpec& mat, LayerCondition& c) {
  const IsotropicElastic& e = mat.elastic;
  if (mat.plane == PlaneAssumption::Stress) {
    c.M = e.E / (1 - e.nu * e.nu);
    c.lambda = e.E * e.nu / (1 - e.nu * e.nu);
  } else {
    c.M = e.lambda + 2 * e.G;
    c.lambda = e.lambda;
  }
  c.mu = e.G;
}

}  // namespace

std::vector<TiedDof> scene_layer_ties(const Scene& scene, const Particles& particles) {
  using K = BoundaryCondition::Kind;
  std::vector<char> body(static_cast<std::size_t>(particles.size()), 1);
  std::vector<std::vector<int>> layers(scene.boundary.size());
  for (std::size_t ci = 0; ci < scene.boundary.size(); ++ci) {
    const BoundaryCondition& bc = scene.boundary[ci];
    if (bc.method != BoundaryCondition::Method::fictitious_layer) continue;
    layers[ci] = region_particles(bc.region, particles, scene);
    if (layers[ci].empty()) throw SceneError(bc.where + ": the fictitious layer's region holds no particle");
    for (int p : layers[ci]) {
      if (!body[p]) throw SceneError(bc.where + ": the fictitious layer overlaps another fictitious layer");
      body[p] = 0;
    }
  }
  std::vector<TiedDof> ties;
  std::vector<char> target(body.size());
  for (std::size_t ci = 0; ci < scene.boundary.size(); ++ci) {
    const BoundaryCondition& bc = scene.boundary[ci];
    if (layers[ci].empty()) continue;
    std::fill(target.begin(), target.end(), 1);
    for (int p : layers[ci]) target[p] = 0;
    LayerCondition c;
    for (int k = 0; k < 3; ++k) c.face.point[k] = bc.face_point[k], c.face.normal[k] = bc.face_normal[k];
    if (bc.kind == K::Traction) {
      c.kind = LayerCondition::Kind::traction;
      for (int k = 0; k < 3; ++k) c.traction[k] = bc.values[k];
      plane_constants(scene.materials[static_cast<std::size_t>(particles.material[layers[ci][0]])], c);
    } else {
      c.prescribed = bc.components;
      if (bc.kind == K::Displacement) {
        const Point v = bc.values;
        c.value = [v](const double*) { return v; };
      } else if (bc.kind == K::Field) {
        auto field = std::make_shared<const AnalyticField>(bc.field, scene.materials[0].elastic);
        if (field->name() == "rotation")
          throw SceneError(
              bc.where + ": a rotation is not proportional to the load; a fictitious layer cannot carry it");
        c.value = [field](const double* x) { return field->displacement(x); };
      }  // fixed: U* = 0
    }
    try {
      std::vector<TiedDof> t = fictitious_layer_ties(particles, layers[ci], target, c);
      ties.insert(ties.end(), std::make_move_iterator(t.begin()), std::make_move_iterator(t.end()));
    } catch (const std::invalid_argument& e) {
      throw SceneError(bc.where + ": " + e.what());
    }
  }
  try {
    compose_ties(ties, particles.size() * particles.dim);
  } catch (const std::invalid_argument& e) {
    throw SceneError(scene.file + ": boundary: " + e.what());
  }
  return ties;
}

}  // namespace pd

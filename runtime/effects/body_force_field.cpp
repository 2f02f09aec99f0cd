// The scene's `body_force: {field: {solution, ...}, region}`: the body force density b(x)
// of an analytic field at each particle of the region, times the particle's volume (its
// quadrature weight): f_i = b(x_i) V_i. The fields with a body force are paper 001's
// manufactured solutions u1 and u2 (b = -div sigma, fields/manufactured.hpp), so a scene
// can impose u on a Dirichlet layer (`field:` condition), load the rest with b, and
// compare against the same u (`reference:`). A dead load: scaled by the load factor (a
// dynamic run applies it in full from t = 0), no stiffness.
#include <fmt/core.h>

#include <cmath>

#include "discretize/discretization.hpp"
#include "effects/loads.hpp"
#include "fields/analytic.hpp"
#include "input/yaml_keys.hpp"

namespace pd {

std::unique_ptr<Effect> make_body_force_field(const Scene& s, const Particles& p) {
  if (!s.body_force) return nullptr;
  const BodyForceField& spec = *s.body_force;
  const AnalyticField field(spec.field, s.materials[0].elastic);
  if (!field.has_body_force())
    throw SceneError(spec.where + ": field: solution '" + field.name() + "' has no body force density");
  const auto ids = region_particles(spec.region, p, s);
  if (ids.empty()) throw SceneError(spec.where + ": the region holds no particle");
  const int d = p.dim;
  std::vector<double> f(static_cast<std::size_t>(p.size()) * d, 0.0);
  for (int i : ids) {
    const auto b = field.body_force(p.position(i));
    for (int c = 0; c < d; ++c) {
      f[static_cast<std::size_t>(i) * d + c] = b[c] * p.volume[i];
      if (!std::isfinite(f[static_cast<std::size_t>(i) * d + c]))
        throw SceneError(fmt::format("{}: the body force is not finite at particle {}", spec.where, i));
    }
  }
  return make_nodal_forces(std::move(f),
                           fmt::format("body force density of field {} times particle volume on {} particles",
                                       field.name(), ids.size()));
}

}  // namespace pd

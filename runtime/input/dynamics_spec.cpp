// Readers of the `dynamics` and `damage` sections; every key checked, errors name file:line:key.
#include "input/dynamics_spec.hpp"

#include <algorithm>

#include "input/enum_choice.hpp"
#include "input/scene_sections.hpp"
#include "input/yaml_keys.hpp"

namespace pd {

namespace {
Point read_vector(const YamlAt& at, int dim) { return to_point(at, dim, "components"); }

InitialCondition read_initial(const YamlAt& at, int dim) {
  MapReader m(at);
  InitialCondition ic;
  ic.where = at.location();
  if (m.has("region")) ic.region = read_region(m.get("region"), dim);
  if (!m.has("displacement") && !m.has("velocity") && !m.has("gradient"))
    at.fail("give displacement, velocity, gradient or several of them");
  if (m.has("displacement")) ic.displacement = read_vector(m.get("displacement"), dim);
  if (m.has("gradient")) {
    const YamlAt g = m.get("gradient");
    if (!g.node.IsSequence() || static_cast<int>(g.node.size()) != dim)
      g.fail("expected " + std::to_string(dim) + " rows of " + std::to_string(dim) + " numbers (du_i/dx_j)");
    for (int i = 0; i < dim; ++i)
      ic.gradient[i] = read_vector(g.element(g.node[i], static_cast<std::size_t>(i)), dim);
    ic.has_gradient = true;
  }
  if (m.has("origin")) {
    if (!ic.has_gradient) m.get("origin").fail("origin belongs to a gradient; give gradient too");
    ic.origin = read_vector(m.get("origin"), dim);
  }
  if (m.has("velocity")) ic.velocity = read_vector(m.get("velocity"), dim);
  if (m.has("gaussian")) {
    MapReader g(m.get("gaussian"));
    const YamlAt axis = g.get("axis");
    const std::string a = as_text(axis);
    ic.axis = axis_index(a, dim);
    if (ic.axis < 0) axis.fail("'" + a + "' is not an axis of a " + std::to_string(dim) + "D scene");
    ic.center = g.number("center");
    ic.width = g.number("width");
    if (!(ic.width > 0)) g.get("width").fail("width must be positive");
    g.finish();
    ic.gaussian = true;
  }
  m.finish();
  return ic;
}
}  // namespace

DynamicsSpec read_dynamics(const YamlAt& at, int dim) {
  MapReader m(at);
  DynamicsSpec d;
  d.method = enum_choice(m, "method", DynamicsMethod::explicit_verlet);
  const bool explicit_method = d.method == DynamicsMethod::explicit_verlet;
  if (explicit_method) {
    d.steps = m.integer("steps", 0);
    if (d.steps < 1)
      (m.has("steps") ? m.get("steps") : at).fail("steps (the number of time steps) must be at least 1");
    d.dt = m.number("dt", 0.0);
    if (d.dt < 0 || (m.has("dt") && d.dt == 0))
      m.get("dt").fail("dt must be positive (omit it to use the stable-step estimate)");
    d.safety_factor = m.number("safety_factor", 0.8);
    if (!(d.safety_factor > 0 && d.safety_factor <= 1))
      m.get("safety_factor").fail("safety_factor must lie in (0, 1]");
    if (m.has("dt") && m.has("safety_factor"))
      m.get("safety_factor").fail("give dt or safety_factor, not both");
    d.damping = m.number("damping", 0.0);
    if (d.damping < 0) m.get("damping").fail("damping must not be negative");
  } else {
    d.steps = m.integer("steps", 100000);
    if (d.steps < 1) m.get("steps").fail("steps (the iteration limit) must be at least 1");
    d.tolerance = m.number("tolerance", 1e-8);
    if (!(d.tolerance > 0 && d.tolerance < 1)) m.get("tolerance").fail("tolerance must lie in (0, 1)");
    for (const char* key : {"dt", "safety_factor", "damping"})
      if (m.has(key))
        m.get(key).fail(std::string(key) + " belongs to method: explicit (relaxation picks its own)");
  }
  d.output_every = m.integer("output_every", 0);
  d.snapshot_every = m.integer("snapshot_every", 0);
  d.checkpoint_every = m.integer("checkpoint_every", 0);
  for (const char* key : {"output_every", "snapshot_every", "checkpoint_every"})
    if (m.has(key) && m.integer(key, 0) < 0) m.get(key).fail(std::string(key) + " must not be negative");
  if (d.output_every == 0) d.output_every = std::max(1, d.steps / 100);
  d.progress_seconds = m.number("progress_seconds", 2.0);
  if (d.progress_seconds < 0) m.get("progress_seconds").fail("progress_seconds must not be negative");
  d.threads = m.integer("threads", 0);
  if (d.threads < 0) m.get("threads").fail("threads must not be negative (0: OpenMP's default)");
  d.restart = m.text("restart", "");
  if (m.has("initial")) {
    const YamlAt list = m.get("initial");
    require_list(list);
    for (std::size_t i = 0; i < list.node.size(); ++i)
      d.initial.push_back(read_initial(list.element(list.node[i], i), dim));
  }
  m.finish();
  return d;
}

DamageSpec read_damage(const YamlAt& at) {
  MapReader m(at);
  DamageSpec d;
  d.where = at.location();
  if (m.has("critical_stretch") == m.has("fracture_energy"))
    at.fail("give exactly one of critical_stretch, fracture_energy");
  if (m.has("critical_stretch")) {
    d.critical_stretch = m.number("critical_stretch");
    if (!(d.critical_stretch > 0)) m.get("critical_stretch").fail("critical_stretch must be positive");
  } else {
    d.fracture_energy = m.number("fracture_energy");
    if (!(d.fracture_energy > 0)) m.get("fracture_energy").fail("fracture_energy must be positive");
  }
  d.tension_only = m.boolean("tension_only", true);
  d.max_resolves = m.integer("max_resolves", 50);
  if (m.has("max_resolves")) {
    d.max_resolves_where = m.get("max_resolves").location();
    if (d.max_resolves < 1) m.get("max_resolves").fail("max_resolves must be at least 1");
  }
  m.finish();
  return d;
}

}  // namespace pd

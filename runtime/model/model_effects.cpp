// Model::build_effects: the list of the scene's effects, in the order the run log names them.
// A new effect is one file in effects/ plus one line here (and its scene key).
#include <fmt/core.h>

#include "effects/damage_evolution.hpp"
#include "effects/inertia.hpp"
#include "effects/loads.hpp"
#include "effects/time_step.hpp"
#include "model/model.hpp"

namespace pd {

namespace {
void add(std::vector<std::unique_ptr<Effect>>& effects, std::unique_ptr<Effect> e) {
  if (e) effects.push_back(std::move(e));
}

// A static run: one dead-load vector for every traction and body-force condition, one
// crack-pressure effect for all cracks; all follow the load factor.
void add_static_loads(Model& m, const Scene& s) {
  add(m.effects, make_external_loads(s, m.particles));
  add(m.effects, make_crack_pressure(s, m.particles, m.bonds));
  add(m.effects, make_body_force_field(s, m.particles));
}

// A dynamic run: each condition and each pressurised crack scaled by its own function
// of time (relaxation has none: every load in full).
void add_timed_loads(Model& m, const Scene& s) {
  for (const BoundaryCondition& bc : s.boundary) {
    if (bc.kind != BoundaryCondition::Kind::Traction && bc.kind != BoundaryCondition::Kind::BodyForce)
      continue;
    if (bc.method == BoundaryCondition::Method::fictitious_layer) continue;  // carried by the layer's ties
    add(m.effects,
        make_timed(make_external_loads(s, m.particles, std::span(&bc, 1)), bc.time.value_or(TimeFunction{}),
                   bc.time ? ", times " + bc.time->describe() : std::string()));
  }
  for (const Crack& crack : s.cracks)
    if (auto e = make_crack_pressure(std::span(&crack, 1), s.h, m.particles, m.bonds))
      add(m.effects,
          make_timed(std::move(e), crack.time.value_or(TimeFunction{}),
                     crack.time ? ", times " + crack.time->describe() : std::string(", constant in time")));
  if (auto e = make_body_force_field(s, m.particles))
    add(m.effects, make_timed(std::move(e), TimeFunction{}, ", constant in time"));
}
// A dynamic run's inertia: explicit dynamics' rho V (and its time step) with the viscous
// damping, or relaxation's fictitious density; both from the row sums of the stiffness at
// the reference configuration (ForceOperator::stiffness_row_sums).
void add_inertia(Model& m, const Scene& s) {
  const std::vector<double> rows = m.assembler->stiffness_row_sums(nullptr);
  if (s.dynamics->method == DynamicsMethod::explicit_verlet) {
    std::unique_ptr<Inertia> inertia = make_inertia(s, m.particles, rows);
    m.inertia = inertia.get();
    add(m.effects, std::move(inertia));
    std::unique_ptr<ViscousDamping> damping = make_viscous_damping(s);
    m.damping = damping.get();
    add(m.effects, std::move(damping));
  } else {
    std::unique_ptr<Inertia> density = make_fictitious_density(s, rows);
    m.inertia = density.get();
    add(m.effects, std::move(density));
  }
}
}  // namespace

void Model::build_effects(const Scene& s) {
  if (s.dynamics)
    add_timed_loads(*this, s);
  else
    add_static_loads(*this, s);
  add(effects, make_pre_cracks(cut_by_cracks));
  DamageEffect evolution =
      make_damage_evolution(s, DamageBody{particles, *law, params[0], *influence}, bonds, *assembler,
                            approximation ? &short_bonds : nullptr, approximation.get());
  damage = evolution.rule;
  add(effects, std::move(evolution.effect));
  if (s.dynamics) add_inertia(*this, s);
}

}  // namespace pd

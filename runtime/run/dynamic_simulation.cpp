// The dynamic run driver: set-up, constraints, loads at time t. The two loops are in
// explicit_run.cpp and relaxation_run.cpp, the series, checkpoints and files in dynamic_outputs.cpp.
#include "run/dynamic_simulation.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <stdexcept>

#include "discretize/discretization.hpp"
#include "discretize/family_quality.hpp"
#include "model/model.hpp"
#include "dynamics/checkpoint.hpp"
#include "dynamics/dynamic_relaxation.hpp"
#include "dynamics/energies.hpp"
#include "dynamics/progress.hpp"
#include "dynamics/pvd_writer.hpp"
#include "dynamics/time_step.hpp"
#include "dynamics/verlet_integrator.hpp"
#include "fields/analytic.hpp"
#include "input/yaml_keys.hpp"
#include "interrupt.hpp"
#include "output/atomic_file.hpp"
#include "output/csv_writer.hpp"
#include "output/vtu_writer.hpp"
#include "run/constraints.hpp"
#include "run/run_outputs.hpp"
#include "solve/stopwatch.hpp"

namespace pd {

DynamicSimulation::~DynamicSimulation() = default;

DynamicSimulation::DynamicSimulation(Scene scene, Log log) : scene_(std::move(scene)), log_(std::move(log)) {
  if (!scene_.dynamics) throw std::invalid_argument("DynamicSimulation: the scene has no dynamics section");
  const DynamicsSpec& dyn = *scene_.dynamics;
  if (is_obq(scene_.quadrature))
    throw std::invalid_argument(scene_.file + ": domain.quadrature: " + std::string(quadrature_name(scene_.quadrature)) +
                                " is implemented for static solves only");
  const auto t0 = std::chrono::steady_clock::now();
  model_ = build_model(scene_);
  summary_.describe(scene_, model_);
  const abi::LawDescriptor* law = model_.law;
  const abi::InfluenceDescriptor* influence = model_.influence;
  const std::vector<std::vector<double>>& params = model_.params;
  // The intact kernels (alpha folded to 1) unless a bond is or can become broken; no
  // matrix: the explicit loop needs forces only.
  const AssemblerOptions options = attach_assembler(model_, scene_, false, dyn.threads);
  if (model_.gauss_points) summary_.effects.push_back(model_.gauss_points->describe());
  summary_.variant = options.intact ? "intact (alpha folded to 1)" : "damaged (reads alpha)";
  summary_.effects.push_back(fmt::format("elasticity: law {} ({} kernels), influence {}", law->name, summary_.variant,
                                         influence->name));

  // The loads (each scaled by its own function of time), the pre-cracks and damage evolution.
  attach_effects(model_, scene_);
  for (const auto& e : model_.effects) summary_.effects.push_back(e->describe());
  setup_constraints();
  probe_ids_ = probe_particles(scene_, model_.particles);

  const std::size_t N = static_cast<std::size_t>(model_.particles.size()) * model_.particles.dim;
  u_.assign(N, 0.0);
  // The Gershgorin row sums of the stiffness at the reference configuration, from a
  // temporary assembler with a matrix pattern (dropped after setup).
  std::vector<double> rows;
  {
    AssemblerOptions with_matrix = options;
    with_matrix.matrix = true;
    const FamilyAssembler tangent(model_.particles, model_.bonds, *law, params, with_matrix);
    rows = stiffness_row_sums(tangent, nullptr);
  }
  if (dyn.method == DynamicsMethod::explicit_verlet) {
    v_.assign(N, 0.0);
    mass_.resize(N);
    for (int p = 0; p < model_.particles.size(); ++p)
      for (int c = 0; c < model_.particles.dim; ++c)
        mass_[static_cast<std::size_t>(p) * model_.particles.dim + c] = scene_.materials[model_.particles.material[p]].density * model_.particles.volume[p];
    const StableStep st = stable_time_step(rows, mass_);
    dt_stable_ = st.dt;
    dt_ = dyn.dt > 0 ? dyn.dt : dyn.safety_factor * st.dt;
    summary_.effects.push_back(fmt::format("inertia: density per material, velocity Verlet, dt = {:.6g} ({}; Gershgorin stable estimate {:.6g} set by particle {})",
                                           dt_, dyn.dt > 0 ? "fixed" : fmt::format("{} x estimate", dyn.safety_factor), st.dt,
                                           st.dof / model_.particles.dim));
    if (dyn.dt > st.dt) log_(fmt::format("  warning: dt = {:.6g} exceeds the stable estimate {:.6g}", dyn.dt, st.dt));
    if (dyn.damping > 0) summary_.effects.push_back(fmt::format("viscous damping: a = f/m - c v, c = {:.6g}", dyn.damping));
    if (!dyn.initial.empty()) summary_.effects.push_back(fmt::format("initial conditions: {} region(s)", dyn.initial.size()));
  } else {
    density_.resize(N);
    double largest = 0;
    for (double r : rows) largest = std::max(largest, r);
    for (std::size_t i = 0; i < N; ++i) density_[i] = 0.25 * (rows[i] > 0 ? rows[i] : largest);
    dt_ = 1;
    summary_.effects.push_back(fmt::format("adaptive dynamic relaxation: fictitious density D = sum_j |K_ij| / 4, dt = 1, tolerance {:.3g}",
                                           dyn.tolerance));
  }
  summary_.newton.unknowns = static_cast<std::int64_t>(free_.size());
  summary_.setup_seconds = seconds_since(t0);
  log_(fmt::format("{}: {} particles, {} bonds, delta = {:.6g} (delta/h = {:.4g}), setup {:.3f} s", scene_.file,
                   summary_.particles, summary_.bonds, scene_.delta(), scene_.delta() / scene_.h, summary_.setup_seconds));
  for (const auto& e : summary_.effects) log_("  effect: " + e);
  for (const auto& w : summary_.warnings) log_("  warning: " + w);
}

void DynamicSimulation::setup_constraints() {
  const std::size_t N = static_cast<std::size_t>(model_.particles.size()) * model_.particles.dim;
  prescribed_ = prescribed_dofs(scene_, model_.particles);
  std::vector<char> constrained(N, 0);
  for (const PrescribedDof& q : prescribed_) constrained[q.dof] = 1;
  for (std::size_t i = 0; i < N; ++i) (constrained[i] ? constrained_ : free_).push_back(static_cast<int>(i));
}

void DynamicSimulation::apply_initial_conditions() {
  const int d = model_.particles.dim;
  for (const InitialCondition& ic : scene_.dynamics->initial) {
    const auto ids = region_particles(ic.region, model_.particles, scene_);
    if (ids.empty()) throw SceneError(ic.where + ": the region holds no particle");
    for (int p : ids) {
      double shape = 1;
      if (ic.gaussian) {
        const double z = (model_.particles.position(p)[ic.axis] - ic.center) / ic.width;
        shape = std::exp(-0.5 * z * z);
      }
      for (int c = 0; c < d; ++c) {
        double linear = 0;  // gradient (x - origin), zero without a gradient
        for (int j = 0; ic.has_gradient && j < d; ++j)
          linear += ic.gradient[c][j] * (model_.particles.position(p)[j] - ic.origin[j]);
        u_[static_cast<std::size_t>(p) * d + c] = shape * ic.displacement[c] + linear;
        if (!v_.empty()) v_[static_cast<std::size_t>(p) * d + c] = shape * ic.velocity[c];
      }
    }
  }
}

void DynamicSimulation::prescribe(double t) {
  using K = BoundaryCondition::Kind;
  for (const PrescribedDof& q : prescribed_) {
    const auto& tf = scene_.boundary[q.condition].time;
    double u = 0, v = 0;
    if (q.kind == K::Velocity) {
      u = q.value * (tf ? tf->integral(t) : t);
      v = q.value * (tf ? tf->value_at(t) : 1.0);
    } else if (q.kind != K::Fixed) {
      u = q.value * (tf ? tf->value_at(t) : 1.0);
      v = q.value * (tf ? tf->derivative(t) : 0.0);
    }
    u_[q.dof] = u;
    if (!v_.empty()) v_[q.dof] = v;
  }
}

bool DynamicSimulation::after_step() {
  long long changes = 0;
  for (const auto& e : model_.effects) changes += e->after_step(u_.data());
  return changes > 0;
}

void DynamicSimulation::forces(double t, std::vector<double>& f, std::vector<double>& g) const {
  f.resize(u_.size());
  g.assign(u_.size(), 0.0);
  model_.assembler->internal_forces(u_.data(), f.data());
  // Each load at its time function's value (effects/timed_effect.cpp); relaxation has no
  // time functions (the reader refuses them), so its loads are in full.
  for (const auto& e : model_.effects) e->add_forces(u_.data(), t, g.data());
  for (std::size_t i = 0; i < f.size(); ++i) f[i] += g[i];
  // The reaction of a constraint, R = -(f_int + load), plus the load there: -f_int.
  for (int i : constrained_) g[i] = g[i] - f[i];
}

RunSummary DynamicSimulation::run(bool write, int stop_after) {
  summary_.dynamics = DynamicsReport{};
  summary_.dynamics->method = scene_.dynamics->method;
  return scene_.dynamics->method == DynamicsMethod::explicit_verlet ? run_explicit(write, stop_after) : run_relaxation(write, stop_after);
}

}  // namespace pd

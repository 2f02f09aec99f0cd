// The dynamic run driver: explicit velocity Verlet or adaptive dynamic relaxation.
#include "run/dynamic_simulation.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <stdexcept>

#include "discretize/discretization.hpp"
#include "discretize/family_quality.hpp"
#include "run/body_setup.hpp"
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

namespace pd {

namespace {
double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
double norm_over(const std::vector<double>& v, const std::vector<int>& dofs) {
  double s = 0;
  for (int i : dofs) s += v[i] * v[i];
  return std::sqrt(s);
}
constexpr int kRowFixed = 7;  // step, time, kinetic, strain, external work, broken bonds, residual ratio
}  // namespace

DynamicSimulation::~DynamicSimulation() = default;

DynamicSimulation::DynamicSimulation(Scene scene, Log log) : scene_(std::move(scene)), log_(std::move(log)) {
  if (!scene_.dynamics) throw std::invalid_argument("DynamicSimulation: the scene has no dynamics section");
  const DynamicsSpec& dyn = *scene_.dynamics;
  const auto t0 = std::chrono::steady_clock::now();
  BodySetup body = set_up_body(scene_, summary_);
  const abi::LawDescriptor* law = body.law;
  const abi::InfluenceDescriptor* influence = body.influence;
  particles_ = std::move(body.particles);
  bonds_ = std::move(body.bonds);
  const std::vector<std::vector<double>> params = std::move(body.params);
  // The intact kernels (alpha folded to 1) unless a bond is or can become broken: a
  // damage scene needs the damaged variant from the start.
  AssemblerOptions options;
  options.intact = summary_.broken_bonds == 0 && !scene_.damage;
  options.matrix = false;  // the explicit loop needs forces only
  options.threads = dyn.threads;
  assembler_ = std::make_unique<FamilyAssembler>(particles_, bonds_, *law, params, options);
  summary_.variant = options.intact ? "intact (alpha folded to 1)" : "damaged (reads alpha)";
  summary_.effects.push_back(fmt::format("elasticity: law {} ({} kernels), influence {}", law->name, summary_.variant,
                                         influence->name));

  // Loads: one effect per condition, each scaled by its own function of time.
  for (const BoundaryCondition& bc : scene_.boundary) {
    if (bc.kind != BoundaryCondition::Kind::Traction && bc.kind != BoundaryCondition::Kind::BodyForce) continue;
    Scene single = scene_;
    single.boundary = {bc};
    TimedLoad l{make_external_loads(single, particles_), bc.time.value_or(TimeFunction{})};
    summary_.effects.push_back(l.effect->describe() + (bc.time ? ", times " + bc.time->describe() : std::string()));
    loads_.push_back(std::move(l));
  }
  // Crack pressure: one effect per pressurised crack, each scaled by its own function
  // of time (relaxation, like every load, applies it in full).
  for (const Crack& crack : scene_.cracks) {
    Scene single = scene_;
    single.cracks = {crack};
    auto e = make_crack_pressure(single, particles_, bonds_);
    if (!e) continue;
    summary_.effects.push_back(e->describe() + (crack.time ? ", times " + crack.time->describe() : std::string(", constant in time")));
    loads_.push_back({std::move(e), crack.time.value_or(TimeFunction{})});
  }
  if (summary_.broken_bonds > 0) summary_.effects.push_back(fmt::format("broken bonds: {} cut by cracks", summary_.broken_bonds));
  if (scene_.damage) {
    const double s0 = critical_stretch(*scene_.damage, scene_.materials[0], scene_.dim, scene_.delta());
    damage_ = std::make_unique<CriticalStretchDamage>(particles_, bonds_, s0, scene_.damage->tension_only);
    summary_.effects.push_back(damage_->describe() + critical_stretch_origin(*scene_.damage, scene_.dim));
  }
  setup_constraints();
  for (const Probe& pr : scene_.probes) {
    probe_ids_.push_back(region_particles(pr.region, particles_, scene_));
    if (probe_ids_.back().empty()) throw SceneError(pr.where + ": the region holds no particle");
  }

  const std::size_t N = static_cast<std::size_t>(particles_.size()) * particles_.dim;
  u_.assign(N, 0.0);
  // The Gershgorin row sums of the stiffness at the reference configuration, from a
  // temporary assembler with a matrix pattern (dropped after setup).
  std::vector<double> rows;
  {
    AssemblerOptions with_matrix = options;
    with_matrix.matrix = true;
    const FamilyAssembler tangent(particles_, bonds_, *law, params, with_matrix);
    rows = stiffness_row_sums(tangent, nullptr);
  }
  if (dyn.method == "explicit") {
    v_.assign(N, 0.0);
    mass_.resize(N);
    for (int p = 0; p < particles_.size(); ++p)
      for (int c = 0; c < particles_.dim; ++c)
        mass_[static_cast<std::size_t>(p) * particles_.dim + c] = scene_.materials[particles_.material[p]].density * particles_.volume[p];
    const StableStep st = stable_time_step(rows, mass_);
    dt_stable_ = st.dt;
    dt_ = dyn.dt > 0 ? dyn.dt : dyn.safety_factor * st.dt;
    summary_.effects.push_back(fmt::format("inertia: density per material, velocity Verlet, dt = {:.6g} ({}; Gershgorin stable estimate {:.6g} set by particle {})",
                                           dt_, dyn.dt > 0 ? "fixed" : fmt::format("{} x estimate", dyn.safety_factor), st.dt,
                                           st.dof / particles_.dim));
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
  const int d = particles_.dim;
  const std::size_t N = static_cast<std::size_t>(particles_.size()) * d;
  std::vector<int> entry(N, -1);
  for (std::size_t ci = 0; ci < scene_.boundary.size(); ++ci) {
    const BoundaryCondition& bc = scene_.boundary[ci];
    using K = BoundaryCondition::Kind;
    if (bc.kind == K::Traction || bc.kind == K::BodyForce) continue;
    const auto ids = region_particles(bc.region, particles_, scene_);
    if (ids.empty()) throw SceneError(bc.where + ": the region holds no particle");
    std::unique_ptr<AnalyticField> field;
    if (bc.kind == K::Field) field = std::make_unique<AnalyticField>(bc.field, scene_.materials[0].elastic);
    for (int p : ids)
      for (int c = 0; c < d; ++c) {
        if (!bc.components[c]) continue;
        const int dof = p * d + c;
        const double value = bc.kind == K::Fixed ? 0.0 : field ? field->displacement(particles_.position(p))[c] : bc.values[c];
        // A later condition on the same component overrides an earlier one.
        if (entry[dof] < 0) entry[dof] = static_cast<int>(prescribed_.size()), prescribed_.push_back({dof, bc.kind, value, static_cast<int>(ci)});
        else prescribed_[entry[dof]] = {dof, bc.kind, value, static_cast<int>(ci)};
      }
  }
  for (std::size_t i = 0; i < N; ++i) (entry[i] < 0 ? free_ : constrained_).push_back(static_cast<int>(i));
}

void DynamicSimulation::apply_initial_conditions() {
  const int d = particles_.dim;
  for (const InitialCondition& ic : scene_.dynamics->initial) {
    const auto ids = region_particles(ic.region, particles_, scene_);
    if (ids.empty()) throw SceneError(ic.where + ": the region holds no particle");
    for (int p : ids) {
      double shape = 1;
      if (ic.gaussian) {
        const double z = (particles_.position(p)[ic.axis] - ic.center) / ic.width;
        shape = std::exp(-0.5 * z * z);
      }
      for (int c = 0; c < d; ++c) {
        u_[static_cast<std::size_t>(p) * d + c] = shape * ic.displacement[c];
        if (!v_.empty()) v_[static_cast<std::size_t>(p) * d + c] = shape * ic.velocity[c];
      }
    }
  }
}

void DynamicSimulation::prescribe(double t) {
  using K = BoundaryCondition::Kind;
  for (const Prescribed& q : prescribed_) {
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

double DynamicSimulation::load_scale(const TimedLoad& l, double t) const {
  // Relaxation solves the static problem: every load at its full value.
  return scene_.dynamics->method == "relaxation" ? 1.0 : l.time.value_at(t);
}

void DynamicSimulation::forces(double t, std::vector<double>& f, std::vector<double>& g) const {
  f.resize(u_.size());
  g.assign(u_.size(), 0.0);
  assembler_->internal_forces(u_.data(), f.data());
  for (const TimedLoad& l : loads_) l.effect->add_forces(u_.data(), load_scale(l, t), g.data());
  for (std::size_t i = 0; i < f.size(); ++i) f[i] += g[i];
  // The reaction of a constraint, R = -(f_int + load), plus the load there: -f_int.
  for (int i : constrained_) g[i] = g[i] - f[i];
}

SeriesRow DynamicSimulation::make_row(int step, double t, double residual_ratio) const {
  SeriesRow r;
  r.step = step;
  r.time = t;
  if (!mass_.empty()) r.kinetic = kinetic_energy(mass_, v_, free_);
  if (assembler_->has_energy()) r.strain = assembler_->strain_energy(u_.data());
  r.broken_bonds = broken_bond_count(bonds_);
  r.residual_ratio = residual_ratio;
  for (std::size_t k = 0; k < probe_ids_.size(); ++k) {
    double s = 0;
    for (int p : probe_ids_[k]) s += u_[static_cast<std::size_t>(p) * particles_.dim + scene_.probes[k].component];
    r.probes.push_back(s / static_cast<double>(probe_ids_[k].size()));
  }
  return r;
}

std::string DynamicSimulation::series_csv_header() const {
  std::string h = "step,time";
  if (!mass_.empty()) h += ",kinetic";
  if (assembler_->has_energy()) h += ",strain";
  if (!mass_.empty()) h += ",external_work";
  if (!mass_.empty() && assembler_->has_energy()) h += ",total";
  if (mass_.empty()) h += ",residual_ratio";
  h += ",broken_bonds";
  for (const Probe& p : scene_.probes) h += "," + p.name;
  return h + "\n";
}

std::string DynamicSimulation::series_csv_row(const SeriesRow& r) const {
  std::string s = fmt::format("{},{:.17g}", r.step, r.time);
  const bool inertia = !mass_.empty(), energy = assembler_->has_energy();
  if (inertia) s += fmt::format(",{:.17g}", r.kinetic);
  if (energy) s += fmt::format(",{:.17g}", r.strain);
  if (inertia) s += fmt::format(",{:.17g}", r.external_work);
  if (inertia && energy) s += fmt::format(",{:.17g}", r.kinetic + r.strain - r.external_work);
  if (!inertia) s += fmt::format(",{:.17g}", r.residual_ratio);
  s += fmt::format(",{}", r.broken_bonds);
  for (double p : r.probes) s += fmt::format(",{:.17g}", p);
  return s + "\n";
}

void DynamicSimulation::restore(const std::string& path, int& step, std::vector<double>& scalars) {
  const Checkpoint c = read_checkpoint(path);
  auto array = [&](const char* name, std::size_t size) -> const std::vector<double>& {
    const auto it = c.arrays.find(name);
    if (it == c.arrays.end() || it->second.size() != size)
      throw std::runtime_error(fmt::format("{}: the checkpoint does not match this scene ({} missing or of another size)", path, name));
    return it->second;
  };
  u_ = array("u", u_.size());
  if (!v_.empty()) v_ = array("v", v_.size());
  bonds_.alpha = array("alpha", bonds_.alpha.size());
  scalars = c.arrays.count("scalars") ? c.arrays.at("scalars") : std::vector<double>{};
  series_.clear();
  if (const auto it = c.arrays.find("series"); it != c.arrays.end()) {
    const std::size_t width = kRowFixed + scene_.probes.size();
    const auto& s = it->second;
    for (std::size_t i = 0; i + width <= s.size(); i += width) {
      SeriesRow r;
      r.step = static_cast<int>(s[i]), r.time = s[i + 1], r.kinetic = s[i + 2], r.strain = s[i + 3];
      r.external_work = s[i + 4], r.broken_bonds = static_cast<long long>(s[i + 5]), r.residual_ratio = s[i + 6];
      r.probes.assign(s.begin() + static_cast<std::ptrdiff_t>(i + kRowFixed), s.begin() + static_cast<std::ptrdiff_t>(i + width));
      series_.push_back(r);
    }
  }
  snapshots_.clear();
  if (const auto it = c.arrays.find("snapshots"); it != c.arrays.end())
    for (std::size_t i = 0; i + 1 < it->second.size(); i += 2) snapshots_.emplace_back(static_cast<int>(it->second[i]), it->second[i + 1]);
  step = static_cast<int>(c.step);
  if (!assembler_->intact()) assembler_->update_moments();
  summary_.dynamics->restarted_from = path;
  log_(fmt::format("  restarted from {} at step {}", path, step));
}

void DynamicSimulation::save_checkpoint(int step, const std::vector<double>& scalars) {
  Checkpoint c;
  c.step = step;
  c.arrays["u"] = u_;
  if (!v_.empty()) c.arrays["v"] = v_;
  c.arrays["alpha"] = bonds_.alpha;
  c.arrays["scalars"] = scalars;
  std::vector<double> s;
  for (const SeriesRow& r : series_) {
    s.insert(s.end(), {static_cast<double>(r.step), r.time, r.kinetic, r.strain, r.external_work,
                       static_cast<double>(r.broken_bonds), r.residual_ratio});
    s.insert(s.end(), r.probes.begin(), r.probes.end());
  }
  c.arrays["series"] = std::move(s);
  std::vector<double> snaps;
  for (const auto& [st, t] : snapshots_) snaps.push_back(st), snaps.push_back(t);
  c.arrays["snapshots"] = std::move(snaps);
  write_checkpoint(scene_.output.directory + "/checkpoint.bin", c);
  ++summary_.dynamics->checkpoints;
}

std::vector<OutputField> DynamicSimulation::output_fields() const {
  const int n = particles_.size();
  std::vector<OutputField> fields;
  if (!v_.empty()) fields.push_back({"velocity", particles_.dim, v_});
  fields.push_back({"material", 1, std::vector<double>(particles_.material.begin(), particles_.material.end())});
  if (damage_ || !assembler_->intact()) fields.push_back({"damage", 1, particle_damage(bonds_)});
  const auto& law = assembler_->law();
  if (law.n_outputs > 0) {
    const std::vector<double> outputs = assembler_->particle_outputs(u_.data());
    for (int k = 0; k < law.n_outputs; ++k) {
      std::vector<double> v(static_cast<std::size_t>(n));
      for (int p = 0; p < n; ++p) v[p] = outputs[static_cast<std::size_t>(p) * law.n_outputs + k];
      fields.push_back({law.output_names[k], 1, v});
    }
  }
  return fields;
}

void DynamicSimulation::write_snapshot(int step, double t) {
  const std::string name = fmt::format("snapshots/step_{:08d}.vtu", step);
  write_vtu_file(scene_.output.directory + "/" + name, particles_, u_, output_fields());
  if (snapshots_.empty() || snapshots_.back().first != step) snapshots_.emplace_back(step, t);
  std::vector<PvdEntry> entries;
  for (const auto& [st, time] : snapshots_) entries.push_back({time, fmt::format("snapshots/step_{:08d}.vtu", st)});
  write_pvd_file(scene_.output.directory + "/animation.pvd", entries);
  ++summary_.dynamics->snapshots;
}

std::vector<ProbeResult> DynamicSimulation::evaluate_probes() const {
  std::vector<ProbeResult> out;
  for (std::size_t k = 0; k < scene_.probes.size(); ++k) {
    const Probe& pr = scene_.probes[k];
    ProbeResult r;
    r.name = pr.name;
    r.particles = static_cast<int>(probe_ids_[k].size());
    std::unique_ptr<AnalyticField> field;
    if (pr.reference) field = std::make_unique<AnalyticField>(*pr.reference, scene_.materials[0].elastic);
    for (int p : probe_ids_[k]) {
      r.value += u_[static_cast<std::size_t>(p) * particles_.dim + pr.component];
      if (field) r.reference += field->displacement(particles_.position(p))[pr.component];
    }
    r.value /= r.particles;
    r.reference /= r.particles;
    r.has_reference = static_cast<bool>(field);
    r.error = std::fabs(r.value - r.reference);
    out.push_back(r);
  }
  return out;
}

void DynamicSimulation::write_results() {
  const auto t1 = std::chrono::steady_clock::now();
  const std::string dir = scene_.output.directory;
  std::string csv = series_csv_header();
  for (const SeriesRow& r : series_) csv += series_csv_row(r);
  write_file_atomically(dir + "/energies.csv", csv);
  summary_.files.push_back(dir + "/energies.csv");
  const auto fields = output_fields();
  if (scene_.output.vtu) write_vtu_file(dir + "/result.vtu", particles_, u_, fields), summary_.files.push_back(dir + "/result.vtu");
  if (scene_.output.csv) write_csv_file(dir + "/result.csv", particles_, u_, fields), summary_.files.push_back(dir + "/result.csv");
  if (!snapshots_.empty()) summary_.files.push_back(dir + "/animation.pvd");
  if (summary_.dynamics->checkpoints > 0) summary_.files.push_back(dir + "/checkpoint.bin");
  summary_.files.push_back(dir + "/summary.json");
  summary_.output_seconds = seconds_since(t1);
  write_file_atomically(dir + "/summary.json", summary_.json());
}

RunSummary DynamicSimulation::run(bool write, int stop_after) {
  summary_.dynamics = DynamicsReport{};
  summary_.dynamics->method = scene_.dynamics->method;
  return scene_.dynamics->method == "explicit" ? run_explicit(write, stop_after) : run_relaxation(write, stop_after);
}

RunSummary DynamicSimulation::run_explicit(bool write, int stop_after) {
  const auto t0 = std::chrono::steady_clock::now();
  const DynamicsSpec& dyn = *scene_.dynamics;
  DynamicsReport& rep = *summary_.dynamics;
  rep.dt = dt_, rep.dt_stable = dt_stable_, rep.damping = dyn.damping;
  rep.dt_rule = dyn.dt > 0 ? "fixed" : fmt::format("{} x the stable estimate", dyn.safety_factor);
  ExternalWork work;
  int step = 0;
  long long broken_start = broken_bond_count(bonds_);
  std::vector<double> scalars;
  if (!dyn.restart.empty()) {
    restore(dyn.restart, step, scalars);
    if (scalars.size() < 2) throw std::runtime_error(dyn.restart + ": the checkpoint has no energy accumulators");
    work.restore(scalars[0]);
    broken_start = static_cast<long long>(scalars[1]);
  } else {
    apply_initial_conditions();
    prescribe(0.0);
    if (damage_ && damage_->break_bonds(u_.data()) > 0) assembler_->update_moments();
  }
  rep.first_step = step;
  const int last = stop_after > 0 ? std::min(stop_after, dyn.steps) : dyn.steps;
  const VerletIntegrator verlet(
      [&] {
        std::vector<double> inv(mass_.size());
        for (std::size_t i = 0; i < mass_.size(); ++i) inv[i] = 1.0 / mass_[i];
        return inv;
      }(),
      free_, dt_, dyn.damping);
  std::vector<double> f, g, f_old, g_old, u_old;
  double t = step * dt_;
  forces(t, f, g);
  auto record = [&](int s) {
    SeriesRow r = make_row(s, t, 0.0);
    r.external_work = work.value();
    series_.push_back(r);
  };
  if (step == 0) {
    record(0);
    if (dyn.snapshot_every > 0 && write) write_snapshot(0, 0.0);
  }
  Progress progress(log_, write ? dyn.progress_seconds : 0.0, step, last);
  for (int s = step + 1; s <= last; ++s) {
    if (interrupt_signal() != 0) throw_if_interrupted(fmt::format("at time step {} of {}", s, last));
    u_old = u_;
    g_old = g;
    verlet.first_half(u_, v_, f);
    t = s * dt_;
    prescribe(t);
    if (damage_) {
      const int nb = damage_->break_bonds(u_.data());
      if (nb > 0) assembler_->update_moments();
    }
    forces(t, f, g);
    verlet.second_half(v_, f);
    work.add(g_old, g, u_old, u_);
    if (s % dyn.output_every == 0 || s == dyn.steps) record(s);
    if (write && dyn.snapshot_every > 0 && (s % dyn.snapshot_every == 0 || s == dyn.steps)) write_snapshot(s, t);
    if (dyn.checkpoint_every > 0 && s % dyn.checkpoint_every == 0) save_checkpoint(s, {work.value(), static_cast<double>(broken_start)});
    progress.update(s, t);
  }
  for (double x : u_)
    if (!std::isfinite(x)) throw std::runtime_error(fmt::format("the displacement is not finite (unstable time step? dt = {:.6g})", dt_));
  rep.last_step = last;
  rep.time = last * dt_;
  const SeriesRow end = make_row(last, rep.time, 0.0);
  rep.kinetic = end.kinetic;
  rep.strain_available = assembler_->has_energy();
  rep.strain = end.strain;
  rep.external_work = work.value();
  rep.bonds_broken = broken_bond_count(bonds_) - broken_start;
  summary_.broken_bonds = static_cast<int>(broken_bond_count(bonds_));
  summary_.probes = evaluate_probes();
  summary_.solve_seconds = seconds_since(t0);
  if (write) write_results();
  log_(summary_.text());
  return summary_;
}

RunSummary DynamicSimulation::run_relaxation(bool write, int stop_after) {
  const auto t0 = std::chrono::steady_clock::now();
  const DynamicsSpec& dyn = *scene_.dynamics;
  DynamicsReport& rep = *summary_.dynamics;
  rep.dt = 1;
  DofMap dofs = scene_constraints(scene_, particles_);
  check_held(particles_, bonds_, dofs);
  AdaptiveDynamicRelaxation adr(density_, free_);
  int step = 0;
  long long broken_start = broken_bond_count(bonds_);
  std::vector<double> f, g;
  double reference = 0;
  // Checkpoint scalars: [iterations, reference, broken_start, v (N), f_prev (N)]. The
  // reference is the one of iteration 0: recomputed at the restored u it would be the
  // residual there, and the restarted run would stop at another iteration.
  constexpr std::size_t kHead = 3;
  if (!dyn.restart.empty()) {
    std::vector<double> scalars;
    restore(dyn.restart, step, scalars);
    const std::size_t N = u_.size();
    if (scalars.size() != kHead + 2 * N) throw std::runtime_error(dyn.restart + ": not a relaxation checkpoint of this scene");
    const auto v_begin = scalars.begin() + kHead, f_begin = v_begin + static_cast<std::ptrdiff_t>(N);
    adr.restore(static_cast<int>(scalars[0]), std::vector<double>(v_begin, f_begin), std::vector<double>(f_begin, scalars.end()));
    reference = scalars[1];
    broken_start = static_cast<long long>(scalars[2]);
    forces(0.0, f, g);
  } else {
    apply_initial_conditions();
    prescribe(0.0);
    forces(0.0, f, g);
    // The reference force: the larger of the loads and the initial out-of-balance force.
    reference = norm_over(f, free_);
    for (const TimedLoad& l : loads_) {
      std::vector<double> load(u_.size(), 0.0);
      l.effect->add_forces(u_.data(), 1.0, load.data());
      reference = std::max(reference, norm_over(load, free_));
    }
    if (reference == 0) reference = 1;
  }
  rep.first_step = step;
  const int last = stop_after > 0 ? std::min(stop_after, dyn.steps) : dyn.steps;
  double ratio = norm_over(f, free_) / reference;
  if (step == 0) series_.push_back(make_row(0, 0, ratio));
  Progress progress(log_, write ? dyn.progress_seconds : 0.0, step, last);
  int s = step;
  while (ratio > dyn.tolerance && s < last) {
    if (interrupt_signal() != 0) throw_if_interrupted(fmt::format("at relaxation iteration {} of at most {}", s + 1, last));
    ++s;
    adr.step(f, u_);
    if (damage_ && damage_->break_bonds(u_.data()) > 0) assembler_->update_moments();
    forces(0.0, f, g);
    ratio = norm_over(f, free_) / reference;
    if (!std::isfinite(ratio)) throw std::runtime_error(fmt::format("adaptive dynamic relaxation diverged at iteration {}", s));
    const bool done = ratio <= dyn.tolerance;
    if (s % dyn.output_every == 0 || done) series_.push_back(make_row(s, s, ratio));
    if (write && dyn.snapshot_every > 0 && (s % dyn.snapshot_every == 0 || done)) write_snapshot(s, s);
    if (dyn.checkpoint_every > 0 && s % dyn.checkpoint_every == 0) {
      std::vector<double> scalars{static_cast<double>(adr.iterations()), reference, static_cast<double>(broken_start)};
      scalars.insert(scalars.end(), adr.velocity().begin(), adr.velocity().end());
      scalars.insert(scalars.end(), adr.previous_force().begin(), adr.previous_force().end());
      save_checkpoint(s, scalars);
    }
    progress.update(s, s, fmt::format(", |r|/ref = {:.3e}", ratio));
  }
  rep.last_step = s;
  rep.time = s;
  rep.converged = ratio <= dyn.tolerance;
  rep.residual_ratio = ratio;
  rep.damping = adr.damping();
  rep.strain_available = assembler_->has_energy();
  if (rep.strain_available) rep.strain = assembler_->strain_energy(u_.data());
  rep.bonds_broken = broken_bond_count(bonds_) - broken_start;
  summary_.broken_bonds = static_cast<int>(broken_bond_count(bonds_));
  summary_.newton.converged = rep.converged;
  summary_.probes = evaluate_probes();
  summary_.solve_seconds = seconds_since(t0);
  log_(fmt::format("  relaxation: {} after {} iterations, |r|/ref = {:.3e}", rep.converged ? "converged" : "not converged", s, ratio));
  if (write) write_results();
  log_(summary_.text());
  if (!rep.converged && stop_after == 0)
    throw std::runtime_error(fmt::format("adaptive dynamic relaxation did not converge in {} iterations (|r|/ref = {:.3e} > {:.3g})", s,
                                         ratio, dyn.tolerance));
  return summary_;
}

}  // namespace pd

// The static run driver.
#include "run/simulation.hpp"

#include <chrono>
#include <map>
#include <nlohmann/json.hpp>
#include <algorithm>
#include <cmath>
#include <fmt/core.h>
#include <stdexcept>

#include "discretize/discretization.hpp"
#include "fields/analytic.hpp"
#include "input/yaml_keys.hpp"
#include "write/writers.hpp"

namespace pd {

namespace {
double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
}  // namespace

Simulation::~Simulation() = default;

Simulation::Simulation(Scene scene, Log log) : scene_(std::move(scene)), log_(std::move(log)) {
  const auto t0 = std::chrono::steady_clock::now();
  const abi::LawDescriptor* law = abi::find_law(scene_.law);
  const abi::InfluenceDescriptor* influence = abi::find_influence(scene_.influence);
  if (!law || !influence) throw std::invalid_argument("unknown law or influence function");
  particles_ = discretize(scene_);
  bonds_ = find_bonds(particles_, scene_.delta(), influence->weight);
  summary_.scene = scene_.file;
  summary_.law = law->name;
  summary_.influence = influence->name;
  summary_.particles = particles_.size();
  summary_.bonds = bonds_.bond_count() / 2;
  summary_.broken_bonds = cut_bonds(scene_.cracks, particles_, bonds_) / 2;
  for (int p = 0; p < particles_.size(); ++p)
    if (bonds_.family_size(p) == 0)
      throw std::runtime_error(fmt::format("particle {} at ({:.6g}, {:.6g}) has no neighbour within the horizon", p,
                                           particles_.x[p * particles_.dim], particles_.x[p * particles_.dim + 1]));
  std::vector<std::vector<double>> params;
  for (const MaterialSpec& m : scene_.materials) params.push_back(law_parameters(*law, m.elastic, m.plane, m.parameters));
  // Simulate only what the scene calls for: no broken bond -> the variant without alpha.
  const bool intact = summary_.broken_bonds == 0;
  assembler_ = std::make_unique<Assembler>(particles_, bonds_, *law, std::move(params), intact);
  summary_.variant = assembler_->variant_name();
  summary_.effects.push_back(fmt::format("elasticity: law {} ({} kernels), influence {}", law->name, summary_.variant,
                                         influence->name));
  if (auto e = make_external_loads(scene_, particles_)) effects_.push_back(std::move(e));
  if (auto e = make_crack_pressure(scene_, particles_, bonds_, assembler_->sparsity())) effects_.push_back(std::move(e));
  for (const auto& e : effects_) summary_.effects.push_back(e->describe());
  if (summary_.broken_bonds > 0) summary_.effects.push_back(fmt::format("broken bonds: {} cut by cracks", summary_.broken_bonds));
  u_.assign(static_cast<std::size_t>(particles_.size()) * particles_.dim, 0.0);
  summary_.setup_seconds = seconds_since(t0);
  log_(fmt::format("{}: {} particles, {} bonds, delta = {:.6g} (delta/h = {:.4g}), setup {:.3f} s", scene_.file,
                   summary_.particles, summary_.bonds, scene_.delta(), scene_.delta() / scene_.h, summary_.setup_seconds));
  for (const auto& e : summary_.effects) log_("  effect: " + e);
}

Constraints Simulation::constraints() const {
  const int d = particles_.dim;
  std::vector<double> value(u_.size(), 0.0);
  std::vector<char> fixed(u_.size(), 0);
  for (std::size_t i = 0; i < scene_.boundary.size(); ++i) {
    const BoundaryCondition& bc = scene_.boundary[i];
    if (bc.kind != BoundaryCondition::Kind::Fixed && bc.kind != BoundaryCondition::Kind::Displacement &&
        bc.kind != BoundaryCondition::Kind::Field)
      continue;
    const auto ids = region_particles(bc.region, particles_, scene_);
    if (ids.empty()) throw SceneError(bc.where + ": the region holds no particle");
    std::unique_ptr<AnalyticField> field;
    if (bc.kind == BoundaryCondition::Kind::Field) field = std::make_unique<AnalyticField>(bc.field, scene_.materials[0].elastic);
    for (int p : ids)
      for (int c = 0; c < d; ++c) {
        if (!bc.components[c]) continue;
        fixed[p * d + c] = 1;
        value[p * d + c] = bc.kind == BoundaryCondition::Kind::Fixed ? 0.0
                           : field ? field->displacement(particles_.position(p))[c]
                                   : bc.values[c];
      }
  }
  Constraints cons;
  for (std::size_t i = 0; i < fixed.size(); ++i)
    if (fixed[i]) cons.dofs.push_back(static_cast<int>(i)), cons.values.push_back(value[i]);
  return cons;
}

std::vector<ProbeResult> Simulation::evaluate_probes() const {
  std::vector<ProbeResult> out;
  for (const Probe& pr : scene_.probes) {
    ProbeResult r;
    r.name = pr.name;
    const auto ids = region_particles(pr.region, particles_, scene_);
    if (ids.empty()) throw SceneError(pr.where + ": the region holds no particle");
    r.particles = static_cast<int>(ids.size());
    std::unique_ptr<AnalyticField> field;
    if (pr.reference) field = std::make_unique<AnalyticField>(*pr.reference, scene_.materials[0].elastic);
    for (int p : ids) {
      r.value += u_[p * particles_.dim + pr.component];
      if (field) r.reference += field->displacement(particles_.position(p))[pr.component];
    }
    r.value /= static_cast<double>(ids.size());
    r.reference /= static_cast<double>(ids.size());
    r.has_reference = static_cast<bool>(field);
    r.error = std::fabs(r.value - r.reference);
    out.push_back(r);
  }
  return out;
}

namespace {
// Rigid-body modes the constraints leave free, found before the solve so the message
// names the missing constraint instead of a singular factorisation. Dead loads cannot
// balance a free rigid mode, so a scene must remove every one of them.
std::string missing_constraints(const Particles& p, const Constraints& cons) {
  const int d = p.dim;
  std::vector<std::vector<double>> coords(static_cast<std::size_t>(d));  // positions of constrained dofs per component
  for (int dof : cons.dofs) {
    const int i = dof / d, c = dof % d;
    coords[c].push_back(p.x[i * d + (c + 1) % d]);
  }
  std::string missing;
  const char* axes = "xyz";
  for (int c = 0; c < d; ++c)
    if (coords[c].empty()) missing += fmt::format("no particle has its {} displacement prescribed (rigid translation in {}); ", axes[c], axes[c]);
  auto spread = [](const std::vector<double>& v) {
    if (v.empty()) return 0.0;
    const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
    return *hi - *lo;
  };
  if (d == 2 && missing.empty() && spread(coords[0]) == 0.0 && spread(coords[1]) == 0.0) {
    // x fixed along one horizontal line and y along one vertical line: rotation about
    // their crossing point is free unless the two constraints sit at different points.
    bool blocked = false;
    for (int dof : cons.dofs)
      for (int other : cons.dofs)
        if (dof % 2 == 0 && other % 2 == 0 && p.x[(dof / 2) * 2 + 1] != p.x[(other / 2) * 2 + 1]) blocked = true;
    if (!blocked && coords[0].size() + coords[1].size() < 3) missing += "the constraints leave the rigid rotation free; ";
  }
  return missing;
}
}  // namespace

RunSummary Simulation::run(bool write_outputs) {
  const auto t0 = std::chrono::steady_clock::now();
  // Clusters of particles joined by intact bonds: each needs its own constraints, or it
  // floats (a particle whose every bond is broken is a cluster of one).
  const Constraints cons = constraints();
  std::vector<int> parent(static_cast<std::size_t>(particles_.size()));
  for (int p = 0; p < particles_.size(); ++p) parent[p] = p;
  auto root = [&](int p) {
    while (parent[p] != p) p = parent[p] = parent[parent[p]];
    return p;
  };
  for (int p = 0; p < particles_.size(); ++p)
    for (int e = bonds_.offsets[p]; e < bonds_.offsets[p + 1]; ++e)
      if (bonds_.alpha[e] != 0.0) parent[root(p)] = root(bonds_.neighbor[e]);
  std::map<int, std::vector<int>> clusters;
  for (int p = 0; p < particles_.size(); ++p) clusters[root(p)].push_back(p);
  std::map<int, Constraints> cluster_constraints;
  for (std::size_t i = 0; i < cons.dofs.size(); ++i) {
    Constraints& c = cluster_constraints[root(cons.dofs[i] / particles_.dim)];
    c.dofs.push_back(cons.dofs[i]);
    c.values.push_back(cons.values[i]);
  }
  for (const auto& [r, members] : clusters) {
    const std::string missing = missing_constraints(particles_, cluster_constraints[r]);
    if (missing.empty()) continue;
    std::string list;
    for (std::size_t i = 0; i < std::min<std::size_t>(members.size(), 8); ++i) list += (i ? ", " : "") + std::to_string(members[i]);
    const double* x = particles_.position(members[0]);
    const std::string what = clusters.size() == 1
                                 ? std::string("the body is under-constrained: ")
                                 : fmt::format("a cluster of {} particle(s) joined by intact bonds (particles {}{}; the first at ({:.6g}, {:.6g})) "
                                               "is disconnected from the rest of the body and under-constrained: ",
                                               members.size(), list, members.size() > 8 ? ", ..." : "", x[0], x[1]);
    throw std::runtime_error(what + missing.substr(0, missing.size() - 2));
  }
  // No load at all: the solution is zero (and the residual is rounding noise).
  bool loaded = !effects_.empty();
  for (double v : cons.values) loaded = loaded || v != 0.0;
  if (!loaded) log_("  no load and no prescribed displacement: the solution is zero");

  NonlinearProblem pb;
  pb.size = static_cast<int>(u_.size());
  // A law derived from an energy has a symmetric tangent; one without (e.g. Oterkus's
  // force law) needs a non-symmetric solver.
  pb.symmetric = assembler_->law().damaged.energy != nullptr;
  for (const auto& e : effects_) pb.symmetric = pb.symmetric && e->symmetric();
  pb.residual = [this](const std::vector<double>& u, double load, std::vector<double>& r) {
    assembler_->forces(u, r);
    for (const auto& e : effects_) e->add_forces(u, load, r);
  };
  pb.stiffness = [this](const std::vector<double>& u, double load, SparseMatrix& K, std::vector<double>& r) {
    assembler_->stiffness(u, K, &r);
    for (const auto& e : effects_) {
      e->add_forces(u, load, r);
      e->add_stiffness(u, load, K);
    }
  };
  NewtonOptions opt;
  opt.load_steps = scene_.solver.load_steps;
  opt.tolerance = scene_.solver.tolerance;
  opt.increment_tolerance = scene_.solver.increment_tolerance;
  opt.max_iterations = scene_.solver.max_iterations;
  opt.linear = scene_.solver.linear;
  opt.krylov_tolerance = scene_.solver.krylov_tolerance;
  if (loaded) {
    summary_.newton = solve_newton(pb, cons, u_, opt, log_);
  } else {
    summary_.newton.converged = true;
  }
  summary_.solve_seconds = seconds_since(t0);
  log_(fmt::format("  linear solver: {}", summary_.newton.linear_choice));
  if (!summary_.newton.converged) throw std::runtime_error(summary_.newton.failure);
  assembler_->check_finite(u_, "the solution");
  summary_.probes = evaluate_probes();
  if (scene_.reference) {
    const AnalyticField field(*scene_.reference, scene_.materials[0].elastic);
    double num = 0, den = 0;
    const int d = particles_.dim;
    for (int p = 0; p < particles_.size(); ++p) {
      const auto ua = field.displacement(particles_.position(p));
      for (int c = 0; c < d; ++c) num += std::pow(ua[c] - u_[p * d + c], 2), den += ua[c] * ua[c];
    }
    summary_.has_field_error = true;
    summary_.field_error = den > 0 ? num / den : num;
    log_(fmt::format("  field error against {} (paper 000 eq. 48): {:.6e}", field.name(), summary_.field_error));
  }
  for (const auto& p : summary_.probes)
    log_(p.has_reference ? fmt::format("  probe {}: {:.9g} (analytic {:.9g}, error {:.3e}, relative {:.3e})", p.name,
                                       p.value, p.reference, p.error, p.error / std::max(std::fabs(p.reference), 1e-300))
                         : fmt::format("  probe {}: {:.9g}", p.name, p.value));
  if (write_outputs) {
    const auto t1 = std::chrono::steady_clock::now();
    std::vector<PointField> fields{{"displacement", particles_.dim, u_}};
    std::vector<double> material(particles_.material.begin(), particles_.material.end()), damage(particles_.size(), 0.0);
    for (int p = 0; p < particles_.size(); ++p) {
      int broken = 0;
      for (int e = bonds_.offsets[p]; e < bonds_.offsets[p + 1]; ++e) broken += bonds_.alpha[e] == 0.0;
      damage[p] = bonds_.family_size(p) ? static_cast<double>(broken) / bonds_.family_size(p) : 0.0;
    }
    fields.push_back({"material", 1, material});
    fields.push_back({"damage", 1, damage});
    std::vector<double> force;
    assembler_->forces(u_, force);
    fields.push_back({"internal_force", particles_.dim, force});
    const auto& law = assembler_->law();
    const std::vector<double> outputs = assembler_->particle_outputs(u_);
    for (int k = 0; k < law.n_outputs; ++k) {
      std::vector<double> v(static_cast<std::size_t>(particles_.size()));
      for (int p = 0; p < particles_.size(); ++p) v[p] = outputs[static_cast<std::size_t>(p) * law.n_outputs + k];
      fields.push_back({law.output_names[k], 1, v});
    }
    const std::string dir = scene_.output.directory;
    if (scene_.output.vtu) write_vtu(dir + "/result.vtu", particles_, fields), summary_.files.push_back(dir + "/result.vtu");
    if (scene_.output.csv) write_csv(dir + "/result.csv", particles_, fields), summary_.files.push_back(dir + "/result.csv");
    summary_.files.push_back(dir + "/summary.json");
    summary_.output_seconds = seconds_since(t1);
    write_text_atomically(dir + "/summary.json", summary_.json());
  }
  return summary_;
}

std::string RunSummary::json() const {
  nlohmann::ordered_json j;
  j["scene"] = scene;
  j["law"] = law;
  j["influence"] = influence;
  j["kernel_variant"] = variant;
  j["effects"] = effects;
  j["particles"] = particles;
  j["bonds"] = bonds;
  j["broken_bonds"] = broken_bonds;
  j["unknowns"] = newton.unknowns;
  j["nonzeros"] = newton.nonzeros;
  j["linear_solver"] = {{"method", newton.linear_method}, {"choice", newton.linear_choice}};
  nlohmann::ordered_json iterations = nlohmann::ordered_json::array();
  for (const auto& it : newton.history)
    iterations.push_back({{"load_step", it.step}, {"iteration", it.iteration}, {"residual", it.residual},
                          {"increment", it.increment}, {"line_search", it.line_search}, {"krylov_iterations", it.krylov_iterations}});
  j["newton"] = {{"converged", newton.converged}, {"iterations", iterations}};
  j["seconds"] = {{"setup", setup_seconds}, {"assembly", newton.assembly_seconds}, {"linear_solve", newton.solve_seconds},
                  {"solve", solve_seconds}, {"output", output_seconds}};
  nlohmann::ordered_json probe_list = nlohmann::ordered_json::array();
  for (const auto& p : probes) {
    nlohmann::ordered_json e{{"name", p.name}, {"particles", p.particles}, {"value", p.value}};
    if (p.has_reference) e["reference"] = p.reference, e["error"] = p.error;
    probe_list.push_back(e);
  }
  j["probes"] = probe_list;
  if (has_field_error) j["field_error_eq48"] = field_error;
  j["files"] = files;
  return j.dump(2) + "\n";
}

std::string RunSummary::text() const {
  std::string s = fmt::format("particles: {}\nbonds: {}\nbroken bonds: {}\nkernel variant: {}\neffects:\n", particles,
                              bonds, broken_bonds, variant);
  for (const auto& e : effects) s += "  - " + e + "\n";
  s += fmt::format("unknowns: {}\nnonzeros: {}\nlinear solver: {} ({})\nnewton iterations: {}\n", newton.unknowns,
                   newton.nonzeros, newton.linear_method, newton.linear_choice,
                   newton.history.empty() ? 0 : static_cast<int>(newton.history.size()) - 1);
  for (const auto& it : newton.history)
    s += fmt::format("  step {} iteration {} residual {:.6e} line-search {:.3g}\n", it.step, it.iteration, it.residual, it.line_search);
  s += fmt::format("seconds: setup {:.4f} assembly {:.4f} linear solve {:.4f} total solve {:.4f} output {:.4f}\n",
                   setup_seconds, newton.assembly_seconds, newton.solve_seconds, solve_seconds, output_seconds);
  if (has_field_error) s += fmt::format("field error (eq. 48): {:.9e}\n", field_error);
  s += "probes:\n";
  for (const auto& p : probes)
    s += p.has_reference ? fmt::format("  {}: value {:.12g} reference {:.12g} error {:.6e}\n", p.name, p.value, p.reference, p.error)
                         : fmt::format("  {}: value {:.12g}\n", p.name, p.value);
  return s;
}

}  // namespace pd

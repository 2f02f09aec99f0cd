// The static run driver.
#include "run/simulation.hpp"

#include <chrono>
#include <cmath>
#include <fmt/core.h>
#include <stdexcept>

#include "discretize/discretization.hpp"
#include "fields/analytic.hpp"
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
    if (ids.empty()) throw std::runtime_error(fmt::format("{}: boundary[{}]: the region holds no particle", scene_.file, i));
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
    if (ids.empty()) throw std::runtime_error("probe " + pr.name + ": the region holds no particle");
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

RunSummary Simulation::run(bool write_outputs) {
  const auto t0 = std::chrono::steady_clock::now();
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
  summary_.newton = solve_newton(pb, constraints(), u_, opt, log_);
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
    const std::string dir = scene_.output.directory;
    if (scene_.output.vtu) write_vtu(dir + "/result.vtu", particles_, fields), summary_.files.push_back(dir + "/result.vtu");
    if (scene_.output.csv) write_csv(dir + "/result.csv", particles_, fields), summary_.files.push_back(dir + "/result.csv");
    summary_.files.push_back(dir + "/summary.txt");
    summary_.output_seconds = seconds_since(t1);
    write_text_atomically(dir + "/summary.txt", summary_.text());
  }
  return summary_;
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

// The run summary: text for the log, JSON for summary.json.
#include "run/run_summary.hpp"

#include <fmt/core.h>

#include <nlohmann/json.hpp>

#include "output/run_id.hpp"
#include "version.hpp"

namespace pd {

namespace {
// The "dynamics" object of summary.json: the method, its steps and time, its energy or
// convergence, and what it broke and wrote.
nlohmann::ordered_json dynamics_json(const DynamicsReport& d) {
  nlohmann::ordered_json dj{{"method", std::string(name_of(d.method))},
                            {"first_step", d.first_step},
                            {"last_step", d.last_step},
                            {"time", d.time},
                            {"dt", d.dt}};
  if (d.method == DynamicsMethod::explicit_verlet)
    dj["dt_stable_estimate"] = d.dt_stable, dj["dt_rule"] = d.dt_rule;
  if (d.method == DynamicsMethod::relaxation)
    dj["last_adaptive_coefficient"] = d.damping;
  else if (d.damping > 0)
    dj["viscous_damping"] = d.damping;
  nlohmann::ordered_json energy{{"kinetic", d.kinetic}, {"external_work", d.external_work}};
  if (d.strain_available)
    energy["strain"] = d.strain;
  else
    energy["strain"] = "unavailable (the law has no energy kernel)";
  if (d.method == DynamicsMethod::explicit_verlet) dj["energy"] = energy;
  if (d.method == DynamicsMethod::relaxation)
    dj["converged"] = d.converged, dj["residual_ratio"] = d.residual_ratio;
  dj["bonds_broken"] = d.bonds_broken;
  if (!d.restarted_from.empty()) dj["restarted_from"] = d.restarted_from;
  dj["checkpoints"] = d.checkpoints;
  dj["snapshots"] = d.snapshots;
  return dj;
}

// One entry per Newton iteration; with_resolve (damage runs) adds which solve of the load step it was.
nlohmann::ordered_json newton_iterations_json(const std::vector<NewtonRecord>& history, bool with_resolve) {
  nlohmann::ordered_json iterations = nlohmann::ordered_json::array();
  for (const auto& it : history) {
    nlohmann::ordered_json e{{"load_step", it.step}, {"load", it.load}};
    if (with_resolve) e["resolve"] = it.round;  // 0: the first solve of the step
    e.update({{"iteration", it.iteration},
              {"residual", it.residual},
              {"increment", it.increment},
              {"line_search", it.step_length},
              {"linear_iterations", it.linear_iterations}});
    iterations.push_back(e);
  }
  return iterations;
}

// The probes' values, with the reference and error where there is one.
nlohmann::ordered_json probes_json(const std::vector<ProbeResult>& probes) {
  nlohmann::ordered_json probe_list = nlohmann::ordered_json::array();
  for (const auto& p : probes) {
    nlohmann::ordered_json e{{"name", p.name}, {"particles", p.particles}, {"value", p.value}};
    if (p.has_reference) e["reference"] = p.reference, e["error"] = p.error;
    probe_list.push_back(e);
  }
  return probe_list;
}
}  // namespace

void RunSummary::describe(const Scene& s, const DiscretizedBody& model) {
  scene = s.file;
  law = model.law->name;
  influence = model.influence->name;
  particles = model.particles.size();
  bonds = model.bond_count;
  broken_bonds = model.cut_by_cracks;
  warnings = model.warnings;
}

std::string RunSummary::json() const {
  nlohmann::ordered_json j;
  j["run_id"] = run_id();  // also in the .pvd and every .vtu of this run
  j["pd"] = {{"version", version()}, {"commit", git_commit()}};  // which binary wrote this
  j["scene"] = scene;
  j["law"] = law;
  j["influence"] = influence;
  j["kernel_variant"] = variant;
  j["effects"] = effects;
  if (!warnings.empty()) j["warnings"] = warnings;
  j["particles"] = particles;
  j["bonds"] = bonds;
  j["broken_bonds"] = broken_bonds;
  j["unknowns"] = newton.unknowns;
  if (dynamics) {
    j["dynamics"] = dynamics_json(*dynamics);
    j["seconds"] = {{"setup", setup_seconds}, {"solve", solve_seconds}, {"output", output_seconds}};
  } else {
    j["nonzeros"] = newton.nonzeros;
    j["linear_solver"] = {
        {"path", solver_path}, {"method", newton.linear_solver}, {"choice", newton.linear_choice}};
    j["newton"] = {
        {"converged", newton.converged},
        {"stagnated_on_rounding_floor", newton.stagnated},
        {"iterations", newton_iterations_json(newton.history, bonds_broken_by_damage.has_value())}};
    if (bonds_broken_by_damage)
      j["damage"] = {{"bonds_broken", *bonds_broken_by_damage}, {"resolves", newton.resolves}};
    j["seconds"] = {{"setup", setup_seconds},
                    {"assembly", newton.assembly_seconds},
                    {"linear_solve", newton.linear_seconds},
                    {"solve", solve_seconds},
                    {"output", output_seconds}};
  }
  if (!j_integrals.empty()) j["j_integral"] = j_integral_json(j_integrals);
  j["probes"] = probes_json(probes);
  if (has_field_error) j["field_error_eq48"] = field_error;
  if (has_field_error) j["rms_error_free"] = {{"value", rms_error}, {"particles", rms_particles}};
  if (!smoothing.empty()) {
    nlohmann::ordered_json sj{{"influence", smoothing}, {"oscillation", oscillation}};
    if (has_field_error) sj["field_error_eq48"] = smoothed_field_error;
    j["smoothing_eq49"] = sj;
  }
  j["files"] = files;
  return j.dump(2) + "\n";
}

std::string RunSummary::text() const {
  std::string s = fmt::format("particles: {}\nbonds: {}\nbroken bonds: {}\nkernel variant: {}\neffects:\n",
                              particles, bonds, broken_bonds, variant);
  for (const auto& e : effects) s += "  - " + e + "\n";
  if (dynamics) {
    const DynamicsReport& d = *dynamics;
    s += fmt::format("unknowns: {}\n{}: steps {}..{}, t = {:.6g}, dt = {:.6g}{}\n", newton.unknowns,
                     d.method == DynamicsMethod::explicit_verlet ? "explicit dynamics (velocity Verlet)"
                                                                 : "adaptive dynamic relaxation",
                     d.first_step, d.last_step, d.time, d.dt,
                     d.method == DynamicsMethod::explicit_verlet
                         ? fmt::format(" ({}; stable estimate {:.6g})", d.dt_rule, d.dt_stable)
                         : "");
    if (d.method == DynamicsMethod::explicit_verlet)
      s += fmt::format("energy: kinetic {:.9g} strain {} external work {:.9g}\n", d.kinetic,
                       d.strain_available ? fmt::format("{:.9g}", d.strain)
                                          : std::string("unavailable (no energy kernel)"),
                       d.external_work);
    else
      s += fmt::format("relaxation: {} |r|/ref = {:.3e}, last damping c = {:.4g}\n",
                       d.converged ? "converged" : "NOT converged", d.residual_ratio, d.damping);
    if (d.bonds_broken > 0) s += fmt::format("bonds broken during the run: {}\n", d.bonds_broken);
    s += fmt::format("seconds: setup {:.4f} solve {:.4f} output {:.4f}\n", setup_seconds, solve_seconds,
                     output_seconds);
  } else {
    s += fmt::format(
        "unknowns: {}\nnonzeros: {}\nsolver path: {}\nlinear solver: {} ({})\nnewton iterations: {}\n",
        newton.unknowns, newton.nonzeros, solver_path, newton.linear_solver, newton.linear_choice,
        newton.iterations());
    for (const auto& it : newton.history)
      s +=
          fmt::format("  step {}{} iteration {} residual {:.6e} line-search {:.3g}{}\n", it.step,
                      it.round > 0 ? fmt::format(" re-solve {}", it.round) : "", it.iteration, it.residual,
                      it.step_length,
                      it.linear_iterations ? fmt::format(" linear iterations {}", it.linear_iterations) : "");
    if (bonds_broken_by_damage)
      s += fmt::format("bonds broken between load steps: {} ({} re-solves)\n", *bonds_broken_by_damage,
                       newton.resolves);
    s += fmt::format(
        "seconds: setup {:.4f} assembly {:.4f} linear solve {:.4f} total solve {:.4f} output {:.4f}\n",
        setup_seconds, newton.assembly_seconds, newton.linear_seconds, solve_seconds, output_seconds);
  }
  if (has_field_error) s += fmt::format("field error (eq. 48): {:.9e}\n", field_error);
  if (has_field_error)
    s += fmt::format("RMS error over the {} free particles (paper 001 §4): {:.9e}\n", rms_particles,
                     rms_error);
  if (!smoothing.empty())
    s += fmt::format(
        "smoothing (eq. 49, {}): oscillation {:.6e}{}\n", smoothing, oscillation,
        has_field_error ? fmt::format(", smoothed field error {:.9e}", smoothed_field_error) : "");
  for (const auto& r : j_integrals) s += j_integral_line(r).substr(2) + "\n";
  if (!probes.empty()) s += "probes:\n";
  for (const auto& p : probes)
    s += p.has_reference ? fmt::format("  {}: value {:.12g} reference {:.12g} error {:.6e}\n", p.name,
                                       p.value, p.reference, p.error)
                         : fmt::format("  {}: value {:.12g}\n", p.name, p.value);
  s.pop_back();  // one log call per line: the log adds the last newline (no empty line after it)
  return s;
}

}  // namespace pd

// What every driver reports from a solution: probes (paper 000 eq. 36), the field error
// against the scene's reference (eq. 48), and the per-particle output fields of the law.
#pragma once

#include <string>
#include <vector>

#include "assembly/force_operator.hpp"
#include "constraints/dof_map.hpp"
#include "input/scene.hpp"
#include "output/particle_fields.hpp"
#include "particles.hpp"
#include "run/run_summary.hpp"

namespace pd {

// The particles of each probe's region, in the scene's order. Throws SceneError naming
// the probe whose region holds no particle.
std::vector<std::vector<int>> probe_particles(const Scene& scene, const Particles& particles);

// Each probe's mean displacement (or stress) component over its particles, and with a
// reference the mean of the analytic field over the same particles and the difference.
// `stress` ([n*dim*dim], peridynamic_stress) is needed when a probe asks for stress
// (std::logic_error otherwise); wants_stress says when to compute it.
std::vector<ProbeResult> evaluate_probes(const Scene& scene, const Particles& particles,
                                         const std::vector<std::vector<int>>& ids,
                                         const std::vector<double>& u,
                                         const std::vector<double>* stress = nullptr);
// The mean of probe k's quantity over its particles.
double probe_mean(const Probe& probe, const std::vector<int>& ids, int dim, const std::vector<double>& u,
                  const std::vector<double>* stress);
// True when output.stress is on or a probe averages a stress component.
bool wants_stress(const Scene& scene);

// Paper 000 eq. (48): sum |u_anal - u|^2 / sum |u_anal|^2 (the plain sum when the
// reference is zero everywhere).
double field_error(const Scene& scene, const FieldSpec& reference, const Particles& particles,
                   const std::vector<double>& u);

// Paper 001 §4's error: the RMS sqrt(sum_i |u_i - u_anal(x_i)|^2 / N) over the N particles
// whose every dof is free (the solved ones; a Dirichlet collar is left out). `count` gets N;
// 0 when no particle is free (the RMS is then 0).
double rms_error_free(const Scene& scene, const FieldSpec& reference, const Particles& particles,
                      const DofMap& dofs, const std::vector<double>& u, int& count);

// The probe's line in the run log.
std::string probe_log_line(const ProbeResult& p);

// The law's per-particle outputs (law.output_names) at u, one field each.
void append_law_outputs(const ForceOperator& assembler, const Particles& particles,
                        const std::vector<double>& u, std::vector<OutputField>& fields);

}  // namespace pd

// Probes, field errors and law output fields, shared by the static and dynamic drivers.
#include "run/run_outputs.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

#include "discretize/discretization.hpp"
#include "fields/analytic.hpp"
#include "input/yaml_keys.hpp"
#include "post/probe_reference.hpp"

namespace pd {

std::vector<std::vector<int>> probe_particles(const Scene& scene, const Particles& particles) {
  std::vector<std::vector<int>> ids;
  for (const Probe& pr : scene.probes) {
    ids.push_back(region_particles(pr.region, particles, scene));
    if (ids.back().empty()) throw SceneError(pr.where + ": the region holds no particle");
  }
  return ids;
}

bool wants_stress(const Scene& scene) {
  return scene.output.stress || std::any_of(scene.probes.begin(), scene.probes.end(), [](const Probe& p) {
           return p.quantity == Probe::Quantity::stress;
         });
}

double probe_mean(const Probe& probe, const std::vector<int>& ids, int dim, const std::vector<double>& u,
                  const std::vector<double>* stress) {
  double sum = 0;
  if (probe.quantity == Probe::Quantity::stress) {
    if (stress == nullptr)
      throw std::logic_error(probe.where + ": a stress probe evaluated without the stress field");
    const std::size_t dd = static_cast<std::size_t>(dim) * dim,
                      at = static_cast<std::size_t>(probe.component) * dim + probe.stress_column;
    for (int p : ids) sum += (*stress)[static_cast<std::size_t>(p) * dd + at];
  } else {
    for (int p : ids) sum += u[static_cast<std::size_t>(p) * dim + probe.component];
  }
  return sum / static_cast<double>(ids.size());
}

std::vector<ProbeResult> evaluate_probes(const Scene& scene, const Particles& particles,
                                         const std::vector<std::vector<int>>& ids,
                                         const std::vector<double>& u, const std::vector<double>* stress) {
  std::vector<ProbeResult> out;
  for (std::size_t k = 0; k < scene.probes.size(); ++k) {
    const Probe& pr = scene.probes[k];
    ProbeResult r;
    r.name = pr.name;
    r.particles = static_cast<int>(ids[k].size());
    std::unique_ptr<AnalyticField> field;
    if (pr.reference) field = std::make_unique<AnalyticField>(*pr.reference, scene.materials[0].elastic);
    r.value = probe_mean(pr, ids[k], particles.dim, u, stress);
    // Where the analytic value is taken: probes[i].reference_at (post/probe_reference.hpp).
    if (field) r.reference = probe_reference(pr, *field, ids[k], particles, scene);
    r.has_reference = static_cast<bool>(field);
    r.error = std::fabs(r.value - r.reference);
    out.push_back(r);
  }
  return out;
}

double field_error(const Scene& scene, const FieldSpec& reference, const Particles& particles,
                   const std::vector<double>& u) {
  const AnalyticField field(reference, scene.materials[0].elastic);
  double num = 0, den = 0;
  const int d = particles.dim;
  for (int p = 0; p < particles.size(); ++p) {
    const auto ua = field.displacement(particles.position(p));
    for (int c = 0; c < d; ++c) num += std::pow(ua[c] - u[p * d + c], 2), den += ua[c] * ua[c];
  }
  return den > 0 ? num / den : num;
}

double rms_error_free(const Scene& scene, const FieldSpec& reference, const Particles& particles,
                      const DofMap& dofs, const std::vector<double>& u, int& count) {
  const AnalyticField field(reference, scene.materials[0].elastic);
  const int d = particles.dim;
  double sum = 0;
  count = 0;
  for (int p = 0; p < particles.size(); ++p) {
    bool free = true;
    for (int c = 0; c < d; ++c) free = free && dofs.free_index(p * d + c) >= 0;
    if (!free) continue;
    const auto ua = field.displacement(particles.position(p));
    for (int c = 0; c < d; ++c) sum += std::pow(ua[c] - u[p * d + c], 2);
    ++count;
  }
  return count > 0 ? std::sqrt(sum / count) : 0.0;
}

std::string probe_log_line(const ProbeResult& p) {
  return p.has_reference
             ? fmt::format("  probe {}: {:.9g} (analytic {:.9g}, error {:.3e}, relative {:.3e})", p.name,
                           p.value, p.reference, p.error, p.error / std::max(std::fabs(p.reference), 1e-300))
             : fmt::format("  probe {}: {:.9g}", p.name, p.value);
}

void append_law_outputs(const ForceOperator& assembler, const Particles& particles,
                        const std::vector<double>& u, std::vector<OutputField>& fields) {
  const auto& law = assembler.law();
  if (law.n_outputs == 0) return;
  const int n = particles.size();
  const std::vector<double> outputs = assembler.particle_outputs(u.data());
  for (int k = 0; k < law.n_outputs; ++k) {
    std::vector<double> v(static_cast<std::size_t>(n));
    for (int p = 0; p < n; ++p) v[p] = outputs[static_cast<std::size_t>(p) * law.n_outputs + k];
    fields.push_back({law.output_names[k], 1, v});
  }
}

}  // namespace pd

// The result-field table (result_fields.hpp).
#include "run/result_fields.hpp"

#include <functional>

#include "damage/critical_stretch.hpp"
#include "output/csv_writer.hpp"
#include "output/vtu_writer.hpp"
#include "run/run_outputs.hpp"

namespace pd {

namespace {

struct FieldRow {
  // Whether the state has this field.
  std::function<bool(const ResultState&)> wanted;
  // Appends the field (or, for the law's outputs, one field per output name).
  std::function<void(const ResultState&, std::vector<OutputField>&)> append;
};

int dim_of(const ResultState& s) { return s.model.particles.dim; }

// In the order the files list them.
const std::vector<FieldRow>& table() {
  static const std::vector<FieldRow> rows = {
      {[](const ResultState& s) { return !s.v.empty(); },
       [](const ResultState& s, std::vector<OutputField>& f) {
         f.push_back({"velocity", dim_of(s), s.v});
       }},
      {[](const ResultState&) { return true; },
       [](const ResultState& s, std::vector<OutputField>& f) {
         const std::vector<int>& m = s.model.particles.material;
         f.push_back({"material", 1, std::vector<double>(m.begin(), m.end())});
       }},
      // A dynamic run whose bonds cannot break has no damage to show.
      {[](const ResultState& s) { return !s.dynamic || s.model.damage || !s.model.assembler->intact(); },
       [](const ResultState& s, std::vector<OutputField>& f) {
         f.push_back({"damage", 1, particle_damage(s.model.bonds)});
       }},
      // The static solve's balance check: the internal forces at the solution.
      {[](const ResultState& s) { return !s.dynamic; },
       [](const ResultState& s, std::vector<OutputField>& f) {
         std::vector<double> force(s.u.size());
         s.model.assembler->internal_forces(s.u.data(), force.data());
         f.push_back({"internal_force", dim_of(s), std::move(force)});
       }},
      {[](const ResultState& s) { return !s.u_smooth.empty(); },
       [](const ResultState& s, std::vector<OutputField>& f) {
         f.push_back({"smoothed_displacement", dim_of(s), s.u_smooth});
       }},
      {[](const ResultState& s) { return s.model.law->n_outputs > 0; },
       [](const ResultState& s, std::vector<OutputField>& f) {
         append_law_outputs(*s.model.assembler, s.model.particles, s.u, f);
       }},
      {[](const ResultState& s) { return s.scene.output.stress; },
       [](const ResultState& s, std::vector<OutputField>& f) {
         f.push_back({"stress", dim_of(s) * dim_of(s),
                      s.stress.empty() ? s.model.assembler->stresses(s.u.data()) : s.stress});
       }},
  };
  return rows;
}

}  // namespace

std::vector<OutputField> result_fields(const ResultState& state) {
  std::vector<OutputField> fields;
  for (const FieldRow& row : table())
    if (row.wanted(state)) row.append(state, fields);
  return fields;
}

void write_result_files(const std::string& dir, const Particles& particles, const std::vector<double>& u,
                        const std::vector<OutputField>& fields, const OutputSpec& output,
                        std::vector<std::string>& files) {
  if (output.vtu) {
    write_vtu_file(dir + "/result.vtu", particles, u, fields);
    files.push_back(dir + "/result.vtu");
  }
  if (output.csv) {
    write_csv_file(dir + "/result.csv", particles, u, fields);
    files.push_back(dir + "/result.csv");
  }
}

}  // namespace pd

// The one table of per-particle result fields: what a static run, a dynamic run and a
// snapshot write into result.vtu / result.csv, in which order, and when.
//
// Adding an output field is one row in result_fields.cpp (its name, components, the runs
// it belongs to and how it is computed) and a line in docs/scene_format.md's output section.
#pragma once

#include <string>
#include <vector>

#include "input/scene.hpp"
#include "model/model.hpp"
#include "output/particle_fields.hpp"

namespace pd {

// What the fields are computed from. u_smooth and stress may be empty (not computed).
struct ResultState {
  const Model& model;
  const Scene& scene;
  const std::vector<double>& u;
  const std::vector<double>& v;         // velocities (empty: a static run or relaxation)
  const std::vector<double>& u_smooth;  // output.smoothing's field (empty without it)
  const std::vector<double>& stress;    // the peridynamic stress, when already computed
  bool dynamic = false;                 // a dynamic run (or its snapshot), not a static solve
};

// The fields the table gives for this state, in the table's order.
std::vector<OutputField> result_fields(const ResultState& state);

// result.vtu and result.csv as the scene's output section asks, each appended to `files`.
void write_result_files(const std::string& dir, const Particles& particles, const std::vector<double>& u,
                        const std::vector<OutputField>& fields, const OutputSpec& output,
                        std::vector<std::string>& files);

}  // namespace pd

// What both drivers report of a built model, in the summary and the run log: the counts,
// the quadrature, the kernel variant, the elasticity line and every effect, then the set-up
// time. One place, so a static and a dynamic run describe the same model alike.
#pragma once

#include <functional>
#include <string>

#include "input/scene.hpp"
#include "model/model.hpp"
#include "run/run_summary.hpp"

namespace pd {

using RunLog = std::function<void(const std::string&)>;

// The summary's scene, law and count fields, and its effects: the quadrature (OBQ
// collocation, Gauss points), the elasticity line with the kernel variant, each effect.
void describe_model(RunSummary& summary, const Model& model, const Scene& scene);

// The set-up's first log lines: counts, horizon and set-up time, the effects, the warnings.
void log_setup(const RunSummary& summary, const Scene& scene, const RunLog& log);

}  // namespace pd

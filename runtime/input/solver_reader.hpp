// Reads the scene's `solver` section (docs/scene_format.md).
#pragma once

#include "input/solver_spec.hpp"
#include "input/yaml_keys.hpp"

namespace pd {

SolverSpec read_solver(const YamlAt& at);  // throws SceneError naming file, line and key

}  // namespace pd

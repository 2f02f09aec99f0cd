// The rules that tie a scene's sections together (a law and the domain's compensation, the
// solver's backend and the domain's Gauss points, dynamics and time functions, ...): one
// table, checked by scene.cpp after each section is read. A section's own rules stay with
// its reader.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "input/scene_sections.hpp"

namespace pd {

// Where a scene breaks a rule ("file:line: key") and what the message says.
struct Finding {
  std::string where;
  std::string message;
};

struct SceneRule {
  std::string_view name;  // what the rule asks for
  Section after;          // checked once this section (and every one before it) is read
  bool warning;           // a warning goes to Scene::warnings; an error stops the reading
  // The places the scene breaks the rule, in the order a reader meets them.
  std::vector<Finding> (*check)(const SceneReading& r);
};

const std::vector<SceneRule>& scene_rules();

// Applies the rules checked after `section`, in the table's order: throws SceneError
// ("where: message") at the first error, appends each warning to r.s.warnings.
void apply_scene_rules(Section section, SceneReading& r);

}  // namespace pd

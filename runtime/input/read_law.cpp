// The `horizon`, `law` and `influence` sections: what each family integrates, and how.
#include <string>

#include "input/scene_sections.hpp"

namespace pd {

void read_horizon(SceneReading& r) {
  if (!r.m.has("horizon")) return;
  MapReader hz(r.m.get("horizon"));
  if (hz.has("ratio") == hz.has("length")) hz.at().fail("give exactly one of ratio (delta/h), length");
  if (hz.has("ratio")) r.s.horizon_ratio = hz.number("ratio");
  if (hz.has("length")) r.s.horizon_length = hz.number("length");
  hz.finish();
}

void read_law(SceneReading& r) {
  Scene& s = r.s;
  s.law = r.m.text("law");
  r.law = abi::find_law(s.law);
  if (r.law == nullptr) r.m.get("law").fail("unknown law '" + s.law + "' (pd laws lists them)");
  if (r.law->dim != s.dim)
    r.m.get("law").fail("law " + s.law + " is " + std::to_string(r.law->dim) + "D, the scene is " +
                        std::to_string(s.dim) + "D");
}

void read_influence(SceneReading& r) {
  r.s.influence = r.m.text("influence", "const");
  if (abi::find_influence(r.s.influence) == nullptr)
    r.m.get("influence").fail("unknown influence function '" + r.s.influence + "' (pd laws lists them)");
}

}  // namespace pd

// The `materials` section: elastic constants, plane assumption, density, extra law parameters.
#include <fmt/core.h>

#include <cmath>
#include <string>

#include "input/enum_choice.hpp"
#include "input/scene_sections.hpp"

namespace pd {

template <>
struct enum_names<PlaneAssumption> {
  static constexpr std::array<EnumName<PlaneAssumption>, 3> table{{{PlaneAssumption::Strain, "strain"},
                                                                   {PlaneAssumption::Stress, "stress"},
                                                                   {PlaneAssumption::None, "none"}}};
};

namespace {

constexpr double kLargestModulus = 1e100;

MaterialSpec read_material(const YamlAt& at, int dim) {
  MapReader m(at);
  MaterialSpec s;
  s.name = m.text("name", "default");
  const bool en = m.has("E") || m.has("nu"), kg = m.has("K") || m.has("G");
  if (en == kg) at.fail("give either E and nu, or K and G");
  try {
    s.elastic = en ? IsotropicElastic::from_E_nu(m.number("E"), m.number("nu"))
                   : IsotropicElastic::from_K_G(m.number("K"), m.number("G"));
  } catch (const std::invalid_argument& e) {
    at.fail(e.what());
  }
  // Forces scale with the moduli, and the solver squares them (residual norms, the
  // factorisation's products): past ~1e100 that overflows double precision, and the run
  // would end in "the residual is not finite". Name the key instead.
  for (const char* key : {"E", "K", "G"})
    if (m.has(key) && std::fabs(m.number(key)) > kLargestModulus)
      m.get(key).fail(
          fmt::format("{:g} is too large a modulus for double precision (the solver squares forces; "
                      "above {:g} they overflow): give the moduli in units that make them moderate (e.g. "
                      "MPa or GPa instead of Pa)",
                      m.number(key), kLargestModulus));
  using PA = PlaneAssumption;
  s.plane = dim == 2 ? enum_choice(m, "plane", PA::Strain, {PA::Strain, PA::Stress})
                     : enum_choice(m, "plane", PA::None, {PA::None});
  s.density = m.number("density", 1.0);
  if (s.density <= 0) m.get("density").fail("density must be positive");
  if (m.has("parameters")) {
    const YamlAt p = m.get("parameters");
    MapReader pm(p);
    for (auto it = p.node.begin(); it != p.node.end(); ++it)
      s.parameters[it->first.Scalar()] = pm.number(it->first.Scalar());
    pm.finish();
  }
  m.finish();
  return s;
}

}  // namespace

void read_materials(SceneReading& r) {
  Scene& s = r.s;
  const YamlAt mats = r.m.get("materials");
  require_list(mats);
  if (mats.node.size() == 0) mats.fail("give at least one material");
  for (std::size_t i = 0; i < mats.node.size(); ++i) {
    const YamlAt mi = mats.element(mats.node[i], i);
    s.materials.push_back(read_material(mi, s.dim));
    for (std::size_t j = 0; j + 1 < s.materials.size(); ++j)
      if (s.materials[j].name == s.materials.back().name)
        mi.fail("material '" + s.materials.back().name + "' defined twice");
  }
}

}  // namespace pd

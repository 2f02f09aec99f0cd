// The `probes` section: a region's mean displacement or stress component, with an optional
// analytic reference and where it is taken.
#include <string>

#include "input/enum_choice.hpp"
#include "input/scene_sections.hpp"

namespace pd {

template <>
struct enum_names<Probe::Quantity> {
  static constexpr std::array<EnumName<Probe::Quantity>, 2> table{
      {{Probe::Quantity::displacement, "displacement"}, {Probe::Quantity::stress, "stress"}}};
};
// The words of reference_at (its third form is a point).
template <>
struct enum_names<Probe::ReferenceAt> {
  static constexpr std::array<EnumName<Probe::ReferenceAt>, 2> table{
      {{Probe::ReferenceAt::region, "region"}, {Probe::ReferenceAt::particles, "particles"}}};
};

namespace {

// A probe's `reference_at`: region (the default), particles, or a point.
void read_reference_at(const YamlAt& at, Probe& probe, int dim) {
  using At = Probe::ReferenceAt;
  if (!probe.reference) at.fail("reference_at needs a reference field");
  if (at.node.IsSequence()) {
    probe.reference_at = At::point;
    probe.reference_point = to_point(at, dim);
    return;
  }
  probe.reference_at = read_word(at, every_value<At>(), [](const std::string& word) {
    return "'" + word + "': expected " + name_list<At>() + " or a point [x, y(, z)]";
  });
  const Region::Kind k = probe.region.kind;
  if (probe.reference_at == At::region && k != Region::Kind::Box && k != Region::Kind::Side)
    at.fail("region: only a box or side region has a reference point; give particles or a point");
}

Probe read_probe(const YamlAt& at, std::size_t i, int dim) {
  MapReader p(at);
  Probe probe;
  probe.where = at.location();
  probe.name = p.text("name", "probe" + std::to_string(i));
  probe.region = read_region(p.get("region"), dim);
  probe.quantity = enum_choice(p, "quantity", Probe::Quantity::displacement);
  const bool stress = probe.quantity == Probe::Quantity::stress;
  const YamlAt comp = p.get("component");
  const std::string c = as_text(comp);
  if (stress) {
    if (c.size() != 2)
      comp.fail("a stress component is two letters, force then bond component (xx, xy, ...): '" + c + "'");
    probe.component = component_index(comp, c.substr(0, 1), dim);
    probe.stress_column = component_index(comp, c.substr(1, 1), dim);
  } else {
    probe.component = component_index(comp, c, dim);
  }
  if (p.has("reference")) {
    if (stress)
      p.get("reference").fail("the analytic fields give displacements: a stress probe has no reference");
    probe.reference = read_field(p.get("reference"), dim);
  }
  if (p.has("reference_at")) read_reference_at(p.get("reference_at"), probe, dim);
  p.finish();
  return probe;
}

}  // namespace

void read_probes(SceneReading& r) {
  read_list(r, "probes", r.s.probes,
            [&](const YamlAt& at, std::size_t i) { return read_probe(at, i, r.s.dim); });
}

}  // namespace pd

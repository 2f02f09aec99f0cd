// Points, components and regions of a scene: the vocabulary every section uses.
#include <vector>

#include "input/enum_choice.hpp"
#include "input/scene_sections.hpp"

namespace pd {

namespace {
enum class Axis { x, y, z };
}  // namespace
template <>
struct enum_names<Axis> {
  static constexpr std::array<EnumName<Axis>, 3> table{{{Axis::x, "x"}, {Axis::y, "y"}, {Axis::z, "z"}}};
};
Point to_point(const YamlAt& at, int dim, const char* what) {
  const auto v = as_numbers(at);
  if (static_cast<int>(v.size()) != dim) at.fail("expected " + std::to_string(dim) + " " + what);
  Point p{};
  for (int i = 0; i < dim; ++i) p[i] = v[i];
  return p;
}

int axis_index(std::string_view word, int dim) {
  const std::optional<Axis> a = parse_name<Axis>(word);
  return a && static_cast<int>(*a) < dim ? static_cast<int>(*a) : -1;
}

int component_index(const YamlAt& at, const std::string& c, int dim) {
  const int i = axis_index(c, dim);
  if (i < 0) at.fail("'" + c + "' is not a component of a " + std::to_string(dim) + "D scene");
  return i;
}

std::array<bool, 3> read_components(const YamlAt& at, int dim) {
  std::array<bool, 3> c{};
  std::vector<std::string> names;
  if (at.node.IsScalar()) {
    names.push_back(at.node.Scalar());
  } else if (at.node.IsSequence()) {
    for (std::size_t i = 0; i < at.node.size(); ++i) names.push_back(as_text(at.element(at.node[i], i)));
  } else {
    at.fail("expected a component (x, y, z) or a list of them");
  }
  for (const auto& n : names) c[component_index(at, n, dim)] = true;
  return c;
}

Region read_region(const YamlAt& at, int dim) {
  MapReader m(at);
  Region r;
  int kinds = 0;
  if (m.has("side")) {
    r.kind = Region::Kind::Side;
    std::vector<Region::Side> sides = every_value<Region::Side>();
    if (dim == 2) sides.resize(4);  // back and front are 3D
    r.side = enum_choice(m, "side", sides);
    ++kinds;
  }
  r.thickness = m.number("thickness", 0.0);
  if (r.thickness < 0) m.get("thickness").fail("thickness must not be negative");
  for (const char* key : {"box", "outside"}) {
    if (!m.has(key)) continue;
    MapReader b(m.get(key));
    r.kind = std::string(key) == "box" ? Region::Kind::Box : Region::Kind::Outside;
    r.min = to_point(b.get("min"), dim);
    r.max = to_point(b.get("max"), dim);
    b.finish();
    ++kinds;
  }
  if (m.has("collar")) {
    MapReader c(m.get("collar"));
    r.kind = Region::Kind::Collar;
    r.horizons = c.number("horizons", 1.0);
    if (!(r.horizons > 0)) c.get("horizons").fail("horizons must be positive");
    c.finish();
    ++kinds;
  }
  if (m.has("all")) {
    if (!m.boolean("all", false)) m.get("all").fail("use all: true, or another region kind");
    r.kind = Region::Kind::All;
    ++kinds;
  }
  if (kinds != 1) at.fail("give exactly one of side, box, outside, collar, all");
  if (m.has("within")) {
    MapReader b(m.get("within"));
    r.has_within = true;
    r.within_min = to_point(b.get("min"), dim);
    r.within_max = to_point(b.get("max"), dim);
    b.finish();
    for (int i = 0; i < dim; ++i)
      if (r.within_max[i] < r.within_min[i])
        m.get("within").fail("max must not be below min in any coordinate");
  }
  m.finish();
  return r;
}

}  // namespace pd

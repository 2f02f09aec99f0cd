// The `boundary` section: each condition's region, kind, values, time function and method.
#include <cmath>
#include <string>

#include "input/enum_choice.hpp"
#include "input/scene_sections.hpp"

namespace pd {

template <>
struct enum_names<BoundaryCondition::Method> {
  static constexpr std::array<EnumName<BoundaryCondition::Method>, 2> table{
      {{BoundaryCondition::Method::on_body, "on_body"},
       {BoundaryCondition::Method::fictitious_layer, "fictitious_layer"}}};
};

namespace {

using Kind = BoundaryCondition::Kind;

// `method: on_body | fictitious_layer` and the layer's `face: {point, normal}`.
void read_condition_method(const YamlAt& at, MapReader& m, BoundaryCondition& bc, int dim) {
  using Method = BoundaryCondition::Method;
  const Method method = read_word(at, every_value<Method>(), [](const std::string& word) {
    return "unknown method '" + word + "' (" + name_list<Method>() + ")";
  });
  if (method == Method::on_body) return;
  if (bc.kind == Kind::Velocity || bc.kind == Kind::BodyForce)
    at.fail("a fictitious layer carries fixed, displacement, field or traction conditions");
  if (bc.kind == Kind::Traction && dim != 2)
    at.fail("the fictitious-layer traction (paper 003 eqs. 32-35) is two-dimensional");
  if (bc.time)
    at.fail(
        "a fictitious layer's values are applied in full (statics: by the load factor); no time_function");
  bc.method = Method::fictitious_layer;
  const YamlAt face = m.get("face");
  MapReader fm(face);
  bc.face_point = to_point(fm.get("point"), dim);
  bc.face_normal = to_point(fm.get("normal"), dim);
  fm.finish();
  double norm = 0;
  for (int k = 0; k < dim; ++k) norm += bc.face_normal[k] * bc.face_normal[k];
  if (!(norm > 0)) face.fail("normal must not be zero");
  for (int k = 0; k < dim; ++k) bc.face_normal[k] /= std::sqrt(norm);
}

// fixed, displacement, velocity, field, traction or body_force: exactly one. Returns how many were given.
int read_condition_kind(MapReader& m, BoundaryCondition& bc, int dim) {
  int kinds = 0;
  if (m.has("fixed")) {
    bc.kind = Kind::Fixed;
    bc.components = read_components(m.get("fixed"), dim);
    ++kinds;
  }
  for (const char* key : {"displacement", "velocity"}) {
    if (!m.has(key)) continue;
    bc.kind = std::string(key) == "displacement" ? Kind::Displacement : Kind::Velocity;
    const YamlAt d = m.get(key);
    MapReader dm(d);
    for (const char* c : {"x", "y", "z"}) {
      if (!dm.has(c)) continue;
      const int i = component_index(dm.get(c), c, dim);
      bc.components[i] = true;
      bc.values[i] = dm.number(c);
    }
    dm.finish();
    if (!bc.components[0] && !bc.components[1] && !bc.components[2]) d.fail("give at least one of x, y, z");
    ++kinds;
  }
  if (m.has("field")) {
    bc.kind = Kind::Field;
    bc.field = read_field(m.get("field"), dim);
    bc.components = {true, true, dim == 3};
    if (m.has("components")) bc.components = read_components(m.get("components"), dim);
    ++kinds;
  }
  for (const char* key : {"traction", "body_force"}) {
    if (!m.has(key)) continue;
    bc.kind = std::string(key) == "traction" ? Kind::Traction : Kind::BodyForce;
    bc.values = to_point(m.get(key), dim);
    ++kinds;
  }
  return kinds;
}

BoundaryCondition read_condition(const YamlAt& at, int dim) {
  MapReader m(at);
  BoundaryCondition bc;
  bc.where = at.location();
  if (m.has("region")) bc.region = read_region(m.get("region"), dim);
  if (read_condition_kind(m, bc, dim) != 1)
    at.fail("give exactly one of fixed, displacement, velocity, field, traction, body_force");
  if (m.has("time_function")) {
    const YamlAt tf = m.get("time_function");
    if (bc.kind == Kind::Fixed || bc.kind == Kind::Field)
      tf.fail("time functions scale displacement, velocity, traction and body_force conditions");
    bc.time = read_time_function(tf);
    bc.time_where = tf.location();
  }
  if (m.has("method")) read_condition_method(m.get("method"), m, bc, dim);
  if (bc.kind == Kind::Traction && bc.method == BoundaryCondition::Method::on_body) {
    bc.face_measure = m.number("face_measure", 0.0);
    if (bc.region.kind != Region::Kind::Side && bc.face_measure <= 0)
      at.fail("a traction on a region that is not a side needs face_measure (the length or area it acts on)");
  }
  if (bc.kind != Kind::Field && m.has("components"))
    m.get("components").fail("components belongs to field conditions");
  m.finish();
  return bc;
}

}  // namespace

void read_boundary(SceneReading& r) {
  read_list(r, "boundary", r.s.boundary,
            [&](const YamlAt& at, std::size_t) { return read_condition(at, r.s.dim); });
}

}  // namespace pd

// Analytic fields (`reference`, a probe's reference, a field condition) and the
// `body_force` section, which takes one of the manufactured fields.
#include <string>
#include <vector>

#include "input/scene_sections.hpp"

namespace pd {

namespace {

// The parameters of each analytic solution (runtime/fields/analytic.hpp), checked here
// so that a scene with a misspelt or missing parameter fails at read time with its
// line, not later in the run. E and nu default to the body's material there.
struct FieldParameters {
  const char* solution;
  std::vector<std::string> required;
  std::vector<std::string> optional;  // besides E, nu, x0, y0
};
const std::vector<FieldParameters> kFieldParameters{
    {"uniaxial", {"traction"}, {}},
    {"biaxial", {"traction"}, {}},
    {"shear", {"traction"}, {}},
    {"westergaard", {"pressure", "half_length"}, {}},
    {"rotation", {"angle"}, {"stretch"}},
    {"inclusion", {"traction", "radius", "E_inclusion", "nu_inclusion"}, {}},
    {"michell", {"traction", "radius"}, {}},
    {"affine", {}, {"e11", "e22", "e33", "e12", "e13", "e23", "z0"}},
    {"u1", {}, {"amplitude"}},
    {"u2", {}, {"amplitude"}}};
const std::vector<std::string> kFieldOptional{"E", "nu", "x0", "y0"};

// The parameters' ranges, once the map is read.
void check_field_parameters(MapReader& m, std::map<std::string, double>& p, int dim) {
  for (const char* key : {"radius", "E_inclusion"})
    if (p.count(key) && p[key] <= 0) m.get(key).fail(std::string(key) + " must be positive");
  if (p.count("nu_inclusion") && !(p["nu_inclusion"] > -1 && p["nu_inclusion"] < 0.5))
    m.get("nu_inclusion").fail("nu_inclusion must lie in (-1, 0.5)");
  if (p.count("stretch") && !(p["stretch"] > -1)) m.get("stretch").fail("stretch must exceed -1");
  if (p.count("half_length") && p["half_length"] <= 0)
    m.get("half_length").fail("half_length must be positive");
  if (dim == 2)
    for (const char* key : {"e13", "e23", "e33", "z0"})
      if (p.count(key)) m.get(key).fail(std::string(key) + " belongs to 3D scenes");
  if (p.count("E") && p["E"] <= 0) m.get("E").fail("Young's modulus E must be positive");
  if (p.count("nu") && !(p["nu"] > -1 && p["nu"] < 0.5))
    m.get("nu").fail("Poisson's ratio nu must lie in (-1, 0.5)");
}

}  // namespace

FieldSpec read_field(const YamlAt& at, int dim) {
  MapReader m(at);
  FieldSpec f;
  std::vector<std::string> names;
  for (const auto& fp : kFieldParameters) names.push_back(fp.solution);
  f.solution = m.choice("solution", "", names);
  const FieldParameters* fp = &kFieldParameters[0];
  for (const auto& candidate : kFieldParameters)
    if (f.solution == candidate.solution) fp = &candidate;
  for (const std::string& key : fp->required) f.parameters[key] = m.number(key);
  for (const std::string& key : kFieldOptional)
    if (m.has(key)) f.parameters[key] = m.number(key);
  for (const std::string& key : fp->optional)
    if (m.has(key)) f.parameters[key] = m.number(key);
  m.finish();
  check_field_parameters(m, f.parameters, dim);
  return f;
}

// `body_force: {field: {solution, ...}, region}`: only the manufactured fields (2D, plane
// strain) have a body force density.
BodyForceField read_body_force(const YamlAt& at, int dim) {
  MapReader m(at);
  BodyForceField b;
  b.where = at.location();
  const YamlAt field = m.get("field");
  b.field = read_field(field, dim);
  if (m.has("region")) b.region = read_region(m.get("region"), dim);
  m.finish();
  const YamlAt solution = field.child(field.node["solution"], "solution");
  if (b.field.solution != "u1" && b.field.solution != "u2")
    solution.fail("'" + b.field.solution +
                  "' has no body force density (u1 and u2, paper 001's manufactured solutions, have)");
  if (dim != 2) at.fail("the manufactured fields u1 and u2 are 2D");
  return b;
}

}  // namespace pd

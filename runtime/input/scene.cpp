// The scene reader: YAML -> Scene, every key checked (runtime/input/yaml_keys.hpp).
#include "input/scene.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "input/block_domain.hpp"
#include "input/particle_domain.hpp"
#include "input/smoothing_influence.hpp"
#include "input/solver_reader.hpp"
#include "input/yaml_keys.hpp"
#include "kernel_abi.hpp"

namespace pd {

Point to_point(const YamlAt& at, int dim) {
  const auto v = as_numbers(at);
  if (static_cast<int>(v.size()) != dim) at.fail("expected " + std::to_string(dim) + " coordinates");
  Point p{};
  for (int i = 0; i < dim; ++i) p[i] = v[i];
  return p;
}

namespace {
const std::vector<std::string> kSides{"left", "right", "bottom", "top", "back", "front"};

int component_index(const YamlAt& at, const std::string& c, int dim) {
  const int i = c == "x" ? 0 : c == "y" ? 1 : c == "z" ? 2 : -1;
  if (i < 0 || i >= dim) at.fail("'" + c + "' is not a component of a " + std::to_string(dim) + "D scene");
  return i;
}

Shape read_shape(const YamlAt& at, int dim, bool inclusion) {
  MapReader m(at);
  Shape s;
  int kinds = 0;
  if (m.has("circle") || m.has("sphere")) {
    const std::string key = m.has("circle") ? "circle" : "sphere";
    MapReader c(m.get(key));
    s.kind = Shape::Kind::Circle;
    s.center = to_point(c.get("center"), dim);
    s.radius = c.number("radius");
    if (s.radius <= 0) c.get("radius").fail("radius must be positive");
    c.finish();
    ++kinds;
  }
  if (m.has("polygon")) {
    if (dim != 2) m.get("polygon").fail("polygons are 2D shapes");
    const YamlAt p = m.get("polygon");
    require_list(p);
    s.kind = Shape::Kind::Polygon;
    for (std::size_t i = 0; i < p.node.size(); ++i)
      s.vertices.push_back(to_point(p.element(p.node[i], i), dim));
    if (s.vertices.size() < 3) p.fail("a polygon needs at least 3 vertices");
    ++kinds;
  }
  if (m.has("box")) {
    MapReader b(m.get("box"));
    s.kind = Shape::Kind::Box;
    s.min = to_point(b.get("min"), dim);
    s.max = to_point(b.get("max"), dim);
    b.finish();
    for (int i = 0; i < dim; ++i)
      if (!(s.max[i] > s.min[i])) m.get("box").fail("max must exceed min in every coordinate");
    ++kinds;
  }
  if (kinds != 1) at.fail("give exactly one of circle, sphere, polygon, box");
  if (inclusion) s.material = m.text("material");
  m.finish();
  return s;
}

}  // namespace

Region read_region(const YamlAt& at, int dim) {
  MapReader m(at);
  Region r;
  int kinds = 0;
  if (m.has("side")) {
    r.kind = Region::Kind::Side;
    r.side = m.choice("side", "",
                      dim == 2 ? std::vector<std::string>(kSides.begin(), kSides.begin() + 4) : kSides);
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

// output.j_integral: a list of {contour: {min, max}} (post/j_integral.hpp, paper 004).
std::vector<JContour> read_j_contours(const YamlAt& list, int dim) {
  require_list(list);
  if (dim != 2) list.fail("the J-integral is implemented in 2D only");
  std::vector<JContour> out;
  for (std::size_t i = 0; i < list.node.size(); ++i) {
    const YamlAt item = list.element(list.node[i], i);
    MapReader m(item);
    MapReader c(m.get("contour"));
    JContour j;
    j.where = item.location();
    j.min = to_point(c.get("min"), dim);
    j.max = to_point(c.get("max"), dim);
    if (!(j.min[0] < j.max[0] && j.min[1] < j.max[1])) c.at().fail("min must be below max in x and y");
    c.finish();
    m.finish();
    out.push_back(j);
  }
  return out;
}

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
  for (const char* key : {"radius", "E_inclusion"})
    if (f.parameters.count(key) && f.parameters[key] <= 0)
      m.get(key).fail(std::string(key) + " must be positive");
  if (f.parameters.count("nu_inclusion") &&
      !(f.parameters["nu_inclusion"] > -1 && f.parameters["nu_inclusion"] < 0.5))
    m.get("nu_inclusion").fail("nu_inclusion must lie in (-1, 0.5)");
  if (f.parameters.count("stretch") && !(f.parameters["stretch"] > -1))
    m.get("stretch").fail("stretch must exceed -1");
  if (f.parameters.count("half_length") && f.parameters["half_length"] <= 0)
    m.get("half_length").fail("half_length must be positive");
  if (dim == 2)
    for (const char* key : {"e13", "e23", "e33", "z0"})
      if (f.parameters.count(key)) m.get(key).fail(std::string(key) + " belongs to 3D scenes");
  if (f.parameters.count("E") && f.parameters["E"] <= 0)
    m.get("E").fail("Young's modulus E must be positive");
  if (f.parameters.count("nu") && !(f.parameters["nu"] > -1 && f.parameters["nu"] < 0.5))
    m.get("nu").fail("Poisson's ratio nu must lie in (-1, 0.5)");
  return f;
}

// A 3D crack polygon must be planar with a non-zero area: the cutting test projects onto
// its plane, so a bent or collinear polygon would cut an ill-defined set of bonds.
void check_crack_polygon(const YamlAt& at, const std::vector<Point>& poly) {
  const Point& o = poly[0];
  double n[3] = {0, 0, 0}, size = 0;
  for (std::size_t i = 1; i + 1 < poly.size(); ++i) {
    const double u[3] = {poly[i][0] - o[0], poly[i][1] - o[1], poly[i][2] - o[2]};
    const double v[3] = {poly[i + 1][0] - o[0], poly[i + 1][1] - o[1], poly[i + 1][2] - o[2]};
    n[0] += u[1] * v[2] - u[2] * v[1];
    n[1] += u[2] * v[0] - u[0] * v[2];
    n[2] += u[0] * v[1] - u[1] * v[0];
  }
  for (const Point& q : poly) size = std::max(size, std::hypot(q[0] - o[0], q[1] - o[1], q[2] - o[2]));
  const double area2 = std::hypot(n[0], n[1], n[2]);
  if (!(area2 > 1e-12 * size * size)) at.fail("the polygon has no area");
  for (const Point& q : poly) {
    const double off = ((q[0] - o[0]) * n[0] + (q[1] - o[1]) * n[1] + (q[2] - o[2]) * n[2]) / area2;
    if (std::fabs(off) > 1e-9 * size) at.fail("the polygon is not planar");
  }
}

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
  const std::string plane =
      m.choice("plane", dim == 2 ? "strain" : "none",
               dim == 2 ? std::vector<std::string>{"strain", "stress"} : std::vector<std::string>{"none"});
  s.plane = plane == "strain"   ? PlaneAssumption::Strain
            : plane == "stress" ? PlaneAssumption::Stress
                                : PlaneAssumption::None;
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

// `method: on_body | fictitious_layer` and the layer's `face: {point, normal}`.
void read_condition_method(const YamlAt& at, MapReader& m, BoundaryCondition& bc, int dim) {
  const std::string method = as_text(at);
  if (method == "on_body") return;
  if (method != "fictitious_layer") at.fail("unknown method '" + method + "' (on_body, fictitious_layer)");
  using K = BoundaryCondition::Kind;
  if (bc.kind == K::Velocity || bc.kind == K::BodyForce)
    at.fail("a fictitious layer carries fixed, displacement, field or traction conditions");
  if (bc.kind == K::Traction && dim != 2)
    at.fail("the fictitious-layer traction (paper 003 eqs. 32-35) is two-dimensional");
  if (bc.time)
    at.fail(
        "a fictitious layer's values are applied in full (statics: by the load factor); no time_function");
  bc.method = BoundaryCondition::Method::fictitious_layer;
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

BoundaryCondition read_condition(const YamlAt& at, int dim) {
  MapReader m(at);
  BoundaryCondition bc;
  bc.where = at.location();
  if (m.has("region")) bc.region = read_region(m.get("region"), dim);
  int kinds = 0;
  if (m.has("fixed")) {
    bc.kind = BoundaryCondition::Kind::Fixed;
    bc.components = read_components(m.get("fixed"), dim);
    ++kinds;
  }
  for (const char* key : {"displacement", "velocity"}) {
    if (!m.has(key)) continue;
    bc.kind = std::string(key) == "displacement" ? BoundaryCondition::Kind::Displacement
                                                 : BoundaryCondition::Kind::Velocity;
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
    bc.kind = BoundaryCondition::Kind::Field;
    bc.field = read_field(m.get("field"), dim);
    bc.components = {true, true, dim == 3};
    if (m.has("components")) bc.components = read_components(m.get("components"), dim);
    ++kinds;
  }
  for (const char* key : {"traction", "body_force"}) {
    if (!m.has(key)) continue;
    bc.kind = std::string(key) == "traction" ? BoundaryCondition::Kind::Traction
                                             : BoundaryCondition::Kind::BodyForce;
    bc.values = to_point(m.get(key), dim);
    ++kinds;
  }
  if (kinds != 1) at.fail("give exactly one of fixed, displacement, velocity, field, traction, body_force");
  if (m.has("time_function")) {
    const YamlAt tf = m.get("time_function");
    if (bc.kind == BoundaryCondition::Kind::Fixed || bc.kind == BoundaryCondition::Kind::Field)
      tf.fail("time functions scale displacement, velocity, traction and body_force conditions");
    bc.time = read_time_function(tf);
    bc.time_where = tf.location();
  }
  if (m.has("method")) read_condition_method(m.get("method"), m, bc, dim);
  if (bc.kind == BoundaryCondition::Kind::Traction && bc.method == BoundaryCondition::Method::on_body) {
    bc.face_measure = m.number("face_measure", 0.0);
    if (bc.region.kind != Region::Kind::Side && bc.face_measure <= 0)
      at.fail("a traction on a region that is not a side needs face_measure (the length or area it acts on)");
  }
  if (bc.kind != BoundaryCondition::Kind::Field && m.has("components"))
    m.get("components").fail("components belongs to field conditions");
  m.finish();
  return bc;
}

// `body_force: {field: {solution, ...}, region}`: only the manufactured fields (2D, plane
// strain) have a body force density.
BodyForceField read_body_force(const YamlAt& at, const Scene& s) {
  MapReader m(at);
  BodyForceField b;
  b.where = at.location();
  const YamlAt field = m.get("field");
  b.field = read_field(field, s.dim);
  if (m.has("region")) b.region = read_region(m.get("region"), s.dim);
  m.finish();
  const YamlAt solution = field.child(field.node["solution"], "solution");
  if (b.field.solution != "u1" && b.field.solution != "u2")
    solution.fail("'" + b.field.solution +
                  "' has no body force density (u1 and u2, paper 001's manufactured solutions, have)");
  if (s.dim != 2) at.fail("the manufactured fields u1 and u2 are 2D");
  if (s.materials[0].plane == PlaneAssumption::Stress)
    at.fail("u1 and u2's body force is the plane-strain one; the body's material is plane stress");
  return b;
}

// A probe's `reference_at`: region (the default), particles, or a point.
void read_reference_at(const YamlAt& at, Probe& probe, int dim) {
  if (!probe.reference) at.fail("reference_at needs a reference field");
  if (at.node.IsSequence()) {
    probe.reference_at = Probe::ReferenceAt::point;
    probe.reference_point = to_point(at, dim);
    return;
  }
  const std::string v = as_text(at);
  if (v == "particles")
    probe.reference_at = Probe::ReferenceAt::particles;
  else if (v != "region")
    at.fail("'" + v + "': expected region, particles or a point [x, y(, z)]");
  const Region::Kind k = probe.region.kind;
  if (v == "region" && k != Region::Kind::Box && k != Region::Kind::Side)
    at.fail("region: only a box or side region has a reference point; give particles or a point");
}

// A parameter the law does not take is most likely a misspelt one (`stabb` for `stab`):
// the law then ran with its default, or refused, so say which names it takes.
void warn_unused_parameters(const abi::LawDescriptor& law, const YamlAt& material,
                            const std::map<std::string, double>& parameters,
                            std::vector<std::string>& warnings) {
  for (const std::string& name : unused_parameters(law, parameters)) {
    std::string taken;
    for (int i = 0; i < law.n_params; ++i) taken += (i ? ", " : "") + std::string(law.param_names[i]);
    const YamlAt at = material.child(material.node["parameters"], "parameters")
                          .child(material.node["parameters"][name], name);
    warnings.push_back(at.location() + ": law " + law.name + " takes no parameter '" + name +
                       "', it is ignored (the law's parameters: " + (taken.empty() ? "none" : taken) + ")");
  }
}

Scene read(const YAML::Node& root, const std::string& file) {
  Scene s;
  s.file = file;
  const YamlAt top{root, file, ""};
  MapReader m(top);
  s.dim = m.integer("dimension", 2);
  if (s.dim != 2 && s.dim != 3) m.get("dimension").fail("dimension must be 2 or 3");

  // A body from a particle file, or a box lattice.
  const YAML::Node domain =
      root.IsMap() ? root["domain"] : YAML::Node();  // a missing domain is reported below
  const bool from_file = domain && domain.IsMap() && domain["particles"];
  const bool from_blocks = domain && domain.IsMap() && domain["blocks"];
  std::optional<ParticleFile> cloud;
  if (from_file)
    cloud = read_particle_domain(m.get("domain"), s);
  else if (from_blocks)
    read_block_domain(m.get("domain"), s);
  else {
    MapReader d(m.get("domain"));
    MapReader box(d.get("box"));
    s.lo = to_point(box.get("min"), s.dim);
    s.hi = to_point(box.get("max"), s.dim);
    box.finish();
    for (int i = 0; i < s.dim; ++i)
      if (!(s.hi[i] > s.lo[i])) d.get("box").fail("max must exceed min in every coordinate");
    if (d.has("spacing") == d.has("count")) d.at().fail("give exactly one of spacing, count");
    if (d.has("spacing")) {
      s.h = d.number("spacing");
      if (s.h <= 0) d.get("spacing").fail("spacing must be positive");
    } else {
      const int n = d.integer("count", 0);
      if (n < 2) d.get("count").fail("count (particles along x) must be at least 2");
      s.h = (s.hi[0] - s.lo[0]) / n;
    }
    s.placement = d.choice("placement", "cell", {"cell", "node"});
    if (d.has("quadrature")) {
      const YamlAt q = d.get("quadrature");
      const std::optional<Quadrature> choice = parse_quadrature(d.text("quadrature"));
      if (!choice) q.fail("unknown quadrature (volume, partial_linear, partial_exact, obq, obq_cut)");
      s.quadrature = *choice;
    }
    if (d.has("obq_space")) {
      s.obq_space = d.choice("obq_space", "paper001", {"paper001", "paper001_odd", "law"});
      if (!is_obq(s.quadrature)) d.get("obq_space").fail("obq_space needs quadrature: obq or obq_cut");
    }
    if (d.has("obq_symmetric")) {
      s.obq_symmetric = d.boolean("obq_symmetric", false);
      if (!is_obq(s.quadrature))
        d.get("obq_symmetric").fail("obq_symmetric needs quadrature: obq or obq_cut");
    }
    if (d.has("perturbation")) {
      MapReader p(d.get("perturbation"));
      s.perturbation = p.number("amplitude", 0.0);
      if (s.perturbation < 0 || s.perturbation >= 0.5)
        p.get("amplitude").fail("amplitude is a fraction of h in [0, 0.5)");
      s.seed = static_cast<unsigned>(p.integer("seed", 1));
      p.finish();
    }
    if (d.has("compensation")) {
      s.compensation = d.boolean("compensation", false);
      if (s.compensation && is_obq(s.quadrature))
        d.get("compensation")
            .fail(
                "the compensation factor scales bond volumes; obq and obq_cut replace them by their own "
                "weights");
      if (s.compensation && s.perturbation > 0)
        d.get("compensation")
            .fail(
                "the compensation factor compares each family with the full family of a regular lattice: not "
                "on a perturbed cloud");
    }
    if (d.has("surface_correction")) {
      const std::string match = d.text("surface_correction", "none");
      if (match != "none" && match != "terms" && match != "responses")
        d.get("surface_correction")
            .fail(
                "surface_correction is none, terms (the references' recipe) or responses (both trial "
                "responses matched)");
      s.surface_correction = match != "none";
      s.surface_match_responses = match == "responses";
      if (s.surface_correction && is_obq(s.quadrature))
        d.get("surface_correction")
            .fail(
                "the surface correction compares each family with the full family of a regular lattice; obq "
                "and obq_cut replace the bond volumes by their own weights");
      if (s.surface_correction && s.compensation)
        d.get("surface_correction")
            .fail(
                "choose one of compensation (paper 002) and surface_correction (paper 003): both correct the "
                "same truncated families");
      if (s.surface_correction && s.perturbation > 0)
        d.get("surface_correction")
            .fail(
                "the surface correction compares each family with the full family of a regular lattice: not "
                "on a perturbed cloud");
    }
    if (d.has("gauss_points")) {
      // {per_axis: 1|2|3, support: r_w / h}: fixed Gauss points with MLS displacements.
      MapReader g(d.get("gauss_points"));
      s.gauss_points = g.integer("per_axis", 2);
      if (s.gauss_points < 1 || s.gauss_points > 3)
        g.get("per_axis").fail("per_axis is 1, 2 or 3 Gauss points per axis of a cell");
      s.gauss_support = g.number("support", 3.0);
      if (!(s.gauss_support >= 1.0))
        g.get("support").fail("support (the MLS radius r_w in units of h) must be at least 1");
      g.finish();
      if (s.quadrature != Quadrature::Volume || s.compensation || s.surface_correction)
        d.get("gauss_points")
            .fail(
                "the Gauss points carry their own volumes and reduction factors (eq. 3.14): not with "
                "another quadrature, compensation or surface_correction");
    }
    for (const char* key : {"holes", "inclusions"}) {
      if (!d.has(key)) continue;
      const YamlAt list = d.get(key);
      require_list(list);
      for (std::size_t i = 0; i < list.node.size(); ++i)
        (std::string(key) == "holes" ? s.holes : s.inclusions)
            .push_back(read_shape(list.element(list.node[i], i), s.dim, std::string(key) == "inclusions"));
    }
    const double cells = (s.hi[0] - s.lo[0]) / s.h;
    if (cells > 1e5) d.at().fail("more than 1e5 particles along x: check spacing/count");
    d.finish();
  }

  if (m.has("horizon")) {
    MapReader hz(m.get("horizon"));
    if (hz.has("ratio") == hz.has("length")) hz.at().fail("give exactly one of ratio (delta/h), length");
    if (hz.has("ratio")) s.horizon_ratio = hz.number("ratio");
    if (hz.has("length")) s.horizon_length = hz.number("length");
    if (s.delta() < s.h * 0.999) hz.at().fail("the horizon must be at least one spacing h");
    hz.finish();
  }

  s.law = m.text("law");
  const abi::LawDescriptor* law = abi::find_law(s.law);
  if (law == nullptr) m.get("law").fail("unknown law '" + s.law + "' (pd laws lists them)");
  if (law->dim != s.dim)
    m.get("law").fail("law " + s.law + " is " + std::to_string(law->dim) + "D, the scene is " +
                      std::to_string(s.dim) + "D");
  if (s.compensation && law->intact.energy == nullptr)
    m.get("domain").fail("compensation: law " + s.law +
                         " has no energy kernel, and the compensation factor is a ratio of energy densities "
                         "(paper 002 eq. 3.61)");
  s.influence = m.text("influence", "const");
  if (abi::find_influence(s.influence) == nullptr)
    m.get("influence").fail("unknown influence function '" + s.influence + "' (pd laws lists them)");
  if (law->ignores_influence && s.influence != "const")  // the generator found no path from w to the force
    s.warnings.push_back(m.get("influence").location() + ": law " + s.law +
                         " does not read the influence function (its "
                         "micromodulus or kernel is built in): '" +
                         s.influence +
                         "' leaves its forces unchanged and only "
                         "weights the family checks and the bonds a short-horizon preconditioner keeps");

  {
    const YamlAt mats = m.get("materials");
    require_list(mats);
    if (mats.node.size() == 0) mats.fail("give at least one material");
    for (std::size_t i = 0; i < mats.node.size(); ++i) {
      const YamlAt mi = mats.element(mats.node[i], i);
      s.materials.push_back(read_material(mi, s.dim));
      for (std::size_t j = 0; j + 1 < s.materials.size(); ++j)
        if (s.materials[j].name == s.materials.back().name)
          mi.fail("material '" + s.materials.back().name + "' defined twice");
      try {
        law_parameters(*law, s.materials.back().elastic, s.materials.back().plane,
                       s.materials.back().parameters);
      } catch (const std::invalid_argument& e) {
        mi.fail(e.what());
      }
      warn_unused_parameters(*law, mi, s.materials.back().parameters, s.warnings);
    }
  }
  if (cloud) attach_point_cloud(top.child(root["domain"], "domain"), *cloud, s);
  for (std::size_t i = 0; i < s.inclusions.size(); ++i)
    if (s.material_index(s.inclusions[i].material) < 0)
      top.child(root["domain"]["inclusions"][i], "domain.inclusions[" + std::to_string(i) + "]")
          .fail("unknown material '" + s.inclusions[i].material + "'");

  if (m.has("boundary")) {
    const YamlAt list = m.get("boundary");
    require_list(list);
    for (std::size_t i = 0; i < list.node.size(); ++i)
      s.boundary.push_back(read_condition(list.element(list.node[i], i), s.dim));
  }
  if (m.has("cracks")) {
    const YamlAt list = m.get("cracks");
    require_list(list);
    for (std::size_t i = 0; i < list.node.size(); ++i) {
      const YamlAt ci = list.element(list.node[i], i);
      MapReader c(ci);
      Crack crack;
      const YamlAt pts = c.get(s.dim == 2 ? "segment" : "polygon");
      require_list(pts);
      for (std::size_t j = 0; j < pts.node.size(); ++j)
        crack.points.push_back(to_point(pts.element(pts.node[j], j), s.dim));
      if (s.dim == 2 && crack.points.size() != 2) pts.fail("a 2D crack is a segment: two points");
      if (s.dim == 3 && crack.points.size() < 3)
        pts.fail("a 3D crack is a planar polygon: at least three points");
      if (s.dim == 2 && crack.points[0] == crack.points[1]) pts.fail("the two points coincide");
      if (s.dim == 3) check_crack_polygon(pts, crack.points);
      crack.pressure = c.number("pressure", 0.0);
      if (c.has("tips") && s.dim == 3) c.get("tips").fail("the tip rule is for 2D cracks (segments)");
      crack.tips = c.choice("tips", "cut", {"cut", "kept"}) == "kept" ? CrackTips::kept : CrackTips::cut;
      if (c.has("time_function")) {
        const YamlAt tf = c.get("time_function");
        if (crack.pressure == 0) tf.fail("a time function scales the crack pressure: give pressure");
        crack.time = read_time_function(tf);
        crack.time_where = tf.location();
      }
      c.finish();
      crack.where = ci.location();
      s.cracks.push_back(crack);
    }
  }
  if (m.has("body_force")) s.body_force = read_body_force(m.get("body_force"), s);
  if (m.has("solver")) {
    s.solver = read_solver(m.get("solver"));
    // The distributed families run the bond kernels; the Gauss families' assembler is serial.
    if (s.solver.backend == Backend::petsc && s.gauss_points > 0)
      MapReader(m.get("solver"))
          .get("backend")
          .fail(
              "backend petsc does not integrate over Gauss points (domain.gauss_points): its ranks run the "
              "bond families "
              "only; use the serial backend");
  }
  if (m.has("output")) {
    MapReader o(m.get("output"));
    s.output.directory = o.text("directory", "out");
    s.output.vtu = o.boolean("vtu", true);
    s.output.csv = o.boolean("csv", true);
    if (o.has("smoothing")) {
      MapReader sm(o.get("smoothing"));
      s.output.smoothing_influence = sm.text("influence");
      const abi::InfluenceDescriptor* inf = abi::find_influence(s.output.smoothing_influence);
      if (inf == nullptr)
        sm.get("influence")
            .fail("unknown influence function '" + s.output.smoothing_influence + "' (pd laws lists them)");
      if (!can_smooth_with(inf->weight))
        sm.get("influence")
            .fail("'" + s.output.smoothing_influence +
                  "' is singular at r = 0, and the smoothing (paper 000 eq. 49) weights each particle itself "
                  "by w(0): choose a bounded influence function");
      sm.finish();
    }
    if (o.has("j_integral")) s.output.j_integral = read_j_contours(o.get("j_integral"), s.dim);
    s.output.stress = o.boolean("stress", false);
    o.finish();
  }
  if (m.has("probes")) {
    const YamlAt list = m.get("probes");
    require_list(list);
    for (std::size_t i = 0; i < list.node.size(); ++i) {
      MapReader p(list.element(list.node[i], i));
      Probe probe;
      probe.where = list.element(list.node[i], i).location();
      probe.name = p.text("name", "probe" + std::to_string(i));
      probe.region = read_region(p.get("region"), s.dim);
      const bool stress = p.choice("quantity", "displacement", {"displacement", "stress"}) == "stress";
      const YamlAt comp = p.get("component");
      const std::string c = as_text(comp);
      if (stress) {
        if (c.size() != 2)
          comp.fail("a stress component is two letters, force then bond component (xx, xy, ...): '" + c +
                    "'");
        probe.quantity = Probe::Quantity::stress;
        probe.component = component_index(comp, c.substr(0, 1), s.dim);
        probe.stress_column = component_index(comp, c.substr(1, 1), s.dim);
      } else {
        probe.component = component_index(comp, c, s.dim);
      }
      if (p.has("reference")) {
        if (stress)
          p.get("reference").fail("the analytic fields give displacements: a stress probe has no reference");
        probe.reference = read_field(p.get("reference"), s.dim);
      }
      if (p.has("reference_at")) read_reference_at(p.get("reference_at"), probe, s.dim);
      p.finish();
      s.probes.push_back(probe);
    }
  }
  if (m.has("reference")) s.reference = read_field(m.get("reference"), s.dim);
  if (m.has("dynamics")) s.dynamics = read_dynamics(m.get("dynamics"), s.dim);
  // Without dynamics, damage breaks bonds between the Newton load steps (Simulation).
  if (m.has("damage")) {
    s.damage = read_damage(m.get("damage"));
    if (s.dynamics && !s.damage->max_resolves_where.empty())
      throw SceneError(
          s.damage->max_resolves_where +
          ": max_resolves belongs to implicit (Newton) runs: a dynamic run checks bonds every step");
  }
  if (s.dynamics && !s.output.j_integral.empty())
    m.get("output").fail("j_integral post-processes the static solution; dynamic scenes do not support it");
  if (s.dynamics && !s.output.smoothing_influence.empty())
    m.get("output").fail(
        "smoothing post-processes the static solution; dynamic scenes do not support it yet");
  if (!s.dynamics) {
    for (const BoundaryCondition& bc : s.boundary) {
      if (bc.time) throw SceneError(bc.time_where + ": time functions need a dynamics section");
      if (bc.kind == BoundaryCondition::Kind::Velocity)
        throw SceneError(bc.where + ": velocity conditions need a dynamics section");
    }
    for (const Crack& c : s.cracks)
      if (c.time)
        throw SceneError(
            c.time_where +
            ": time functions need a dynamics section (a static crack pressure follows the load factor)");
  }
  if (s.dynamics && s.dynamics->method == DynamicsMethod::relaxation) {
    for (const BoundaryCondition& bc : s.boundary) {
      if (bc.time)
        throw SceneError(bc.time_where + ": relaxation solves the static problem: no time functions");
      if (bc.kind == BoundaryCondition::Kind::Velocity)
        throw SceneError(bc.where + ": relaxation solves the static problem: no velocity conditions");
    }
    for (const Crack& c : s.cracks)
      if (c.time)
        throw SceneError(c.time_where + ": relaxation solves the static problem: no time functions");
  }
  if (s.dynamics && s.dynamics->method == DynamicsMethod::relaxation)
    for (const InitialCondition& ic : s.dynamics->initial)
      if (ic.velocity != Point{})
        throw SceneError(ic.where + ": relaxation starts at rest: give an initial displacement only");
  m.finish();
  return s;
}
}  // namespace

std::vector<double> Scene::particle_horizons() const {
  std::vector<double> delta(particle_spacing.size());
  for (std::size_t i = 0; i < delta.size(); ++i)
    delta[i] = horizon_length > 0 ? horizon_length : horizon_ratio * particle_spacing[i];
  return delta;
}

int Scene::material_index(const std::string& name) const {
  for (std::size_t i = 0; i < materials.size(); ++i)
    if (materials[i].name == name) return static_cast<int>(i);
  return -1;
}

Scene parse_scene(const std::string& yaml, const std::string& name) {
  const YAML::Node root = parse_yaml(yaml, name);
  if (!root.IsMap()) throw SceneError(name + ":1: (top level): expected a map of keys");
  return read(root, name);
}

Scene read_scene(const std::string& path) { return parse_scene(read_input_file(path, "scene"), path); }

}  // namespace pd

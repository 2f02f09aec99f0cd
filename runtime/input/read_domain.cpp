// The `domain` section: a box lattice (spacing, placement, quadrature and its options,
// holes, inclusions), or a body from a particle file or of lattice blocks.
#include <string>

#include "input/block_domain.hpp"
#include "input/enum_choice.hpp"
#include "input/particle_domain.hpp"
#include "input/scene_sections.hpp"

namespace pd {

namespace {
// domain.surface_correction's words (paper 003 eq. 19): none, or match the terms, the
// responses or the axes' directions (input/surface_match.hpp).
enum class SurfaceCorrection { none, terms, responses, directions };
}  // namespace
template <>
struct enum_names<SurfaceCorrection> {
  static constexpr std::array<EnumName<SurfaceCorrection>, 4> table{
      {{SurfaceCorrection::none, "none"},
       {SurfaceCorrection::terms, "terms"},
       {SurfaceCorrection::responses, "responses"},
       {SurfaceCorrection::directions, "directions"}}};
};

namespace {

// The names of the rules with their own weights, and of those whose volumes the corrections scale.
std::string own_weight_rules() {
  return name_list<Quadrature>(quadratures_with(&QuadratureRule::own_weights), " or ");
}
std::string volume_scaling_rules() {
  return name_list<Quadrature>(quadratures_with(&QuadratureRule::scales_volumes), " or ");
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

// box and spacing or count.
void read_lattice(MapReader& d, Scene& s) {
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
  s.placement = enum_choice(d, "placement", Placement::cell);
}

// quadrature, obq_space, obq_symmetric.
void read_quadrature(MapReader& d, Scene& s) {
  if (d.has("quadrature"))
    s.quadrature = read_word(d.get("quadrature"), every_value<Quadrature>(), [](const std::string&) {
      return "unknown quadrature (" + name_list<Quadrature>() + ")";
    });
  if (d.has("obq_space")) {
    s.obq_space = enum_choice(d, "obq_space", ObqSpace::paper001);
    if (!quadrature_rule(s.quadrature).own_weights)
      d.get("obq_space").fail("obq_space needs quadrature: " + own_weight_rules());
  }
  if (d.has("obq_symmetric")) {
    s.obq_symmetric = d.boolean("obq_symmetric", false);
    if (!quadrature_rule(s.quadrature).own_weights)
      d.get("obq_symmetric").fail("obq_symmetric needs quadrature: " + own_weight_rules());
  }
}

// compensation (paper 002) and surface_correction (paper 003): not with OBQ, a perturbed cloud or each other.
void read_corrections(MapReader& d, Scene& s) {
  if (d.has("compensation")) {
    s.compensation = d.boolean("compensation", false);
    if (s.compensation && !quadrature_rule(s.quadrature).scales_volumes)
      d.get("compensation")
          .fail("the compensation factor scales bond volumes; quadrature " +
                std::string(name_of(s.quadrature)) + " replaces them by its own weights (use " +
                volume_scaling_rules() + ")");
    if (s.compensation && s.perturbation > 0)
      d.get("compensation")
          .fail(
              "the compensation factor compares each family with the full family of a regular lattice: not "
              "on "
              "a perturbed cloud");
  }
  if (!d.has("surface_correction")) return;
  using SC = SurfaceCorrection;
  const SC match = read_word(d.get("surface_correction"), every_value<SC>(), [](const std::string&) {
    return "surface_correction is " + std::string(name_of(SC::none)) + ", " +
           std::string(name_of(SC::terms)) + " (the references' recipe), " +
           std::string(name_of(SC::responses)) + " (both trial responses matched) or " +
           std::string(name_of(SC::directions)) + " (one factor per axis, combined by the bond's direction)";
  });
  s.surface_correction = match != SC::none;
  s.surface_match = match == SC::responses    ? SurfaceMatch::Responses
                    : match == SC::directions ? SurfaceMatch::Directions
                                              : SurfaceMatch::Terms;
  const YamlAt at = d.get("surface_correction");
  if (s.surface_correction && !quadrature_rule(s.quadrature).scales_volumes)
    at.fail(
        "the surface correction compares each family with the full family of a regular lattice; quadrature " +
        std::string(name_of(s.quadrature)) + " replaces the bond volumes by its own weights (use " +
        volume_scaling_rules() + ")");
  if (s.surface_correction && s.compensation)
    at.fail(
        "choose one of compensation (paper 002) and surface_correction (paper 003): both correct the same "
        "truncated families");
  if (s.surface_correction && s.perturbation > 0)
    at.fail(
        "the surface correction compares each family with the full family of a regular lattice: not on a "
        "perturbed cloud");
}

// {per_axis: 1|2|3, support: r_w / h}: fixed Gauss points with MLS displacements.
void read_gauss_points(MapReader& d, Scene& s) {
  MapReader g(d.get("gauss_points"));
  s.gauss_points = g.integer("per_axis", 2);
  if (s.gauss_points < 1 || s.gauss_points > 3)
    g.get("per_axis").fail("per_axis is 1, 2 or 3 Gauss points per axis of a cell");
  s.gauss_support = g.number("support", 3.0);
  if (!(s.gauss_support >= 1.0))
    g.get("support").fail("support (the MLS radius r_w in units of h) must be at least 1");
  g.finish();
  if (!quadrature_rule(s.quadrature).gauss_points || s.compensation || s.surface_correction)
    d.get("gauss_points")
        .fail(
            "the Gauss points carry their own volumes and reduction factors (eq. 3.14): not with "
            "compensation, surface_correction or a quadrature other than " +
            name_list<Quadrature>(quadratures_with(&QuadratureRule::gauss_points), " or "));
}

void read_box_domain(const YamlAt& at, Scene& s) {
  MapReader d(at);
  read_lattice(d, s);
  read_quadrature(d, s);
  if (d.has("perturbation")) {
    MapReader p(d.get("perturbation"));
    s.perturbation = p.number("amplitude", 0.0);
    if (s.perturbation < 0 || s.perturbation >= 0.5)
      p.get("amplitude").fail("amplitude is a fraction of h in [0, 0.5)");
    s.seed = static_cast<unsigned>(p.integer("seed", 1));
    p.finish();
  }
  read_corrections(d, s);
  if (d.has("gauss_points")) read_gauss_points(d, s);
  for (const char* key : {"holes", "inclusions"}) {
    if (!d.has(key)) continue;
    const YamlAt list = d.get(key);
    require_list(list);
    const bool inclusions = std::string(key) == "inclusions";
    for (std::size_t i = 0; i < list.node.size(); ++i)
      (inclusions ? s.inclusions : s.holes)
          .push_back(read_shape(list.element(list.node[i], i), s.dim, inclusions));
  }
  const double cells = (s.hi[0] - s.lo[0]) / s.h;
  if (cells > 1e5) d.at().fail("more than 1e5 particles along x: check spacing/count");
  d.finish();
}

}  // namespace

void read_domain(SceneReading& r) {
  const YAML::Node domain = r.root["domain"];  // a missing domain is reported by m.get below
  const bool is_map = domain && domain.IsMap();
  if (is_map && domain["particles"])
    r.cloud = read_particle_domain(r.m.get("domain"), r.s);
  else if (is_map && domain["blocks"])
    read_block_domain(r.m.get("domain"), r.s);
  else
    read_box_domain(r.m.get("domain"), r.s);
}

}  // namespace pd

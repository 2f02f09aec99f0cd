// The `cracks` section: 2D segments and 3D planar polygons, with pressure and tip rule.
#include <algorithm>
#include <cmath>

#include "input/enum_choice.hpp"
#include "input/scene_sections.hpp"

namespace pd {

namespace {

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

Crack read_crack(const YamlAt& ci, int dim) {
  MapReader c(ci);
  Crack crack;
  const YamlAt pts = c.get(dim == 2 ? "segment" : "polygon");
  require_list(pts);
  for (std::size_t j = 0; j < pts.node.size(); ++j)
    crack.points.push_back(to_point(pts.element(pts.node[j], j), dim));
  if (dim == 2 && crack.points.size() != 2) pts.fail("a 2D crack is a segment: two points");
  if (dim == 3 && crack.points.size() < 3) pts.fail("a 3D crack is a planar polygon: at least three points");
  if (dim == 2 && crack.points[0] == crack.points[1]) pts.fail("the two points coincide");
  if (dim == 3) check_crack_polygon(pts, crack.points);
  crack.pressure = c.number("pressure", 0.0);
  if (c.has("tips") && dim == 3) c.get("tips").fail("the tip rule is for 2D cracks (segments)");
  crack.tips = enum_choice(c, "tips", CrackTips::cut);
  if (c.has("time_function")) {
    const YamlAt tf = c.get("time_function");
    if (crack.pressure == 0) tf.fail("a time function scales the crack pressure: give pressure");
    crack.time = read_time_function(tf);
    crack.time_where = tf.location();
  }
  c.finish();
  crack.where = ci.location();
  return crack;
}

}  // namespace

void read_cracks(SceneReading& r) {
  read_list(r, "cracks", r.s.cracks, [&](const YamlAt& at, std::size_t) { return read_crack(at, r.s.dim); });
}

}  // namespace pd

// Bond cutting by pre-cracks, with ties (a particle on the crack line, a bond through a
// tip) decided by one tolerance relative to the bond length and the crack's tip rule.
#include "discretize/crack_cut.hpp"

#include <algorithm>
#include <cmath>

namespace pd {

namespace {
double cross2(double ax, double ay, double bx, double by) { return ax * by - ay * bx; }

// Bond pq crosses crack ab (2D): p and q on opposite sides of the crack's line, each
// farther than the tie distance from it, and the crossing point on the crack segment.
// The crossing point's distance s along the crack from a is compared with 0 and the
// crack length L with the same tolerance: within it the bond passes through a tip and
// `tips` decides. The rounding error of s is ~1e-16 |xi|, far below the tolerance, so a
// tie is recognised whatever the rounding (a bond and its mirror image agree).
bool segments_cross(const double* p, const double* q, const Crack& c) {
  const Point& a = c.points[0];
  const Point& b = c.points[1];
  const double ex = b[0] - a[0], ey = b[1] - a[1];
  const double length = std::hypot(ex, ey);
  const double tie = tie_tolerance * std::hypot(q[0] - p[0], q[1] - p[1]);
  // Signed distances of p and q from the crack's line.
  const double dp = cross2(ex, ey, p[0] - a[0], p[1] - a[1]) / length;
  const double dq = cross2(ex, ey, q[0] - a[0], q[1] - a[1]) / length;
  if (std::fabs(dp) <= tie || std::fabs(dq) <= tie || (dp > 0) == (dq > 0)) return false;
  const double t = dp / (dp - dq);
  const double x = p[0] + t * (q[0] - p[0]), y = p[1] + t * (q[1] - p[1]);
  const double s = ((x - a[0]) * ex + (y - a[1]) * ey) / length;
  if (std::fabs(s) <= tie || std::fabs(s - length) <= tie) return c.tips == CrackTips::cut;
  return s > 0 && s < length;
}

// Segment pq against a planar polygon (3D): the crossing point of the polygon's plane
// must lie inside the polygon (tested in the plane's projection). Ties on the polygon's
// edges are not treated specially (the 2D tip rule has no 3D counterpart yet).
bool segment_crosses_polygon(const double* p, const double* q, const std::vector<Point>& poly) {
  const Point& o = poly[0];
  double nrm[3] = {0, 0, 0};
  for (std::size_t i = 1; i + 1 < poly.size(); ++i) {
    const double u[3] = {poly[i][0] - o[0], poly[i][1] - o[1], poly[i][2] - o[2]};
    const double v[3] = {poly[i + 1][0] - o[0], poly[i + 1][1] - o[1], poly[i + 1][2] - o[2]};
    nrm[0] += u[1] * v[2] - u[2] * v[1];
    nrm[1] += u[2] * v[0] - u[0] * v[2];
    nrm[2] += u[0] * v[1] - u[1] * v[0];
  }
  const double sp = (p[0] - o[0]) * nrm[0] + (p[1] - o[1]) * nrm[1] + (p[2] - o[2]) * nrm[2];
  const double sq = (q[0] - o[0]) * nrm[0] + (q[1] - o[1]) * nrm[1] + (q[2] - o[2]) * nrm[2];
  if ((sp > 0) == (sq > 0) || sp == 0 || sq == 0) return false;
  const double t = sp / (sp - sq);
  double x[3];
  for (int c = 0; c < 3; ++c) x[c] = p[c] + t * (q[c] - p[c]);
  // Drop the dominant normal axis and test in 2D.
  int drop = 0;
  for (int c = 1; c < 3; ++c)
    if (std::fabs(nrm[c]) > std::fabs(nrm[drop])) drop = c;
  const int a0 = drop == 0 ? 1 : 0, a1 = drop == 2 ? 1 : 2;
  bool inside = false;
  for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    const double yi = poly[i][a1], yj = poly[j][a1], xi = poly[i][a0], xj = poly[j][a0];
    if ((yi > x[a1]) != (yj > x[a1]) && x[a0] < (xj - xi) * (x[a1] - yi) / (yj - yi) + xi) inside = !inside;
  }
  return inside;
}
}  // namespace

bool crack_crosses(const Crack& c, const double* xa, const double* xb, int dim) {
  return dim == 2 ? segments_cross(xa, xb, c) : segment_crosses_polygon(xa, xb, c.points);
}

int cut_bonds(const std::vector<Crack>& cracks, const Particles& p, Bonds& bonds) {
  return cut_bonds(cracks, p, bonds, nullptr);
}

int cut_bonds(const std::vector<Crack>& cracks, const Particles& p, Bonds& bonds,
              std::vector<int>* crossed_per_crack) {
  if (crossed_per_crack) crossed_per_crack->assign(cracks.size(), 0);
  int broken = 0;
  const int d = p.dim;
  for (int i = 0; i < p.size(); ++i)
    for (int b = bonds.offsets[i]; b < bonds.offsets[i + 1]; ++b) {
      // The lower index first: both directions of a bond then run the same arithmetic,
      // so a bond is cut in both families or in neither.
      const int lo = std::min(i, bonds.neighbor[b]), hi = std::max(i, bonds.neighbor[b]);
      const double* xa = p.position(lo);
      const double* xb = p.position(hi);
      for (std::size_t k = 0; k < cracks.size(); ++k) {
        const bool cross = crack_crosses(cracks[k], xa, xb, d);
        if (cross && crossed_per_crack) ++(*crossed_per_crack)[k];
        if (cross && bonds.alpha[b] != 0.0) {
          bonds.alpha[b] = 0.0;
          ++broken;
        }
      }
    }
  return broken;
}

}  // namespace pd

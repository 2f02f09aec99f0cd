// Lattice discretisation, cell-list neighbour search, crack cutting.
#include "discretize/discretization.hpp"

#include "input/yaml_keys.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <stdexcept>

namespace pd {

Particles discretize(const Scene& s) {
  Particles p;
  p.dim = s.dim;
  const bool node = s.placement == "node";
  std::array<int, 3> n{1, 1, 1};
  for (int i = 0; i < s.dim; ++i) {
    const double cells = (s.hi[i] - s.lo[i]) / s.h;
    n[i] = static_cast<int>(std::lround(cells)) + (node ? 1 : 0);
    if (n[i] < 1) n[i] = 1;
  }
  std::mt19937_64 rng(s.seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const double volume = std::pow(s.h, s.dim);
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i) {
        const int idx[3] = {i, j, k};
        double x[3] = {0, 0, 0};
        for (int c = 0; c < s.dim; ++c) x[c] = s.lo[c] + (idx[c] + (node ? 0.0 : 0.5)) * s.h;
        bool hole = false;
        for (const Shape& sh : s.holes) hole = hole || sh.contains(x, s.dim);
        if (hole) continue;
        if (s.perturbation > 0)
          for (int c = 0; c < s.dim; ++c) x[c] += s.perturbation * s.h * u(rng);
        int material = 0;
        for (const Shape& inc : s.inclusions)
          if (inc.contains(x, s.dim)) material = s.material_index(inc.material);
        for (int c = 0; c < s.dim; ++c) p.x.push_back(x[c]);
        p.volume.push_back(volume);
        p.material.push_back(material);
      }
  if (p.size() == 0) throw SceneError(s.file + ": domain: the domain holds no particle (do the holes cover it?)");
  return p;
}

std::vector<int> region_particles(const Region& region, const Particles& p, const Scene& scene) {
  // A side with no thickness means the outermost row. Its boundary is put halfway
  // between that row and the next: h from the face for cell centres (rows at h/2, 3h/2),
  // h/2 for nodes (rows at 0, h). A perturbed row (amplitude < h/2) then stays whole,
  // and no unperturbed row sits on the boundary where rounding would decide.
  Region r = region;
  if (r.kind == Region::Kind::Side && r.thickness <= 0) r.thickness = scene.placement == "node" ? 0.5 * scene.h : scene.h;
  // A collar particle at depth d lacks the lattice site beyond the face, at distance d + s
  // (s = h/2 for cell centres, h for nodes), when d + s <= k delta. The tolerance puts a
  // site exactly k delta away (half-integer delta/h) inside the family, as find_bonds does.
  if (r.kind == Region::Kind::Collar)
    r.thickness = r.horizons * scene.delta() - (scene.placement == "node" ? scene.h : 0.5 * scene.h) + 1e-6 * scene.h;
  std::vector<int> out;
  for (int i = 0; i < p.size(); ++i)
    if (r.contains(p.position(i), p.dim, scene.lo, scene.hi, scene.h)) out.push_back(i);
  return out;
}

namespace {
// A family holds the particles within delta (1 + 1e-12): the tolerance keeps a lattice
// site exactly delta away (integer delta/h) whatever the rounding of |xi|.
double family_reach(double delta) { return delta * (1 + 1e-12); }
// A bond weighs nothing when its w is below this fraction of the largest in its bonds.
constexpr double negligible_weight_fraction = 1e-12;
}  // namespace

Bonds find_bonds(const Particles& p, double delta, double (*influence)(double, double)) {
  const int d = p.dim, n = p.size();
  // Cell list with cells a little larger than the reach delta (1 + 1e-12): neighbours then
  // lie in the 3^d surrounding cells even when rounding of (x - lo) / size puts a neighbour
  // exactly delta away (integer delta/h on a lattice) one cell further than exact arithmetic.
  const double size = delta * (1 + 1e-9);
  double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
  for (int c = 0; c < d; ++c) {
    lo[c] = hi[c] = p.x[c];
    for (int i = 0; i < n; ++i) lo[c] = std::min(lo[c], p.x[i * d + c]), hi[c] = std::max(hi[c], p.x[i * d + c]);
  }
  int dims[3] = {1, 1, 1};
  for (int c = 0; c < d; ++c) dims[c] = std::max(1, static_cast<int>((hi[c] - lo[c]) / size) + 1);
  auto cell_of = [&](const double* x, int* ci) {
    for (int c = 0; c < 3; ++c) ci[c] = c < d ? std::min(dims[c] - 1, static_cast<int>((x[c] - lo[c]) / size)) : 0;
  };
  const std::size_t n_cells = static_cast<std::size_t>(dims[0]) * dims[1] * dims[2];
  std::vector<int> cell_start(n_cells + 1, 0), cell_items(static_cast<std::size_t>(n));
  std::vector<std::size_t> cell_index(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    int ci[3];
    cell_of(p.position(i), ci);
    cell_index[i] = (static_cast<std::size_t>(ci[2]) * dims[1] + ci[1]) * dims[0] + ci[0];
    ++cell_start[cell_index[i] + 1];
  }
  for (std::size_t c = 0; c < n_cells; ++c) cell_start[c + 1] += cell_start[c];
  {
    std::vector<int> fill(cell_start.begin(), cell_start.end() - 1);
    for (int i = 0; i < n; ++i) cell_items[fill[cell_index[i]]++] = i;
  }
  Bonds b;
  b.dim = d;
  b.offsets.assign(static_cast<std::size_t>(n) + 1, 0);
  b.delta.assign(static_cast<std::size_t>(n), delta);
  const double reach2 = family_reach(delta) * family_reach(delta);
  std::vector<int> found;
  for (int i = 0; i < n; ++i) {
    int ci[3];
    cell_of(p.position(i), ci);
    found.clear();
    for (int dz = (d == 3 ? -1 : 0); dz <= (d == 3 ? 1 : 0); ++dz)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int cx = ci[0] + dx, cy = ci[1] + dy, cz = ci[2] + dz;
          if (cx < 0 || cy < 0 || cz < 0 || cx >= dims[0] || cy >= dims[1] || cz >= dims[2]) continue;
          const std::size_t cell = (static_cast<std::size_t>(cz) * dims[1] + cy) * dims[0] + cx;
          for (int q = cell_start[cell]; q < cell_start[cell + 1]; ++q) {
            const int j = cell_items[q];
            if (j == i) continue;
            double r2 = 0;
            for (int c = 0; c < d; ++c) r2 += (p.x[j * d + c] - p.x[i * d + c]) * (p.x[j * d + c] - p.x[i * d + c]);
            if (r2 <= reach2) found.push_back(j);
          }
        }
    std::sort(found.begin(), found.end());
    for (int j : found) {
      double r2 = 0;
      for (int c = 0; c < d; ++c) {
        const double e = p.x[j * d + c] - p.x[i * d + c];
        b.xi.push_back(e);
        r2 += e * e;
      }
      const double r = std::sqrt(r2);
      b.neighbor.push_back(j);
      b.length.push_back(r);
      b.w.push_back(influence(r, delta));
      b.alpha.push_back(1.0);
    }
    b.offsets[i + 1] = static_cast<int>(b.neighbor.size());
  }
  return b;
}

int drop_negligible_bonds(Bonds& b) {
  const int n = b.particle_count(), d = b.dim;
  const double negligible =
      negligible_weight_fraction * (b.w.empty() ? 0.0 : *std::max_element(b.w.begin(), b.w.end()));
  int kept = 0, dropped = 0;
  for (int p = 0; p < n; ++p) {
    const int begin = b.offsets[p], end = b.offsets[p + 1];
    b.offsets[p] = kept;
    for (int k = begin; k < end; ++k) {
      if (b.w[k] <= negligible) {
        ++dropped;
        continue;
      }
      b.neighbor[kept] = b.neighbor[k], b.length[kept] = b.length[k], b.w[kept] = b.w[k], b.alpha[kept] = b.alpha[k];
      for (int c = 0; c < d; ++c) b.xi[static_cast<std::size_t>(kept) * d + c] = b.xi[static_cast<std::size_t>(k) * d + c];
      ++kept;
    }
  }
  b.offsets[n] = kept;
  b.neighbor.resize(kept), b.length.resize(kept), b.w.resize(kept), b.alpha.resize(kept);
  b.xi.resize(static_cast<std::size_t>(kept) * d);
  return dropped;
}

double mean_short_family_size(const Bonds& b, double short_delta, double (*influence)(double, double)) {
  const int n = b.particle_count();
  if (n == 0) return 0;
  const double reach = family_reach(short_delta);
  double largest = 0;
  for (int k = 0; k < b.bond_count(); ++k)
    if (b.length[k] <= reach) largest = std::max(largest, influence(b.length[k], short_delta));
  long long count = 0;
  for (int k = 0; k < b.bond_count(); ++k)
    count += b.length[k] <= reach && influence(b.length[k], short_delta) > negligible_weight_fraction * largest;
  return static_cast<double>(count) / n;
}

namespace {
double cross2(double ax, double ay, double bx, double by) { return ax * by - ay * bx; }

// Bond pq crosses crack ab (2D): p and q strictly on opposite sides of the crack's line
// (a particle on the line is on neither side), and the crossing point on the closed
// crack segment (a bond through a crack tip is cut). Both tests use sign products, so
// the answer does not depend on the order of p and q.
bool segments_cross(const double* p, const double* q, const Point& a, const Point& b) {
  const double d1 = cross2(b[0] - a[0], b[1] - a[1], p[0] - a[0], p[1] - a[1]);
  const double d2 = cross2(b[0] - a[0], b[1] - a[1], q[0] - a[0], q[1] - a[1]);
  const double d3 = cross2(q[0] - p[0], q[1] - p[1], a[0] - p[0], a[1] - p[1]);
  const double d4 = cross2(q[0] - p[0], q[1] - p[1], b[0] - p[0], b[1] - p[1]);
  const auto sign = [](double v) { return (v > 0) - (v < 0); };
  return sign(d1) * sign(d2) < 0 && sign(d3) * sign(d4) <= 0;
}

// Segment pq against a planar polygon (3D): the crossing point of the polygon's plane
// must lie inside the polygon (tested in the plane's projection).
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

int cut_bonds(const std::vector<Crack>& cracks, const Particles& p, Bonds& bonds) {
  return cut_bonds(cracks, p, bonds, nullptr);
}

int cut_bonds(const std::vector<Crack>& cracks, const Particles& p, Bonds& bonds, std::vector<int>* crossed_per_crack) {
  if (crossed_per_crack) crossed_per_crack->assign(cracks.size(), 0);
  int broken = 0;
  const int d = p.dim;
  for (int i = 0; i < p.size(); ++i)
    for (int b = bonds.offsets[i]; b < bonds.offsets[i + 1]; ++b) {
      // The lower index first: both directions of a bond then run the same arithmetic,
      // so a bond through a crack tip is cut in both families or in neither.
      const int lo = std::min(i, bonds.neighbor[b]), hi = std::max(i, bonds.neighbor[b]);
      const double* xa = p.position(lo);
      const double* xb = p.position(hi);
      for (std::size_t k = 0; k < cracks.size(); ++k) {
        const Crack& c = cracks[k];
        const bool cross = d == 2 ? segments_cross(xa, xb, c.points[0], c.points[1]) : segment_crosses_polygon(xa, xb, c.points);
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

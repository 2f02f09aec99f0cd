// Lattice discretisation, cell-list neighbour search (crack cutting: crack_cut.cpp).
#include "discretize/discretization.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <stdexcept>

#include "discretize/lattice_blocks.hpp"
#include "input/yaml_keys.hpp"

namespace pd {

Particles discretize(const Scene& s) {
  if (s.point_cloud) return *s.point_cloud;  // domain.particles
  Particles p;
  p.dim = s.dim;
  const bool node = s.placement == Placement::node;
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
  if (p.size() == 0)
    throw SceneError(s.file + ": domain: the domain holds no particle (do the holes cover it?)");
  return p;
}

std::vector<int> region_particles(const Region& region, const Particles& p, const Scene& scene) {
  // A side with no thickness means the outermost row. Its boundary is put halfway
  // between that row and the next: h from the face for cell centres (rows at h/2, 3h/2),
  // h/2 for nodes (rows at 0, h). A perturbed row (amplitude < h/2) then stays whole,
  // and no unperturbed row sits on the boundary where rounding would decide.
  Region r = region;
  if (r.kind == Region::Kind::Side && r.thickness <= 0)
    r.thickness = scene.placement == Placement::node ? 0.5 * scene.h : scene.h;
  // A collar particle at depth d lacks the lattice site beyond the face, at distance d + s
  // (s = h/2 for cell centres, h for nodes), when d + s <= k delta. The tolerance puts a
  // site exactly k delta away (half-integer delta/h) inside the family, as find_bonds does.
  if (r.kind == Region::Kind::Collar)
    r.thickness = r.horizons * scene.delta() -
                  (scene.placement == Placement::node ? scene.h : 0.5 * scene.h) + 1e-6 * scene.h;
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
  // One horizon for all: the per-particle search scans the 3^d surrounding cells.
  return find_bonds_per_particle(p, std::vector<double>(static_cast<std::size_t>(p.size()), delta),
                                 influence);
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
      b.neighbor[kept] = b.neighbor[k], b.length[kept] = b.length[k], b.w[kept] = b.w[k],
      b.alpha[kept] = b.alpha[k];
      if (!b.volume_factor.empty()) b.volume_factor[kept] = b.volume_factor[k];
      for (int c = 0; c < d; ++c)
        b.xi[static_cast<std::size_t>(kept) * d + c] = b.xi[static_cast<std::size_t>(k) * d + c];
      ++kept;
    }
  }
  b.offsets[n] = kept;
  b.neighbor.resize(kept), b.length.resize(kept), b.w.resize(kept), b.alpha.resize(kept);
  if (!b.volume_factor.empty()) b.volume_factor.resize(kept);
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
    count +=
        b.length[k] <= reach && influence(b.length[k], short_delta) > negligible_weight_fraction * largest;
  return static_cast<double>(count) / n;
}

}  // namespace pd

// Crack cutting is decided by geometry, not by rounding: a crack symmetric about both axes
// of a symmetric lattice breaks a bond set symmetric about both axes, at every resolution
// (tips on cell corners, on particle columns, anywhere) and under both tip rules.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include "discretize/discretization.hpp"

namespace {

double unit(double, double) { return 1.0; }

struct Band {
  pd::Particles particles;
  std::vector<int> i, j;  // lattice indices of each particle
  int points = 0;         // lattice points per axis
};

// The lattice of the square [-half, half]^2 at `count` cells, kept only near the crack (a
// band symmetric in lattice indices, so the mirror image of every kept particle is kept).
Band lattice_band(double half, int count, const std::string& placement, double crack_half, double reach) {
  pd::Scene s;
  s.dim = 2;
  s.lo = {-half, -half, 0};
  s.hi = {half, half, 0};
  s.h = 2 * half / count;
  s.placement = *pd::parse_name<pd::Placement>(placement);
  s.materials.resize(1);
  const pd::Particles all = pd::discretize(s);
  Band band;
  band.points = placement == "node" ? count + 1 : count;
  band.particles.dim = 2;
  const double shift = placement == "node" ? 0.0 : 0.5;
  const double mid = 0.5 * (band.points - 1);
  for (int p = 0; p < all.size(); ++p) {
    const int i = static_cast<int>(std::lround((all.position(p)[0] + half) / s.h - shift));
    const int j = static_cast<int>(std::lround((all.position(p)[1] + half) / s.h - shift));
    if (std::fabs(i - mid) > (crack_half + reach) / s.h + 2 || std::fabs(j - mid) > reach / s.h + 2) continue;
    band.particles.x.insert(band.particles.x.end(), {all.position(p)[0], all.position(p)[1]});
    band.particles.volume.push_back(all.volume[p]);
    band.particles.material.push_back(0);
    band.i.push_back(i);
    band.j.push_back(j);
  }
  return band;
}

// Whether the broken-bond set is its own mirror image in x (flip_x) or in y. Returns the
// count of broken bonds (one direction) whose mirror image is intact.
int asymmetric_bonds(const Band& band, const pd::Bonds& b, bool flip_x) {
  std::vector<int> at(static_cast<std::size_t>(band.points) * band.points, -1);
  for (std::size_t p = 0; p < band.i.size(); ++p)
    at[static_cast<std::size_t>(band.j[p]) * band.points + band.i[p]] = static_cast<int>(p);
  const auto mirror = [&](int p) {
    const int i = flip_x ? band.points - 1 - band.i[p] : band.i[p];
    const int j = flip_x ? band.j[p] : band.points - 1 - band.j[p];
    return at[static_cast<std::size_t>(j) * band.points + i];
  };
  int differing = 0;
  for (int p = 0; p < b.particle_count(); ++p)
    for (int e = b.offsets[p]; e < b.offsets[p + 1]; ++e) {
      if (b.alpha[e] != 0.0) continue;
      const int mp = mirror(p), mq = mirror(b.neighbor[e]);
      bool mirror_broken = false;
      for (int f = b.offsets[mp]; f < b.offsets[mp + 1]; ++f)
        if (b.neighbor[f] == mq) mirror_broken = b.alpha[f] == 0.0;
      differing += !mirror_broken;
    }
  return differing;
}

struct Geometry {
  double half, crack_half;  // the box [-half, half]^2, the crack [-crack_half, crack_half] x {0}
};

}  // namespace

TEST(CrackTips, SymmetricCrackBreaksMirrorSymmetricBondsAtEveryCount) {
  // scenes/crack.yaml (tips on cell corners at every count divisible by 40) and the
  // unit-modulus crack of issue 20 ([-1, 1]^2, a = 0.1: corners at multiples of 20).
  for (const Geometry& g : {Geometry{1.4, 0.35}, Geometry{1.0, 0.1}})
    for (const std::string placement : {"cell", "node"})
      for (int count = 20; count <= 200; ++count) {
        const double h = 2 * g.half / count, delta = 3.5 * h;
        const Band band = lattice_band(g.half, count, placement, g.crack_half, delta);
        const pd::Bonds intact = pd::find_bonds(band.particles, delta, unit);
        int broken[2] = {0, 0};
        for (const pd::CrackTips tips : {pd::CrackTips::cut, pd::CrackTips::kept}) {
          pd::Crack crack;
          crack.points = {pd::Point{-g.crack_half, 0, 0}, pd::Point{g.crack_half, 0, 0}};
          crack.tips = tips;
          pd::Bonds b = intact;
          const int n = pd::cut_bonds({crack}, band.particles, b);
          broken[tips == pd::CrackTips::kept] = n;
          const std::string what = placement + " " + std::to_string(count) +
                                   (tips == pd::CrackTips::cut ? " tips cut" : " tips kept") +
                                   ", half-width " + std::to_string(g.half);
          ASSERT_GT(n, 0) << what;
          ASSERT_EQ(asymmetric_bonds(band, b, true), 0) << what << ": not symmetric in x";
          ASSERT_EQ(asymmetric_bonds(band, b, false), 0) << what << ": not symmetric in y";
        }
        // With a tip on a cell corner (scenes/crack.yaml at counts divisible by 40) the
        // bonds through the tip are real ties, and the two rules must differ.
        if (g.half == 1.4 && placement == "cell" && count % 40 == 0) {
          EXPECT_GT(broken[0], broken[1]) << count;
        }
        EXPECT_GE(broken[0], broken[1]) << placement << " " << count;
      }
}

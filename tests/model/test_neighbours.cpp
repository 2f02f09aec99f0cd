// Neighbour search: the cell list against brute force on random clouds in 2D and 3D,
// every per-bond array, both directions of each bond, and bonds exactly at the horizon.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "discretize/discretization.hpp"
#include "kernel_abi.hpp"

namespace {

pd::Particles random_cloud(int dim, int n, const double* extent, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  pd::Particles p;
  p.dim = dim;
  for (int i = 0; i < n; ++i) {
    for (int c = 0; c < dim; ++c) p.x.push_back(-3.0 + extent[c] * u(rng));
    p.volume.push_back(1.0);
    p.material.push_back(0);
  }
  return p;
}

double weight(double r, double delta) { return 1.0 + r / delta; }  // distinguishes r, so w must use |xi|

void check_against_brute_force(const pd::Particles& p, double delta) {
  const int d = p.dim, n = p.size();
  const pd::Bonds b = pd::find_bonds(p, delta, weight);
  ASSERT_EQ(b.particle_count(), n);
  ASSERT_EQ(static_cast<int>(b.delta.size()), n);
  ASSERT_EQ(b.xi.size(), static_cast<std::size_t>(b.bond_count()) * d);
  ASSERT_EQ(b.length.size(), static_cast<std::size_t>(b.bond_count()));
  ASSERT_EQ(b.w.size(), b.length.size());
  ASSERT_EQ(b.alpha.size(), b.length.size());
  long long total = 0;
  for (int i = 0; i < n; ++i) {
    EXPECT_EQ(b.delta[i], delta);
    std::vector<int> expected;
    for (int j = 0; j < n; ++j) {
      if (j == i) continue;
      double r2 = 0;
      for (int c = 0; c < d; ++c) r2 += std::pow(p.x[j * d + c] - p.x[i * d + c], 2);
      if (std::sqrt(r2) <= delta) expected.push_back(j);
    }
    total += static_cast<long long>(expected.size());
    const std::vector<int> got(b.neighbor.begin() + b.offsets[i], b.neighbor.begin() + b.offsets[i + 1]);
    ASSERT_EQ(got, expected) << "particle " << i;  // ascending, like the brute-force order
    for (int e = b.offsets[i]; e < b.offsets[i + 1]; ++e) {
      const int j = b.neighbor[e];
      double r2 = 0;
      for (int c = 0; c < d; ++c) {
        EXPECT_DOUBLE_EQ(b.xi[e * d + c], p.x[j * d + c] - p.x[i * d + c]);
        r2 += b.xi[e * d + c] * b.xi[e * d + c];
      }
      EXPECT_DOUBLE_EQ(b.length[e], std::sqrt(r2));
      EXPECT_DOUBLE_EQ(b.w[e], weight(b.length[e], delta));
      EXPECT_EQ(b.alpha[e], 1.0);
      // The reverse bond exists in j's family.
      bool reverse = false;
      for (int f = b.offsets[j]; f < b.offsets[j + 1]; ++f) reverse = reverse || b.neighbor[f] == i;
      EXPECT_TRUE(reverse) << i << " -> " << j;
    }
  }
  EXPECT_EQ(total, b.bond_count());
}

}  // namespace

TEST(Neighbours, RandomCloudsMatchBruteForce2D) {
  const double square[2] = {2.0, 2.0}, strip[2] = {10.0, 0.3};
  check_against_brute_force(random_cloud(2, 700, square, 1), 0.17);
  check_against_brute_force(random_cloud(2, 700, strip, 2), 0.25);  // fewer cells in y than the stencil
  check_against_brute_force(random_cloud(2, 300, square, 3), 5.0);  // horizon larger than the cloud
}

TEST(Neighbours, RandomCloudsMatchBruteForce3D) {
  const double cube[3] = {1.0, 1.0, 1.0}, slab[3] = {3.0, 2.0, 0.2};
  check_against_brute_force(random_cloud(3, 900, cube, 4), 0.16);
  check_against_brute_force(random_cloud(3, 900, slab, 5), 0.31);
}

TEST(Neighbours, PerturbedLatticeMatchesBruteForce) {
  for (int dim : {2, 3}) {
    pd::Scene s;
    s.dim = dim;
    s.lo = {0, 0, 0};
    s.hi = {1.2, 0.8, 0.6};
    s.h = 0.1;
    s.perturbation = 0.4;
    s.seed = 9;
    s.materials.resize(1);
    check_against_brute_force(pd::discretize(s), 3.0 * s.h);
  }
}

TEST(Neighbours, BondsAtExactlyTheHorizonAreKept) {
  // On an unperturbed lattice with delta = 3h, the particles at distance 3h along the
  // axes lie on the horizon up to rounding; (1 + 1e-12) keeps them. An interior family
  // then holds every integer offset (a, b) with 0 < a^2 + b^2 <= 9: 28 in 2D, 122 in 3D.
  for (int dim : {2, 3}) {
    pd::Scene s;
    s.dim = dim;
    s.lo = {0, 0, 0};
    s.hi = {1.1, 1.1, 1.1};
    s.h = 0.1;
    s.materials.resize(1);
    const pd::Particles p = pd::discretize(s);
    const auto influence = pd::abi::find_influence("const");
    ASSERT_NE(influence, nullptr);
    const pd::Bonds b = pd::find_bonds(p, 3 * s.h, influence->weight);
    int expected = 0;
    for (int a = -3; a <= 3; ++a)
      for (int c = -3; c <= 3; ++c)
        for (int e = (dim == 3 ? -3 : 0); e <= (dim == 3 ? 3 : 0); ++e)
          expected += (a * a + c * c + e * e <= 9) && (a || c || e);
    EXPECT_EQ(expected, dim == 2 ? 28 : 122);
    int centre = 0;  // the particle nearest the middle
    for (int i = 0; i < p.size(); ++i) {
      double r = 0, rc = 0;
      for (int c = 0; c < dim; ++c)
        r += std::pow(p.position(i)[c] - 0.55, 2), rc += std::pow(p.position(centre)[c] - 0.55, 2);
      if (r < rc) centre = i;
    }
    EXPECT_EQ(b.family_size(centre), expected) << dim << "D";
  }
}

TEST(Neighbours, IntegerHorizonRatiosKeepEveryLatticeNeighbour) {
  // delta = k h exactly: a pair at distance delta along an axis can fall two cells apart
  // when the cell size is exactly delta and the positions round the other way (0.35 and
  // 0.45 with h = 0.1 land in cells 2 and 4). Every particle must still see every
  // lattice offset with a^2 + b^2 <= k^2 that lies in the domain.
  pd::Scene s;
  s.dim = 2;
  s.lo = {0, 0, 0};
  s.hi = {1, 1, 0};
  s.h = 0.1;
  s.materials.resize(1);
  const pd::Particles p = pd::discretize(s);
  for (int k : {1, 2, 3}) {
    const pd::Bonds b = pd::find_bonds(p, k * s.h, weight);
    for (int i = 0; i < p.size(); ++i) {
      const int ix = static_cast<int>(std::lround(p.position(i)[0] / s.h - 0.5)),
                iy = static_cast<int>(std::lround(p.position(i)[1] / s.h - 0.5));
      int expected = 0;
      for (int a = -k; a <= k; ++a)
        for (int c = -k; c <= k; ++c)
          expected +=
              (a || c) && a * a + c * c <= k * k && ix + a >= 0 && ix + a < 10 && iy + c >= 0 && iy + c < 10;
      ASSERT_EQ(b.family_size(i), expected) << "delta = " << k << "h, particle " << i;
    }
  }
}

TEST(Neighbours, SingleParticleAndCollinearClouds) {
  pd::Particles one;
  one.dim = 2;
  one.x = {0.5, 0.5};
  one.volume = {1};
  one.material = {0};
  const pd::Bonds b1 = pd::find_bonds(one, 1.0, weight);
  EXPECT_EQ(b1.bond_count(), 0);
  EXPECT_EQ(b1.particle_count(), 1);
  pd::Particles line;
  line.dim = 3;
  for (int i = 0; i < 50; ++i) {
    line.x.insert(line.x.end(), {0.1 * i, 2.0, -1.0});
    line.volume.push_back(1);
    line.material.push_back(0);
  }
  check_against_brute_force(line, 0.25);
}

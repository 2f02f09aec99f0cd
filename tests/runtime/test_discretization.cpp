// Discretisation, neighbour search against brute force, crack cutting against geometry.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "discretize/discretization.hpp"

namespace {
pd::Scene box_scene(int dim, double h, double perturbation) {
  pd::Scene s;
  s.dim = dim;
  s.lo = {0, 0, 0};
  s.hi = {2, 1.5, 1};
  s.h = h;
  s.perturbation = perturbation;
  s.seed = 3;
  s.materials.resize(1);
  return s;
}
double unit(double, double) { return 1.0; }
}  // namespace

TEST(Discretization, CellCentredLatticeCountsAndVolumes) {
  const pd::Scene s = box_scene(2, 0.25, 0.0);
  const pd::Particles p = pd::discretize(s);
  EXPECT_EQ(p.size(), 8 * 6);
  double total = 0;
  for (double v : p.volume) total += v;
  EXPECT_NEAR(total, 2 * 1.5, 1e-12);
}

TEST(Discretization, HolesRemoveParticles) {
  pd::Scene s = box_scene(2, 0.05, 0.0);
  pd::Shape hole;
  hole.center = {1, 0.75, 0};
  hole.radius = 0.5;
  s.holes.push_back(hole);
  const pd::Particles p = pd::discretize(s);
  for (int i = 0; i < p.size(); ++i) EXPECT_GT(std::hypot(p.x[2 * i] - 1, p.x[2 * i + 1] - 0.75), 0.5);
  const double removed_area = (40 * 30 - p.size()) * 0.05 * 0.05;
  EXPECT_NEAR(removed_area, M_PI * 0.25, 0.02);
}

TEST(Discretization, NeighboursMatchBruteForce) {
  for (int dim : {2, 3}) {
    const pd::Scene s = box_scene(dim, 0.2, 0.3);
    const pd::Particles p = pd::discretize(s);
    const double delta = 3.1 * s.h;
    const pd::Bonds b = pd::find_bonds(p, delta, unit);
    long long count = 0;
    for (int i = 0; i < p.size(); ++i) {
      std::set<int> expected;
      for (int j = 0; j < p.size(); ++j) {
        if (j == i) continue;
        double r2 = 0;
        for (int c = 0; c < dim; ++c) r2 += std::pow(p.x[j * dim + c] - p.x[i * dim + c], 2);
        if (r2 <= delta * delta) expected.insert(j);
      }
      const std::set<int> got(b.neighbor.begin() + b.offsets[i], b.neighbor.begin() + b.offsets[i + 1]);
      EXPECT_EQ(got, expected) << "particle " << i << " dim " << dim;
      count += static_cast<long long>(expected.size());
    }
    EXPECT_EQ(count, b.bond_count());
  }
}

TEST(Discretization, CrackCutsExactlyTheBondsCrossingIt) {
  const pd::Scene s = box_scene(2, 0.1, 0.2);
  const pd::Particles p = pd::discretize(s);
  pd::Bonds b = pd::find_bonds(p, 0.3, unit);
  pd::Crack crack;
  crack.points = {pd::Point{0.5, 0.73, 0}, pd::Point{1.5, 0.77, 0}};
  const int broken = pd::cut_bonds({crack}, p, b);
  int expected = 0;
  for (int i = 0; i < p.size(); ++i)
    for (int e = b.offsets[i]; e < b.offsets[i + 1]; ++e) {
      const int j = b.neighbor[e];
      // Brute force: parametric intersection of the two segments.
      const double px = p.x[2 * i], py = p.x[2 * i + 1], qx = p.x[2 * j], qy = p.x[2 * j + 1];
      const double ax = 0.5, ay = 0.73, bx = 1.5, by = 0.77;
      const double den = (qx - px) * (by - ay) - (qy - py) * (bx - ax);
      bool cross = false;
      if (den != 0) {
        const double t = ((ax - px) * (by - ay) - (ay - py) * (bx - ax)) / den;
        const double u = ((ax - px) * (qy - py) - (ay - py) * (qx - px)) / den;
        cross = t > 0 && t < 1 && u > 0 && u < 1;
      }
      expected += cross;
      EXPECT_EQ(b.alpha[e] == 0.0, cross) << i << "-" << j;
    }
  EXPECT_EQ(broken, expected);
  EXPECT_GT(broken, 0);
}

TEST(Discretization, ThreeDimensionalPolygonCrack) {
  const pd::Scene s = box_scene(3, 0.1, 0.0);
  const pd::Particles p = pd::discretize(s);
  pd::Bonds b = pd::find_bonds(p, 0.15, unit);
  pd::Crack crack;  // the square x in [0.5, 1.5], y in [0.5, 1], in the plane z = 0.52
  crack.points = {pd::Point{0.5, 0.5, 0.52}, pd::Point{1.5, 0.5, 0.52}, pd::Point{1.5, 1.0, 0.52},
                  pd::Point{0.5, 1.0, 0.52}};
  pd::cut_bonds({crack}, p, b);
  for (int i = 0; i < p.size(); ++i)
    for (int e = b.offsets[i]; e < b.offsets[i + 1]; ++e) {
      const int j = b.neighbor[e];
      const double* a = p.position(i);
      const double* c = p.position(j);
      bool cross = false;
      if ((a[2] - 0.52) * (c[2] - 0.52) < 0) {
        const double t = (0.52 - a[2]) / (c[2] - a[2]);
        const double x = a[0] + t * (c[0] - a[0]), y = a[1] + t * (c[1] - a[1]);
        cross = x > 0.5 && x < 1.5 && y > 0.5 && y < 1.0;
      }
      EXPECT_EQ(b.alpha[e] == 0.0, cross);
    }
}

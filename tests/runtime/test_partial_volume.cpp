// Paper 002's bond volume factors as geometry: the closed-form 2D cell-disc area against
// an independent construction (the clipped polygon plus its circular segments) and a
// Monte Carlo estimate; the adaptive 3D cell-sphere volume against the exact sphere and
// against the 2D closed form integrated over the third axis; eq. (2.16)'s values.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "discretize/ai_volume.hpp"
#include "discretize/partial_volume.hpp"

namespace {
struct P2 {
  double x, y;
};

// Area of square [x0,x1]x[y0,y1] inside the disc |p| <= R by clipping: walk the square's
// boundary counter-clockwise keeping the parts inside the disc (corners inside, edge-circle
// crossings); the polygon of those points by the shoelace formula, plus a circular segment
// wherever the walk leaves the disc and re-enters it (there the true boundary is the arc).
double clipped_area(double x0, double y0, double x1, double y1, double R) {
  const P2 corners[4] = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
  struct Vertex {
    P2 p;
    bool leaves;  // the boundary leaves the disc after this point
  };
  std::vector<Vertex> v;
  auto inside = [&](P2 p) { return p.x * p.x + p.y * p.y <= R * R; };
  for (int e = 0; e < 4; ++e) {
    const P2 a = corners[e], b = corners[(e + 1) % 4];
    if (inside(a)) v.push_back({a, false});
    // Crossings of a + t (b - a) with the circle, t in (0, 1), in order.
    const double dx = b.x - a.x, dy = b.y - a.y;
    const double A = dx * dx + dy * dy, B = 2 * (a.x * dx + a.y * dy), C = a.x * a.x + a.y * a.y - R * R;
    const double disc = B * B - 4 * A * C;
    if (disc > 0) {
      const double s = std::sqrt(disc);
      for (double t : {(-B - s) / (2 * A), (-B + s) / (2 * A)})
        if (t > 0 && t < 1) {
          const P2 p{a.x + t * dx, a.y + t * dy};
          const P2 after{a.x + (t + 1e-9) * dx, a.y + (t + 1e-9) * dy};
          v.push_back({p, !inside(after)});
        }
    }
  }
  if (v.empty()) {
    // No corner inside and no crossing: the disc is inside the square, or they are apart.
    return (x0 <= -R && x1 >= R && y0 <= -R && y1 >= R) ? std::numbers::pi * R * R : 0.0;
  }
  double area = 0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const Vertex& a = v[i];
    const Vertex& b = v[(i + 1) % v.size()];
    area += 0.5 * (a.p.x * b.p.y - b.p.x * a.p.y);
    if (a.leaves) {
      double theta = std::atan2(b.p.y, b.p.x) - std::atan2(a.p.y, a.p.x);
      while (theta <= 0) theta += 2 * std::numbers::pi;
      area += 0.5 * R * R * (theta - std::sin(theta));
    }
  }
  return area;
}
}  // namespace

TEST(PartialVolume, CellDiscAreaEqualsClippedPolygonAndSegments) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const double R = 3.0;
  int partial = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    const double h = 0.3 + 1.7 * (0.5 + 0.5 * u(rng));
    const double cx = 4.0 * u(rng), cy = 4.0 * u(rng);
    const double expected = clipped_area(cx - h / 2, cy - h / 2, cx + h / 2, cy + h / 2, R);
    const double area = pd::cell_disc_area(cx, cy, R, h);
    ASSERT_NEAR(area, expected, 1e-10 * h * h) << "cell (" << cx << ", " << cy << ") side " << h;
    partial += expected > 1e-6 * h * h && expected < (1 - 1e-6) * h * h;
  }
  EXPECT_GT(partial, 500);  // the test is about cut cells, not only whole or empty ones
}

TEST(PartialVolume, CellDiscAreaOnLatticeCellsStraddlingTheAxes) {
  // Lattice cells at integer spacing, delta/h from 1 to 6 by halves: cuts exactly at
  // corners and cells centred on the axes (the cases a random draw never hits).
  for (int twice = 2; twice <= 12; ++twice) {
    const double R = 0.5 * twice;
    double total = 0;
    for (int i = -8; i <= 8; ++i)
      for (int j = -8; j <= 8; ++j) {
        const double a = pd::cell_disc_area(i, j, R, 1.0);
        ASSERT_NEAR(a, clipped_area(i - 0.5, j - 0.5, i + 0.5, j + 0.5, R), 1e-10)
            << i << " " << j << " R " << R;
        total += a;
      }
    EXPECT_NEAR(total, std::numbers::pi * R * R, 1e-9);  // the cells tile the plane
  }
}

TEST(PartialVolume, CellDiscAreaAgreesWithMonteCarlo) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-0.5, 0.5);
  const double R = 2.5, h = 1.0;
  const double centres[][2] = {{2.0, 1.0}, {0.0, 2.6}, {1.7, 1.7}, {-2.4, 0.4}};
  const int samples = 200000;
  for (const auto& c : centres) {
    int hits = 0;
    for (int s = 0; s < samples; ++s) {
      const double x = c[0] + u(rng) * h, y = c[1] + u(rng) * h;
      hits += x * x + y * y <= R * R;
    }
    const double fraction = static_cast<double>(hits) / samples;
    const double sigma = std::sqrt(fraction * (1 - fraction) / samples);
    EXPECT_GT(fraction, 0.02);
    EXPECT_LT(fraction, 0.98);
    EXPECT_NEAR(pd::cell_disc_area(c[0], c[1], R, h) / (h * h), fraction, 4 * sigma);
  }
}

TEST(PartialVolume, LinearFactorIsEquation216) {
  EXPECT_DOUBLE_EQ(pd::linear_volume_factor(2.4, 3.0, 1.0), 1.0);
  EXPECT_DOUBLE_EQ(pd::linear_volume_factor(2.5, 3.0, 1.0), 1.0);
  EXPECT_DOUBLE_EQ(pd::linear_volume_factor(3.0, 3.0, 1.0), 0.5);
  EXPECT_DOUBLE_EQ(pd::linear_volume_factor(3.25, 3.0, 1.0), 0.25);
  EXPECT_DOUBLE_EQ(pd::linear_volume_factor(3.5, 3.0, 1.0), 0.0);
  EXPECT_DOUBLE_EQ(pd::linear_volume_factor(4.0, 3.0, 1.0), 0.0);
}

TEST(AdaptiveIntegration, SphereVolumeFromItsCellsWithinTolerance) {
  // delta = 3 dx and 4.5 dx (the horizon through cell faces and through cell centres).
  for (double ratio : {3.0, 4.5}) {
    const int n = static_cast<int>(ratio) + 2;
    double total = 0;
    for (int i = -n; i <= n; ++i)
      for (int j = -n; j <= n; ++j)
        for (int k = -n; k <= n; ++k) {
          const double c[3] = {double(i), double(j), double(k)};
          total += pd::ai_cell_ball_volume(c, ratio, 1.0, pd::kAiEps).volume;
        }
    const double exact = 4.0 / 3.0 * std::numbers::pi * ratio * ratio * ratio;
    EXPECT_LT(std::abs(total - exact) / exact, pd::kAiTol) << "delta/dx = " << ratio;
  }
}

TEST(AdaptiveIntegration, CellVolumeEqualsTheIntegratedExactDiscArea) {
  // Independent value: the 2D closed-form area of the cross-section at height z,
  // integrated over z by composite Simpson with 20000 panels (the integrand is smooth
  // apart from square-root ends, which limits Simpson to ~1e-7 here).
  const double R = 3.0, h = 1.0;
  const double centres[][3] = {{0, 0, 3},       {1, 1, 2.5},     {2, 1, 2},
                               {1.5, 1.5, 1.5}, {0.7, 2.2, 1.3}, {0, 3, 1}};
  for (const auto& c : centres) {
    const int panels = 20000;
    const double z0 = c[2] - h / 2, dz = h / panels;
    auto section = [&](double z) {
      const double r2 = R * R - z * z;
      return r2 > 0 ? pd::cell_disc_area(c[0], c[1], std::sqrt(r2), h) : 0.0;
    };
    double simpson = section(z0) + section(z0 + h);
    for (int k = 1; k < panels; ++k) simpson += (k % 2 ? 4 : 2) * section(z0 + k * dz);
    simpson *= dz / 3;
    const pd::AiResult ai = pd::ai_cell_ball_volume(c, R, h, pd::kAiEps);
    EXPECT_GT(simpson, 1e-3);
    EXPECT_LT(simpson, 0.999);
    EXPECT_NEAR(ai.volume, simpson, 3 * pd::kAiEps * simpson + 1e-6) << c[0] << " " << c[1] << " " << c[2];
    EXPECT_GT(ai.points, 8);
  }
}

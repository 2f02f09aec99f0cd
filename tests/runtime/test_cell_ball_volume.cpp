// The closed-form 3D cell-ball volume (the `partial_exact` factor): partition of unity over
// lattices, half and quarter balls, the degenerate cells, symmetry, and two independent
// evaluations -- the exact 2D cell-disc area integrated over z by tanh-sinh quadrature
// (to rounding), and paper 002's adaptive integration (to its tolerance).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>
#include <vector>

#include "discretize/ai_volume.hpp"
#include "discretize/cell_ball_volume.hpp"
#include "discretize/partial_volume.hpp"

namespace {
double ball(double R) { return 4.0 / 3.0 * std::numbers::pi * R * R * R; }

// Sum of f(centre) over the cells of side h centred at offset + h (i, j, k), over a block
// that covers the ball of radius R about the origin.
template <class F>
double lattice_sum(double R, double h, const double* offset, F f) {
  const int n = static_cast<int>(std::ceil(R / h)) + 2;
  double total = 0;
  for (int i = -n; i <= n; ++i)
    for (int j = -n; j <= n; ++j)
      for (int k = -n; k <= n; ++k) {
        const double c[3] = {offset[0] + h * i, offset[1] + h * j, offset[2] + h * k};
        total += f(c);
      }
  return total;
}

// Ball centred on a cell centre (a particle), on a cell corner, and at a generic point.
const double kOffsets[][3] = {{0, 0, 0}, {0.5, 0.5, 0.5}, {0.1234, 0.377, 0.6021}};

// tanh-sinh rule on [a, b]: double-exponential convergence for an integrand analytic inside
// the interval, whatever its square-root behaviour at the ends.
template <class F>
double tanh_sinh(F f, double a, double b) {
  const double m = 0.5 * (a + b), w = 0.5 * (b - a), step = 1.0 / 32, half_pi = 0.5 * std::numbers::pi;
  double sum = 0;
  for (int k = -112; k <= 112; ++k) {
    const double t = k * step, u = half_pi * std::sinh(t);
    const double weight = half_pi * std::cosh(t) / (std::cosh(u) * std::cosh(u));
    sum += weight * f(m + w * std::tanh(u));
  }
  return sum * step * w;
}

// Independent value: the cube's cross-section at height z is its h x h square against the
// disc of radius sqrt(R^2 - z^2), whose area cell_disc_area gives exactly. That area is
// analytic in z except where the disc's circle meets an edge line or a corner of the square,
// so z is split there and each piece integrated by tanh-sinh.
double sliced_volume(const double* c, double R, double h) {
  const double a = std::max(c[2] - h / 2, -R), b = std::min(c[2] + h / 2, R);
  if (b <= a) return 0.0;
  std::vector<double> levels;  // squared distances in the xy-plane where the area kinks
  for (double x : {c[0] - h / 2, c[0] + h / 2}) {
    levels.push_back(x * x);
    for (double y : {c[1] - h / 2, c[1] + h / 2}) levels.push_back(x * x + y * y);
  }
  for (double y : {c[1] - h / 2, c[1] + h / 2}) levels.push_back(y * y);
  std::vector<double> cuts{a, b};
  for (double s : levels)
    if (s < R * R)
      for (double sign : {-1.0, 1.0}) {
        const double z = sign * std::sqrt(R * R - s);
        if (z > a && z < b) cuts.push_back(z);
      }
  std::sort(cuts.begin(), cuts.end());
  auto section = [&](double z) {
    return pd::cell_disc_area(c[0], c[1], std::sqrt(std::max(0.0, R * R - z * z)), h);
  };
  double sum = 0;
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i) sum += tanh_sinh(section, cuts[i], cuts[i + 1]);
  return sum;
}

// Random cells cut by the sphere (neither inside nor outside), with their side and radius.
struct CutCell {
  double c[3], R, h;
};
std::vector<CutCell> cut_cells(int count, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<CutCell> out;
  while (static_cast<int>(out.size()) < count) {
    CutCell cell{{0, 0, 0}, 1.0 + 2.0 * (0.5 + 0.5 * u(rng)), 0.4 + 0.8 * (0.5 + 0.5 * u(rng))};
    for (double& x : cell.c) x = (cell.R + cell.h) * u(rng);
    const double v = pd::cell_ball_volume(cell.c, cell.R, cell.h);
    if (v > 0 && v < cell.h * cell.h * cell.h) out.push_back(cell);
  }
  return out;
}
}  // namespace

TEST(CellBallVolume, CellsOfALatticeSumToTheBall) {
  // The adaptive integration at its runtime tolerance misses this by ~1e-5.
  for (double ratio : {1.3, 3.0, 3.7, 5.01})
    for (const auto& offset : kOffsets)
      for (double h : {1.0, 0.7}) {
        const double R = ratio * h, o[3] = {offset[0] * h, offset[1] * h, offset[2] * h};
        const double total =
            lattice_sum(R, h, o, [&](const double* c) { return pd::cell_ball_volume(c, R, h); });
        EXPECT_NEAR(total / ball(R), 1.0, 1e-12) << "R/h " << ratio << " offset " << offset[0] << " h " << h;
      }
}

TEST(CellBallVolume, PartialExactFactorsSumToTheBall) {
  // The same through the runtime's entry point: factor times cell volume, 3D.
  for (double ratio : {3.0, 3.7})
    for (const auto& o : kOffsets) {
      const double total = lattice_sum(ratio, 1.0, o, [&](const double* c) {
        return pd::volume_factor(pd::Quadrature::PartialExact, c, 3, ratio, 1.0);
      });
      EXPECT_NEAR(total / ball(ratio), 1.0, 1e-12) << "R/h " << ratio << " offset " << o[0];
    }
}

TEST(CellBallVolume, HalfAndQuarterBalls) {
  // The ball centred on a face plane x = 0 (and on an edge line x = y = 0): the cells on
  // one side carry exactly half (a quarter) of it. Corners then lie on the planes.
  for (double R : {1.3, 3.0, 3.7}) {
    const double face[3] = {0.5, 0.0, 0.3}, edge[3] = {0.5, 0.5, 0.3};
    const double half = lattice_sum(
        R, 1.0, face, [&](const double* c) { return c[0] > 0 ? pd::cell_ball_volume(c, R, 1.0) : 0.0; });
    const double quarter = lattice_sum(R, 1.0, edge, [&](const double* c) {
      return c[0] > 0 && c[1] > 0 ? pd::cell_ball_volume(c, R, 1.0) : 0.0;
    });
    EXPECT_NEAR(half / (ball(R) / 2), 1.0, 1e-12) << "R " << R;
    EXPECT_NEAR(quarter / (ball(R) / 4), 1.0, 1e-12) << "R " << R;
  }
}

TEST(CellBallVolume, DegenerateCells) {
  const double inside[3] = {0.6, -0.4, 1.1}, outside[3] = {3.0, 2.0, 0.0};
  EXPECT_EQ(pd::cell_ball_volume(inside, 2.5, 0.5), 0.125);
  EXPECT_EQ(pd::cell_ball_volume(outside, 2.5, 1.0), 0.0);
  // Touching from outside at a corner only: the nearest corner (1, 2, 2) is at distance 3.
  const double corner[3] = {1.5, 2.5, 2.5};
  EXPECT_EQ(pd::cell_ball_volume(corner, 3.0, 1.0), 0.0);
  // The ball inside one cell, also touching its faces.
  const double off[3] = {0.1, -0.05, 0.02}, centred[3] = {0, 0, 0};
  EXPECT_DOUBLE_EQ(pd::cell_ball_volume(off, 0.3, 1.0), ball(0.3));
  EXPECT_DOUBLE_EQ(pd::cell_ball_volume(centred, 0.5, 1.0), ball(0.5));
  // Poking out of one face: the ball minus the cap beyond x = -0.49. Every corner
  // coordinate is then on the negative side of some axis, the most reflected case.
  const double shifted[3] = {0.01, 0, 0}, d = 0.49, R = 0.5;
  const double cap = std::numbers::pi * (R - d) * (R - d) * (2 * R + d) / 3;
  EXPECT_NEAR(pd::cell_ball_volume(shifted, R, 1.0), ball(R) - cap, 1e-15);
  EXPECT_EQ(pd::cell_ball_volume(shifted, 0.0, 1.0), 0.0);
}

TEST(CellBallVolume, SymmetricUnderPermutationAndReflection) {
  for (const CutCell& cell : cut_cells(200, 3)) {
    const double v = pd::cell_ball_volume(cell.c, cell.R, cell.h);
    const double* c = cell.c;
    const double permuted[][3] = {{c[1], c[2], c[0]}, {c[2], c[0], c[1]}, {c[1], c[0], c[2]}};
    const double reflected[][3] = {{-c[0], c[1], c[2]}, {c[0], -c[1], -c[2]}, {-c[2], c[0], -c[1]}};
    for (const auto& p : permuted) EXPECT_NEAR(pd::cell_ball_volume(p, cell.R, cell.h), v, 1e-14);
    for (const auto& p : reflected) EXPECT_NEAR(pd::cell_ball_volume(p, cell.R, cell.h), v, 1e-14);
  }
}

TEST(CellBallVolume, EqualsTheExactDiscAreaIntegratedOverZ) {
  for (const CutCell& cell : cut_cells(300, 7)) {
    const double cube = cell.h * cell.h * cell.h;
    EXPECT_NEAR(pd::cell_ball_volume(cell.c, cell.R, cell.h), sliced_volume(cell.c, cell.R, cell.h),
                2e-13 * cube)
        << cell.c[0] << " " << cell.c[1] << " " << cell.c[2] << " R " << cell.R << " h " << cell.h;
  }
}

TEST(CellBallVolume, AgreesWithTheAdaptiveIntegrationToItsTolerance) {
  // Paper 002's AI does not reach 1e-7 within its 12 refinements on most cells, and now and
  // then not 1e-5 (it throws): it is compared at 1e-5, skipping the cells it gives up on.
  const double eps = 1e-5;
  int compared = 0;
  for (const CutCell& cell : cut_cells(300, 11)) {
    const double cube = cell.h * cell.h * cell.h;
    double ai = 0;
    try {
      ai = pd::ai_cell_ball_volume(cell.c, cell.R, cell.h, eps).volume;
    } catch (const std::runtime_error&) {
      continue;
    }
    ++compared;
    EXPECT_NEAR(pd::cell_ball_volume(cell.c, cell.R, cell.h), ai, 2 * eps * cube);
  }
  EXPECT_GT(compared, 290);
}

// Paper 002 §2.5.1, Tables 2.2 and 2.3: the volume of the horizon sphere (delta = 18h)
// on a uniform grid, dx = delta/m, by
//  - AI: every cell meeting the sphere integrated by ai_cell_ball_volume (TOL = 1e-4,
//    EPS from the command line, 1e-4 by default), points = the sum of each cell's
//    accepted integration points;
//  - CCI, the paper's "cubic-cell integration": the nodes with |xi| <= delta (the source
//    included) with the linear factor of eq. (2.16); one point per node.
// The paper's CCI is reproduced to one unit of its last printed digit by this reading (the factor is
// applied only to nodes within delta, so the outer half of the linear ramp is missing:
// the O(dx) bias that dominates its error).
//
// Usage: paper002_sphere_volume [EPS [largest m for AI]]
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <vector>

#include "discretize/ai_volume.hpp"
#include "discretize/partial_volume.hpp"

namespace {
constexpr double kDeltaH = 18.0;  // the paper's horizon in its length unit h

struct Result {
  double error_percent = 0, runtime_ms = 0, adip_h = 0;
  long points = 0;
};

double exact_volume(int m) { return 4.0 / 3.0 * std::numbers::pi * m * m * m; }  // in cells (dx = 1)

template <class F>
double time_ms(F f) {
  const auto t0 = std::chrono::steady_clock::now();
  f();
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

Result adaptive(int m, double eps) {
  double volume = 0;
  long points = 0;
  Result r;
  r.runtime_ms = time_ms([&] {
    for (int i = -m - 1; i <= m + 1; ++i)
      for (int j = -m - 1; j <= m + 1; ++j)
        for (int k = -m - 1; k <= m + 1; ++k) {
          const double c[3] = {double(i), double(j), double(k)};
          const pd::AiResult a = pd::ai_cell_ball_volume(c, m, 1.0, eps);
          volume += a.volume, points += a.points;
        }
  });
  r.points = points;
  r.error_percent = 100 * std::fabs(volume - exact_volume(m)) / exact_volume(m);
  r.adip_h = std::cbrt(exact_volume(m) / points) * kDeltaH / m;
  return r;
}

Result cubic_cell(int m) {
  double volume = 0;
  long points = 0;
  Result r;
  r.runtime_ms = time_ms([&] {
    for (int i = -m; i <= m; ++i)
      for (int j = -m; j <= m; ++j)
        for (int k = -m; k <= m; ++k) {
          const double len = std::sqrt(double(i * i + j * j + k * k));
          if (len > m * (1 + 1e-12)) continue;
          volume += pd::linear_volume_factor(len, m, 1.0);
          ++points;
        }
  });
  r.points = points;
  r.error_percent = 100 * std::fabs(volume - exact_volume(m)) / exact_volume(m);
  r.adip_h = std::cbrt(exact_volume(m) / points) * kDeltaH / m;
  return r;
}

// Least-squares slope of log(error) against log(x).
double slope(const std::vector<double>& x, const std::vector<double>& e) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  const double n = static_cast<double>(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double a = std::log(x[i]), b = std::log(e[i]);
    sx += a, sy += b, sxx += a * a, sxy += a * b;
  }
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}
}  // namespace

int main(int argc, char** argv) {
  const double eps = argc > 1 ? std::atof(argv[1]) : pd::kAiEps;
  const int ai_up_to = argc > 2 ? std::atoi(argv[2]) : 30;
  const int ms[] = {3, 4, 5, 6, 8, 9, 10, 15, 20, 30};
  // Table 2.3's CCI grids (the paper's pick of the closest ADIP) and the paper's numbers.
  const int cci_ms[] = {11, 13, 15, 16, 20, 22, 24, 33, 44, 63};
  const double paper_ai[] = {0.050, 0.029, 0.025, 0.017, 0.011, 0.009, 0.007, 0.003, 0.002, 0.001};
  const double paper_cci[] = {7.992, 10.525, 7.966, 4.891, 5.367, 3.773, 3.862, 2.415, 2.028, 1.251};
  const double paper_cci23[] = {3.317, 3.056, 2.415, 2.531, 2.028, 1.833, 1.635, 1.120, 0.873, 0.595};
  const double paper_adip_ai[] = {1.708, 1.457, 1.239, 1.121, 0.887, 0.817, 0.755, 0.535, 0.415, 0.286};
  std::printf("EPS = %g, TOL = %g\n\n", eps, pd::kAiTol);
  std::printf(
      "Table 2.2 (same dx)\n\n| dx | AI err %% | paper | AI ms | AI points | CCI err %% | paper | CCI ms "
      "|\n|---|---|---|---|---|---|---|---|\n");
  std::vector<Result> ai, cci, cci23;
  std::vector<double> dx;
  for (int i = 0; i < 10; ++i) {
    ai.push_back(ms[i] <= ai_up_to ? adaptive(ms[i], eps) : Result{1e9, 0, 0, 0});
    cci.push_back(cubic_cell(ms[i]));
    dx.push_back(kDeltaH / ms[i]);
    std::printf("| δ/%d | %.4f | %.3f | %.0f | %ld | %.3f | %.3f | %.1f |\n", ms[i], ai.back().error_percent,
                paper_ai[i], ai.back().runtime_ms, ai.back().points, cci.back().error_percent, paper_cci[i],
                cci.back().runtime_ms);
    std::fflush(stdout);
  }
  std::printf(
      "\nTable 2.3 (closest ADIP)\n\n| AI ADIP [h] | paper | dx | AI err %% | CCI ADIP [h] | dx | CCI err %% "
      "| paper | CCI ms |\n|---|---|---|---|---|---|---|---|---|\n");
  for (int i = 0; i < 10; ++i) {
    cci23.push_back(cubic_cell(cci_ms[i]));
    std::printf("| %.3f | %.3f | δ/%d | %.4f | %.3f | δ/%d | %.3f | %.3f | %.1f |\n", ai[i].adip_h,
                paper_adip_ai[i], ms[i], ai[i].error_percent, cci23.back().adip_h, cci_ms[i],
                cci23.back().error_percent, paper_cci23[i], cci23.back().runtime_ms);
  }
  std::vector<double> ea, ec, aa, ac, e23;
  for (int i = 0; i < 10; ++i)
    ea.push_back(ai[i].error_percent), ec.push_back(cci[i].error_percent), aa.push_back(ai[i].adip_h),
        ac.push_back(cci23[i].adip_h), e23.push_back(cci23[i].error_percent);
  std::printf(
      "\nRates (least-squares slope of log error): AI vs dx %.2f (paper 1.72), AI vs ADIP %.2f (paper 2.20), "
      "CCI vs dx %.2f, CCI vs ADIP %.2f\n",
      slope(dx, ea), slope(aa, ea), slope(dx, ec), slope(ac, e23));
  return 0;
}

// Adaptive nested trapezoid integration of cell-sphere intersection volumes.
#include "discretize/ai_volume.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace pd {

namespace {
constexpr int kMaxIndex = 12;  // M = 2048 subintervals; reached only if EPS is far too tight

struct Box {
  double lo[3], hi[3];
};

// The cut levels of one direction: its two faces, and the axis when the cell straddles it
// (the sphere's extent in the other directions is largest there, a kink of the limits).
std::vector<double> levels(const Box& b, int axis) {
  std::vector<double> out{b.lo[axis], b.hi[axis]};
  if (b.lo[axis] < 0 && b.hi[axis] > 0) out.push_back(0.0);
  return out;
}

// The interval [a, b] cut at +-sqrt(s) for every s in squares (s > 0).
std::vector<double> cut(double a, double b, const std::vector<double>& squares) {
  std::vector<double> out{a, b};
  for (double s : squares)
    if (s > 0)
      for (double sign : {-1.0, 1.0}) {
        const double x = sign * std::sqrt(s);
        if (x > a && x < b) out.push_back(x);
      }
  std::sort(out.begin(), out.end());
  return out;
}

class Integrator {
 public:
  Integrator(const Box& box, double R, int M) : b_(box), R2_(R * R), M_(M) {
    for (double y : levels(b_, 1))
      for (double z : levels(b_, 2)) x_squares_.push_back(R2_ - y * y - z * z);
    for (double z : levels(b_, 2)) z_levels_sq_.push_back(z * z);
  }
  double volume(long& points) {
    const double a = std::max(b_.lo[0], -std::sqrt(R2_)), c = std::min(b_.hi[0], std::sqrt(R2_));
    double sum = 0;
    const std::vector<double> xs = cut(a, c, x_squares_);
    for (std::size_t i = 0; i + 1 < xs.size(); ++i)
      sum += trapezoid(xs[i], xs[i + 1], points, [&](double x, long& pts) { return area(x, pts); });
    return sum;
  }

 private:
  template <class F>
  double trapezoid(double a, double b, long& points, F f) const {
    if (b <= a) return 0.0;
    const double step = (b - a) / M_;
    double s = 0.5 * (f(a, points) + f(b, points));
    for (int k = 1; k < M_; ++k) s += f(a + k * step, points);
    return s * step;
  }
  // G(X): the cross-section at X, integrated over Y between its cuts.
  double area(double x, long& points) const {
    const double rho2 = std::max(0.0, R2_ - x * x), rho = std::sqrt(rho2);
    const double a = std::max(b_.lo[1], -rho), c = std::min(b_.hi[1], rho);
    std::vector<double> squares;
    for (double z2 : z_levels_sq_) squares.push_back(rho2 - z2);
    const std::vector<double> ys = cut(a, c, squares);
    double sum = 0;
    for (std::size_t i = 0; i + 1 < ys.size(); ++i)
      sum += trapezoid(ys[i], ys[i + 1], points, [&](double y, long& pts) { return length(x, y, pts); });
    return sum;
  }
  // H(X, Y): the Z extent. The integrand is 1, on which the trapezoid rule is exact, so
  // the extent is taken directly; its M + 1 points still count (the paper's TNIP, eq. 2.52).
  double length(double x, double y, long& points) const {
    const double s = std::sqrt(std::max(0.0, R2_ - x * x - y * y));
    const double a = std::max(b_.lo[2], -s), c = std::min(b_.hi[2], s);
    points += M_ + 1;
    return std::max(0.0, c - a);
  }

  Box b_;
  double R2_;
  int M_;
  std::vector<double> x_squares_, z_levels_sq_;
};
}  // namespace

AiResult ai_cell_ball_volume(const double* c, double delta, double h, double eps) {
  Box box{};
  double near2 = 0, far2 = 0;
  for (int i = 0; i < 3; ++i) {
    box.lo[i] = c[i] - 0.5 * h, box.hi[i] = c[i] + 0.5 * h;
    const double gap = std::max(0.0, std::fabs(c[i]) - 0.5 * h), reach = std::fabs(c[i]) + 0.5 * h;
    near2 += gap * gap, far2 += reach * reach;
  }
  const double cell = h * h * h;
  if (near2 >= delta * delta) return {0.0, 0, 0};
  if (far2 <= delta * delta) return {cell, 8, 1};
  long points = 0;
  double previous = Integrator(box, delta, 1).volume(points) / cell;
  for (int n = 2; n <= kMaxIndex; ++n) {
    points = 0;
    const double current = Integrator(box, delta, 1 << (n - 1)).volume(points) / cell;
    const double change = std::fabs(current - previous);
    const bool done = std::fabs(previous) > kAiTol ? change <= eps * std::fabs(previous) : change <= eps;
    if (done) return {current * cell, points, n};
    previous = current;
  }
  throw std::runtime_error("adaptive integration: no convergence at trapezoidal index 12 (EPS too small?)");
}

}  // namespace pd

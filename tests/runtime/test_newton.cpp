// Newton's method: one step for a linear problem, quadratic convergence for a
// nonlinear one, constraints honoured, failure reported.
#include <gtest/gtest.h>

#include <cmath>

#include "solvers/newton.hpp"

namespace {
// r(u) = b * load - (A u + c (u^3)): A tridiagonal SPD, c >= 0 adds a cubic term.
pd::NonlinearProblem chain(int n, double c) {
  pd::NonlinearProblem pb;
  pb.size = n;
  auto r = [n, c](const std::vector<double>& u, double load, std::vector<double>& out) {
    out.assign(static_cast<std::size_t>(n), 0.0);
    for (int i = 0; i < n; ++i) {
      double Au = 2 * u[i];
      if (i > 0) Au -= u[i - 1];
      if (i + 1 < n) Au -= u[i + 1];
      out[i] = load * 1.0 - Au - c * u[i] * u[i] * u[i];
    }
  };
  pb.residual = r;
  pb.stiffness = [n, c, r](const std::vector<double>& u, double load, pd::SparseMatrix& K, std::vector<double>& out) {
    r(u, load, out);
    std::vector<Eigen::Triplet<double>> t;
    for (int i = 0; i < n; ++i) {
      t.emplace_back(i, i, 2 + 3 * c * u[i] * u[i]);
      if (i > 0) t.emplace_back(i, i - 1, -1.0);
      if (i + 1 < n) t.emplace_back(i, i + 1, -1.0);
    }
    K.resize(n, n);
    K.setFromTriplets(t.begin(), t.end());
  };
  return pb;
}
}  // namespace

TEST(Newton, LinearProblemConvergesInOneStep) {
  std::vector<double> u(50, 0.0);
  pd::Constraints cons{{0}, {0.5}};
  pd::NewtonOptions opt;
  opt.increment_tolerance = 0;  // judge by the residual alone
  const auto rep = pd::solve_newton(chain(50, 0.0), cons, u, opt, [](const std::string&) {});
  ASSERT_TRUE(rep.converged) << rep.failure;
  EXPECT_EQ(rep.history.size(), 2u);  // iteration 0 and the converged iteration 1
  EXPECT_DOUBLE_EQ(u[0], 0.5);
}

TEST(Newton, NonlinearProblemConvergesQuadratically) {
  std::vector<double> u(40, 0.0);
  pd::NewtonOptions opt;
  opt.load_steps = 2;
  opt.tolerance = 1e-13;
  opt.increment_tolerance = 0;
  const auto rep = pd::solve_newton(chain(40, 5.0), pd::Constraints{{0, 39}, {0, 0}}, u, opt, [](const std::string&) {});
  ASSERT_TRUE(rep.converged) << rep.failure;
  // In the last step, each residual is bounded by a constant times the square of the previous one.
  std::vector<double> last;
  for (const auto& h : rep.history)
    if (h.step == 2) last.push_back(h.residual);
  ASSERT_GE(last.size(), 4u);
  int quadratic = 0;
  for (std::size_t k = 1; k + 1 < last.size(); ++k)
    if (last[k] < 1e-2 && last[k + 1] > 1e-14) quadratic += last[k + 1] <= 10 * last[k] * last[k];
  EXPECT_GE(quadratic, 1);
  for (std::size_t k = 1; k < last.size(); ++k) EXPECT_LT(last[k], last[k - 1]);
}

TEST(Newton, ReportsNonConvergence) {
  std::vector<double> u(10, 0.0);
  pd::NewtonOptions opt;
  opt.max_iterations = 1;
  opt.tolerance = 1e-30;
  opt.increment_tolerance = 0;
  const auto rep = pd::solve_newton(chain(10, 50.0), pd::Constraints{{0}, {0}}, u, opt, [](const std::string&) {});
  EXPECT_FALSE(rep.converged);
  EXPECT_NE(rep.failure.find("did not converge"), std::string::npos);
}

// Progress inside one Newton step (solve/progress.hpp): a Krylov solve that outlasts the
// progress interval writes lines with its iteration and residual while it runs; a phase
// shorter than the interval writes nothing. The operator below blocks until the first
// progress line has arrived (or 20 s pass), so the test does not depend on timing: before
// the watchdog existed, no line ever arrived and the solve stalled to the timeout.
#include <gtest/gtest.h>

#include <chrono>
#include <condition_variable>
#include <mutex>
#include <string>
#include <vector>

#include "solve/matrix_free_krylov.hpp"
#include "solve/progress.hpp"

namespace {
struct Lines {
  std::mutex m;
  std::condition_variable cv;
  std::vector<std::string> lines;
  void add(const std::string& s) {
    {
      std::lock_guard lock(m);
      lines.push_back(s);
    }
    cv.notify_all();
  }
  bool wait_for_first(std::chrono::seconds limit) {
    std::unique_lock lock(m);
    return cv.wait_for(lock, limit, [&] { return !lines.empty(); });
  }
};
}  // namespace

TEST(Progress, ALongKrylovSolveLogsItsIterationAndResidualWhileItRuns) {
  Lines out;
  const pd::ProgressSink sink([&](const std::string& s) { out.add(s); }, 0.05);
  const int n = 20;
  int calls = 0;
  bool arrived = false;
  // A tridiagonal SPD operator (2, -1): CG needs about n iterations.
  const pd::LinearOperator A = [&](const Eigen::VectorXd& x, Eigen::VectorXd& y) {
    y = 2 * x;
    y.head(n - 1) -= x.tail(n - 1);
    y.tail(n - 1) -= x.head(n - 1);
  };
  const pd::LinearOperator M = [&](const Eigen::VectorXd& r, Eigen::VectorXd& z) {
    if (++calls == 3)
      arrived = out.wait_for_first(std::chrono::seconds(20));  // hold the solve until the watchdog has spoken
    z = r;
  };
  Eigen::VectorXd x, b = Eigen::VectorXd::Ones(n);
  const pd::KrylovResult r = pd::preconditioned_cg(A, M, b, x, 1e-12, 100);
  EXPECT_TRUE(r.converged);
  ASSERT_TRUE(arrived) << "no progress line within 20 s";
  std::lock_guard lock(out.m);
  ASSERT_GE(out.lines.size(), 2u);
  EXPECT_NE(out.lines.front().find("    matrix-free CG of 20 unknowns: "), std::string::npos)
      << out.lines.front();
  bool iteration_shown = false;  // the first line may come before the first iteration was counted
  for (const std::string& line : out.lines)
    iteration_shown = iteration_shown || (line.find(" s so far, iteration ") != std::string::npos &&
                                          line.find(", |r|/|b| = ") != std::string::npos);
  EXPECT_TRUE(iteration_shown) << out.lines.front();
  EXPECT_NE(out.lines.back().find("    matrix-free CG of 20 unknowns: done in "), std::string::npos)
      << out.lines.back();
}

TEST(Progress, AShortPhaseOrNoSinkWritesNothing) {
  Lines out;
  {
    const pd::ProgressSink sink([&](const std::string& s) { out.add(s); }, 60.0);
    const pd::ProgressPhase phase("a short phase");
    pd::progress_iteration(1, 0.5);
  }
  const pd::ProgressPhase without_sink("nobody listens");
  EXPECT_TRUE(out.lines.empty());
}

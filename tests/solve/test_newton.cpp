// Newton: one step on a linear problem, quadratic convergence on a nonlinear one, load
// stepping, the matrix-free Newton-Krylov variant, the non-symmetric path, and the
// failure message.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <cstdlib>

#include "solve/newton.hpp"
#include "support_spring_grid_problem.hpp"

namespace {
// Pulls the right edge by force: the tip moves by about 40% of the length, clearly
// nonlinear, yet Newton converges from zero without load steps.
pd::test::GridProblem nonlinear_problem() {
  const double load = std::getenv("PD_TEST_LOAD") ? std::atof(std::getenv("PD_TEST_LOAD")) : 0.01;
  return {pd::test::state_law_2d(), {5.0e2, 3.0e2}, 8, 6, 0.0, load};
}

// The same system declared non-symmetric: exercises UMFPACK and GMRES.
struct NonSymmetric final : pd::NonlinearSystem {
  pd::NonlinearSystem& s;
  explicit NonSymmetric(pd::NonlinearSystem& inner) : s(inner) {}
  int size() const override { return s.size(); }
  void residual(const Eigen::VectorXd& u, double l, Eigen::VectorXd& r) override { s.residual(u, l, r); }
  void tangent(const Eigen::VectorXd& u, double l, pd::SparseMatrix& K, Eigen::VectorXd* r) override {
    s.tangent(u, l, K, r);
  }
  bool symmetric() const override { return false; }
  bool has_jvp() const override { return true; }
  void jvp(const Eigen::VectorXd& u, double l, const Eigen::VectorXd& v, Eigen::VectorXd& Kv) override {
    s.jvp(u, l, v, Kv);
  }
  void diagonal(const Eigen::VectorXd& u, double l, Eigen::VectorXd& d) override { s.diagonal(u, l, d); }
};

pd::NewtonResult run(pd::NonlinearSystem& sys, const pd::DofMap& dofs, Eigen::VectorXd& u,
                     pd::NewtonSettings st, std::vector<std::string>* log = nullptr) {
  u = Eigen::VectorXd::Zero(sys.size());
  pd::NewtonSolver solver(st, [&](const std::string& m) {
    if (log) log->push_back(m);
    if (std::getenv("PD_TEST_VERBOSE")) std::printf("%s\n", m.c_str());
  });
  return solver.solve(sys, dofs, u);
}
}  // namespace

TEST(Newton, LinearProblemConvergesInOneStep) {
  pd::test::GridProblem pb(pd::test::linear_spring_2d(), {1.0e3}, 9, 7, 0.01, 0.0);
  auto sys = pb.system();
  Eigen::VectorXd u;
  std::vector<std::string> log;
  const pd::NewtonResult r = run(sys, pb.dofs, u, {}, &log);
  ASSERT_TRUE(r.converged) << r.message;
  EXPECT_EQ(r.iterations(), 1);
  EXPECT_EQ(r.linear_solver, "cholmod");
  EXPECT_EQ(log.size(), 4u);  // the solver choice, two iterations and the step's convergence line
  EXPECT_NE(log.back().find("converged in 1 iterations; residual ratios"), std::string::npos) << log.back();
  EXPECT_LT(r.history[1].residual, 1e-10 * r.history[0].residual);
  // The pulled edge moved by the prescribed amount, the interior in between.
  for (int p = 0; p < pb.body.particles.size(); ++p) {
    if (p % 9 == 8) {
      EXPECT_DOUBLE_EQ(u[2 * p], 0.01);
    }
    if (p % 9 == 4) {
      EXPECT_GT(u[2 * p], 0.002);
    }
  }
}

TEST(Newton, NonlinearProblemConvergesQuadratically) {
  auto pb = nonlinear_problem();
  auto sys = pb.system();
  Eigen::VectorXd u;
  const pd::NewtonResult r = run(sys, pb.dofs, u, {});
  ASSERT_TRUE(r.converged) << r.message;
  const auto& h = r.history;
  std::printf("max |u| = %g\n", u.cwiseAbs().maxCoeff());
  for (const auto& rec : h)
    std::printf("  it %d  |r| = %.3e  step %.3g\n", rec.iteration, rec.residual, rec.step_length);
  ASSERT_GE(r.iterations(), 3) << "the problem should be nonlinear";
  EXPECT_LE(r.iterations(), 8);
  // Quadratic: once the step is full, r_{k+1} <= C r_k^2 / r_0 with a modest C, down to rounding.
  int checked = 0;
  for (std::size_t k = 1; k + 1 < h.size(); ++k) {
    if (h[k + 1].step_length != 1.0 || h[k + 1].residual < 1e-12 * h[0].residual) continue;
    const double e0 = h[k].residual / h[0].residual, e1 = h[k + 1].residual / h[0].residual;
    EXPECT_LT(e1, 50 * e0 * e0) << "iteration " << k + 1;
    ++checked;
  }
  EXPECT_GE(checked, 1);
  // The external load is balanced: the clamped edge carries the reaction, the rest is in equilibrium.
  Eigen::VectorXd res;
  sys.residual(u, 1.0, res);
  EXPECT_LT(pb.dofs.restrict_free(res).norm(), 1e-9 * pb.external.norm());
}

TEST(Newton, LoadSteppingReachesTheSameSolution) {
  auto pb = nonlinear_problem();
  auto sys = pb.system();
  Eigen::VectorXd u1, u3;
  ASSERT_TRUE(run(sys, pb.dofs, u1, {}).converged);
  pd::NewtonSettings st;
  st.load_steps = 3;
  const pd::NewtonResult r = run(sys, pb.dofs, u3, st);
  ASSERT_TRUE(r.converged) << r.message;
  EXPECT_EQ(r.history.back().step, 3);
  EXPECT_LT((u1 - u3).norm(), 1e-9 * u1.norm());
}

// A load step too large for the iterations allowed is cut in halves from its converged
// start; the cut path reaches the answer of the uncut solve (the problem is elastic, so
// path-independent), and without cuts the same settings fail.
TEST(Newton, AFailedLoadStepIsCutAndReachesTheSameSolution) {
  auto pb = nonlinear_problem();
  auto sys = pb.system();
  Eigen::VectorXd reference, u;
  const pd::NewtonResult full = run(sys, pb.dofs, reference, {});
  ASSERT_TRUE(full.converged);
  // One iteration fewer than the whole step needs: the whole step must fail, and
  // smaller steps, being closer to linear, must get there within that budget.
  const int needed = static_cast<int>(full.history.size()) - 1;
  ASSERT_GE(needed, 2) << "the test needs a step that takes more than one iteration";
  pd::NewtonSettings st;
  st.max_iterations = needed - 1;
  const pd::NewtonResult uncut = run(sys, pb.dofs, u, st);
  ASSERT_FALSE(uncut.converged);
  EXPECT_EQ(uncut.step_cuts, 0);
  st.max_step_cuts = 6;
  std::vector<std::string> log;
  const pd::NewtonResult cut = run(sys, pb.dofs, u, st, &log);
  ASSERT_TRUE(cut.converged) << cut.message;
  EXPECT_TRUE(cut.message.empty()) << cut.message;
  EXPECT_GT(cut.step_cuts, 0);
  EXPECT_LT((u - reference).norm(), 1e-9 * reference.norm());
  int cut_lines = 0;
  for (const std::string& line : log) cut_lines += line.find("cutting load step 1/1") != std::string::npos;
  EXPECT_EQ(cut_lines, cut.step_cuts);
  // Every part that converged ended at a load of the bisection, the last at the full load.
  EXPECT_EQ(cut.history.back().load, 1.0);
}

// solver.duration: every increment is announced with its physical times before its
// iterations; the increments that stand tile [0, duration] in order, a cut step's halves
// each lasting half of what they split, and a hold (a flat load path) lasts as long as a ramp.
TEST(Newton, IncrementsTileThePhysicalTimeAndCutsHalveIt) {
  auto pb = nonlinear_problem();
  auto sys = pb.system();
  Eigen::VectorXd u;
  const pd::NewtonResult full = run(sys, pb.dofs, u, {});
  ASSERT_TRUE(full.converged);
  pd::NewtonSettings st;
  st.load_steps = 2;
  st.load_path = {0.0, 1.0, 1.0};  // a ramp, then a hold at the full load
  st.duration = 3.0;
  st.max_iterations = static_cast<int>(full.history.size()) - 2;  // the ramp must be cut
  st.max_step_cuts = 6;
  std::vector<std::pair<double, double>> announced, stood;
  std::vector<double> loads;
  st.begin_increment = [&](double t0, double t1) { announced.emplace_back(t0, t1); };
  st.after_step = [&](int, double load, const Eigen::VectorXd&) {
    stood.push_back(announced.back());
    loads.push_back(load);
    return 0LL;
  };
  const pd::NewtonResult r = run(sys, pb.dofs, u, st);
  ASSERT_TRUE(r.converged) << r.message;
  ASSERT_GT(r.step_cuts, 0);
  EXPECT_GT(announced.size(), stood.size()) << "the failed increments were announced too";
  ASSERT_GE(stood.size(), 3u);
  EXPECT_EQ(stood.front().first, 0.0);
  EXPECT_EQ(stood.back(), std::make_pair(1.5, 3.0)) << "the hold, uncut, lasts duration / load_steps";
  for (std::size_t k = 1; k < stood.size(); ++k) EXPECT_EQ(stood[k].first, stood[k - 1].second);
  // The ramp's parts: lengths 1.5 / 2^c; the load follows the path at each part's end.
  for (std::size_t k = 0; k + 1 < stood.size(); ++k) {
    const double parts = 1.5 / (stood[k].second - stood[k].first);
    EXPECT_EQ(parts, std::exp2(std::round(std::log2(parts)))) << k;
    EXPECT_DOUBLE_EQ(loads[k], stood[k].second / 1.5);
  }
  EXPECT_EQ(loads.back(), 1.0);
}

TEST(Newton, CutsThatRunOutNameTheLimit) {
  auto pb = nonlinear_problem();
  auto sys = pb.system();
  Eigen::VectorXd u;
  pd::NewtonSettings st;
  st.max_iterations = 1;
  st.max_step_cuts = 1;
  const pd::NewtonResult r = run(sys, pb.dofs, u, st);
  ASSERT_FALSE(r.converged);
  EXPECT_GT(r.step_cuts, 0);
  EXPECT_NE(r.message.find("solver.max_step_cuts"), std::string::npos) << r.message;
}

TEST(Newton, MatrixFreeNewtonKrylovMatchesAssembledNewton) {
  auto pb = nonlinear_problem();
  auto sys = pb.system();
  Eigen::VectorXd u_direct, u_mf;
  ASSERT_TRUE(run(sys, pb.dofs, u_direct, {}).converged);
  pd::NewtonSettings st;
  st.matrix_free = true;
  st.krylov_tolerance = 1e-10;
  const pd::NewtonResult r = run(sys, pb.dofs, u_mf, st);
  ASSERT_TRUE(r.converged) << r.message;
  EXPECT_EQ(r.linear_solver, "matrix-free cg+jacobi");
  EXPECT_GT(r.history[1].linear_iterations, 0);
  EXPECT_LT((u_direct - u_mf).norm(), 1e-8 * u_direct.norm());
}

namespace {
// The same system offering its own exact tangent as the "approximate" one: a perfect
// preconditioner, so every Krylov solve must finish in one or two iterations.
struct ExactApproximation final : pd::NonlinearSystem {
  pd::NonlinearSystem& s;
  explicit ExactApproximation(pd::NonlinearSystem& inner) : s(inner) {}
  int size() const override { return s.size(); }
  void residual(const Eigen::VectorXd& u, double l, Eigen::VectorXd& r) override { s.residual(u, l, r); }
  void tangent(const Eigen::VectorXd& u, double l, pd::SparseMatrix& K, Eigen::VectorXd* r) override {
    s.tangent(u, l, K, r);
  }
  bool has_jvp() const override { return true; }
  void jvp(const Eigen::VectorXd& u, double l, const Eigen::VectorXd& v, Eigen::VectorXd& Kv) override {
    s.jvp(u, l, v, Kv);
  }
  void diagonal(const Eigen::VectorXd& u, double l, Eigen::VectorXd& d) override { s.diagonal(u, l, d); }
  bool has_approximate_tangent() const override { return true; }
  void approximate_tangent(const Eigen::VectorXd& u, double l, pd::SparseMatrix& P) override {
    s.tangent(u, l, P, nullptr);
  }
};
}  // namespace

TEST(Newton, MatrixFreeWithAnApproximateTangentUsesItsFactorisation) {
  auto pb = nonlinear_problem();
  auto inner = pb.system();
  ExactApproximation sys(inner);
  Eigen::VectorXd u_direct, u_mf;
  ASSERT_TRUE(run(inner, pb.dofs, u_direct, {}).converged);
  pd::NewtonSettings st;
  st.matrix_free = true;
  st.matrix_free_preconditioner = pd::MatrixFreePreconditioner::approximate_tangent;
  st.krylov_tolerance = 1e-10;
  const pd::NewtonResult r = run(sys, pb.dofs, u_mf, st);
  ASSERT_TRUE(r.converged) << r.message;
  EXPECT_EQ(r.linear_solver, "matrix-free cg+cholmod");
  // The factorisation is of the tangent at the start of the load step, so later
  // Newton iterations see a slightly different K: a handful of iterations, not hundreds.
  EXPECT_LE(r.history[1].linear_iterations, 2);
  for (const auto& rec : r.history) EXPECT_LE(rec.linear_iterations, 30) << "iteration " << rec.iteration;
  EXPECT_LT((u_direct - u_mf).norm(), 1e-8 * u_direct.norm());
}

// Eisenstat-Walker forcing: the same answer as a fixed tight Krylov tolerance, with
// fewer Krylov iterations in total (loose solves while Newton is far from the solution).
TEST(Newton, AdaptiveForcingSavesKrylovIterationsWithoutChangingTheAnswer) {
  auto pb = nonlinear_problem();
  auto sys = pb.system();
  auto total = [](const pd::NewtonResult& r) {
    int n = 0;
    for (const auto& rec : r.history) n += rec.linear_iterations;
    return n;
  };
  Eigen::VectorXd u_fixed, u_adaptive;
  pd::NewtonSettings st;
  st.matrix_free = true;
  st.krylov_tolerance = 1e-12;
  st.adaptive_forcing = false;
  const pd::NewtonResult fixed = run(sys, pb.dofs, u_fixed, st);
  st.adaptive_forcing = true;
  const pd::NewtonResult adaptive = run(sys, pb.dofs, u_adaptive, st);
  ASSERT_TRUE(fixed.converged) << fixed.message;
  ASSERT_TRUE(adaptive.converged) << adaptive.message;
  EXPECT_LT(total(adaptive), total(fixed)) << total(adaptive) << " vs " << total(fixed);
  EXPECT_LT((u_fixed - u_adaptive).norm(), 1e-8 * u_fixed.norm());
}

TEST(Newton, NonSymmetricPathUsesUmfpackAndGmres) {
  auto pb = nonlinear_problem();
  auto inner = pb.system();
  NonSymmetric sys(inner);
  Eigen::VectorXd u_ref, u_lu, u_gm;
  ASSERT_TRUE(run(inner, pb.dofs, u_ref, {}).converged);
  const pd::NewtonResult lu = run(sys, pb.dofs, u_lu, {});
  ASSERT_TRUE(lu.converged) << lu.message;
  EXPECT_EQ(lu.linear_solver, "umfpack");
  pd::NewtonSettings st;
  st.matrix_free = true;
  st.krylov_tolerance = 1e-10;
  st.gmres_restart = 20;  // forces restarts on this problem
  const pd::NewtonResult gm = run(sys, pb.dofs, u_gm, st);
  ASSERT_TRUE(gm.converged) << gm.message;
  EXPECT_EQ(gm.linear_solver, "matrix-free gmres+jacobi");
  EXPECT_LT((u_ref - u_lu).norm(), 1e-9 * u_ref.norm());
  EXPECT_LT((u_ref - u_gm).norm(), 1e-8 * u_ref.norm());
}

TEST(Newton, NonConvergenceIsReportedClearly) {
  auto pb = nonlinear_problem();
  auto sys = pb.system();
  Eigen::VectorXd u;
  pd::NewtonSettings st;
  st.max_iterations = 1;
  const pd::NewtonResult r = run(sys, pb.dofs, u, st);
  EXPECT_FALSE(r.converged);
  EXPECT_NE(r.message.find("did not converge"), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("load steps"), std::string::npos) << r.message;
}

namespace {
// The spring grid with a deterministic residual "rounding floor": a fixed pseudo-random
// vector of relative size 1e-7 added to r, as an ill-conditioned system's cancellation does.
struct NoisyFloor final : pd::NonlinearSystem {
  pd::NonlinearSystem& s;
  double floor;
  int calls = 0;
  NoisyFloor(pd::NonlinearSystem& inner, double f) : s(inner), floor(f) {}
  int size() const override { return s.size(); }
  void add_noise(Eigen::VectorXd& r) {
    ++calls;
    for (Eigen::Index i = 0; i < r.size(); ++i) r[i] += floor * std::sin(12.9898 * (i + 1) * calls);
  }
  void residual(const Eigen::VectorXd& u, double l, Eigen::VectorXd& r) override {
    s.residual(u, l, r), add_noise(r);
  }
  void tangent(const Eigen::VectorXd& u, double l, pd::SparseMatrix& K, Eigen::VectorXd* r) override {
    s.tangent(u, l, K, r);
    if (r) add_noise(*r);
  }
};
}  // namespace

TEST(Newton, StagnationOnTheRoundingFloorEndsTheIterationAndIsReported) {
  auto pb = nonlinear_problem();
  auto inner = pb.system();
  NoisyFloor sys(inner, 1e-7 * pb.external.norm());
  Eigen::VectorXd u;
  pd::NewtonSettings st;
  std::vector<std::string> log;
  const pd::NewtonResult r = run(sys, pb.dofs, u, st, &log);
  ASSERT_TRUE(r.converged) << r.message;
  EXPECT_TRUE(r.stagnated);
  EXPECT_LT(r.iterations(), 15);
  bool said = false;
  for (const auto& line : log)
    said = said || line.find("stagnated on the rounding floor") != std::string::npos;
  EXPECT_TRUE(said);
  // Without the rule the same system cannot reach rtol = 1e-10 and fails clearly.
  st.stagnation_window = 0;
  const pd::NewtonResult strict = run(sys, pb.dofs, u, st);
  EXPECT_FALSE(strict.converged);
  EXPECT_NE(strict.message.find("did not converge"), std::string::npos);
}

namespace {
// The spring grid with a tangent `scale` times too stiff (a badly scaled system: the
// steps come out `scale` times too short while r stays where it is).
struct TooStiffTangent final : pd::NonlinearSystem {
  pd::NonlinearSystem& s;
  double scale;
  TooStiffTangent(pd::NonlinearSystem& inner, double k) : s(inner), scale(k) {}
  int size() const override { return s.size(); }
  void residual(const Eigen::VectorXd& u, double l, Eigen::VectorXd& r) override { s.residual(u, l, r); }
  void tangent(const Eigen::VectorXd& u, double l, pd::SparseMatrix& K, Eigen::VectorXd* r) override {
    s.tangent(u, l, K, r);
    K *= scale;
  }
  bool has_jvp() const override { return true; }
  void jvp(const Eigen::VectorXd& u, double l, const Eigen::VectorXd& v, Eigen::VectorXd& Kv) override {
    s.jvp(u, l, v, Kv);
    Kv *= scale;
  }
  void diagonal(const Eigen::VectorXd& u, double l, Eigen::VectorXd& d) override {
    s.diagonal(u, l, d);
    d *= scale;
  }
  double rounding_length() const override { return s.rounding_length(); }
};

// Pulled by a prescribed displacement, so |u| is set from the first iterate on.
pd::test::GridProblem pulled_problem(double pull) {
  return {pd::test::state_law_2d(), {5.0e2, 3.0e2}, 8, 6, pull, 0.0};
}
}  // namespace

// The true rounding floor: a pull of 1e-7 spacings leaves the bond extensions |Y| - |xi|
// with about 9 digits, so rtol = 1e-16 is out of reach and the increment rule must end
// the step, within the ceiling, at a residual no better solve could lower.
TEST(Newton, AResidualOnItsRoundingFloorConvergesByTheIncrementRule) {
  auto pb = pulled_problem(1e-7);
  auto sys = pb.system();
  Eigen::VectorXd u;
  pd::NewtonSettings st;
  st.relative_tolerance = 1e-16;
  st.increment_tolerance = 1e-9;  // the scenes' default
  const pd::NewtonResult r = run(sys, pb.dofs, u, st);
  ASSERT_TRUE(r.converged) << r.message;
  EXPECT_FALSE(r.stagnated);
  const double last = r.history.back().residual, first = r.history.front().residual;
  EXPECT_GT(last, 1e-16 * first) << "rtol was reached: this is not the floor";
  EXPECT_GT(r.rounding_floor, 0.0);
  EXPECT_LE(last, st.floor_factor * r.rounding_floor);
  // The floor is the rounding of the bond vectors (|xi| ~ 2, eps |xi| against a stretch
  // of 1e-7): about 1e-9 of the reference, far above eps.
  EXPECT_GT(r.rounding_floor, 1e-11 * first);
  EXPECT_LT(r.rounding_floor, 1e-7 * first);
}

// A tangent 1e14 times too stiff: every full step moves u by about 1e-14 |u|, below the
// increment tolerance. The old rule (step 1 and |du| <= increment_tolerance |u|, no
// ceiling) reported convergence after one iteration with |r| still at its initial value;
// the residual is far above its rounding floor, so this must not converge, and the
// message names |r| and the ceiling. Assembled and matrix-free.
TEST(Newton, NegligibleStepsFarAboveTheRoundingFloorDoNotConverge) {
  auto pb = pulled_problem(1e-2);
  auto inner = pb.system();
  TooStiffTangent sys(inner, 1e14);
  for (const bool matrix_free : {false, true}) {
    pd::NewtonSettings st;
    st.increment_tolerance = 1e-9;
    st.matrix_free = matrix_free;
    Eigen::VectorXd u;
    std::vector<std::string> log;
    const pd::NewtonResult r = run(sys, pb.dofs, u, st, &log);
    EXPECT_FALSE(r.converged) << (matrix_free ? "matrix-free" : "assembled");
    ASSERT_GE(r.history.size(), 2u);
    EXPECT_LT(r.history[1].increment, st.increment_tolerance) << "the steps should be negligible";
    EXPECT_GT(r.history.back().residual, 0.5 * r.history.front().residual);
    EXPECT_NE(r.message.find("did not converge"), std::string::npos) << r.message;
    EXPECT_NE(r.message.find("|r| = "), std::string::npos) << r.message;
    EXPECT_NE(r.message.find("rounding-floor ceiling"), std::string::npos) << r.message;
    EXPECT_LE(r.iterations(), 3) << "a step that does not move u is not repeated to max_iterations";
  }
}

// A tangent 1e9 times too stiff: steps of about 1e-9 |u|, above the increment tolerance
// but below the stagnation increment, each lowering |r| by a part in 1e9. The old
// stagnation rule ("stagnated on the rounding floor", no ceiling) reported convergence
// after three such steps at the initial residual; now the iteration goes on to
// max_iterations and fails.
TEST(Newton, StagnationFarAboveTheRoundingFloorDoesNotConverge) {
  auto pb = pulled_problem(1e-2);
  auto inner = pb.system();
  TooStiffTangent sys(inner, 1e9);
  pd::NewtonSettings st;
  st.max_iterations = 8;
  Eigen::VectorXd u;
  std::vector<std::string> log;
  const pd::NewtonResult r = run(sys, pb.dofs, u, st, &log);
  EXPECT_FALSE(r.converged);
  EXPECT_FALSE(r.stagnated);
  EXPECT_EQ(r.iterations(), st.max_iterations);
  EXPECT_GT(r.history.back().residual, 0.5 * r.history.front().residual);
  EXPECT_NE(r.message.find("iteration stagnated"), std::string::npos) << r.message;
  for (const auto& line : log)
    EXPECT_EQ(line.find("stagnated on the rounding floor"), std::string::npos) << line;
}

namespace {
// r(u) = load b - A u with A symmetric but indefinite (a softening region): declared
// symmetric, so the matrix-free path starts with CG and must hand over to GMRES.
struct IndefiniteLinear final : pd::NonlinearSystem {
  Eigen::MatrixXd A;
  Eigen::VectorXd b;
  explicit IndefiniteLinear(int n) : A(Eigen::MatrixXd::Zero(n, n)), b(n) {
    for (int i = 0; i < n; ++i) {
      A(i, i) = i < 3 * n / 4 ? 2.5 : -3.0;
      if (i + 1 < n) A(i, i + 1) = A(i + 1, i) = -1.0;
      b[i] = std::sin(1.0 + i);
    }
  }
  int size() const override { return static_cast<int>(b.size()); }
  void residual(const Eigen::VectorXd& u, double l, Eigen::VectorXd& r) override { r = l * b - A * u; }
  void tangent(const Eigen::VectorXd&, double, pd::SparseMatrix& K, Eigen::VectorXd*) override {
    K = A.sparseView();
  }
  bool has_jvp() const override { return true; }
  void jvp(const Eigen::VectorXd&, double, const Eigen::VectorXd& v, Eigen::VectorXd& Kv) override {
    Kv = A * v;
  }
  void diagonal(const Eigen::VectorXd&, double, Eigen::VectorXd& d) override { d = A.diagonal(); }
};
}  // namespace

TEST(Newton, MatrixFreeCgHandsOverToGmresOnNegativeCurvature) {
  IndefiniteLinear sys(40);
  const std::vector<char> constrained(40, 0);
  const std::vector<double> prescribed(40, 0.0);
  const pd::DofMap dofs(constrained, prescribed);
  pd::NewtonSettings st;
  st.matrix_free = true;
  st.krylov_tolerance = 1e-12;
  Eigen::VectorXd u;
  std::vector<std::string> log;
  const pd::NewtonResult r = run(sys, dofs, u, st, &log);
  ASSERT_TRUE(r.converged) << r.message;
  EXPECT_EQ(r.linear_solver, "matrix-free gmres+jacobi");
  bool said = false;
  for (const auto& line : log) said = said || line.find("negative curvature") != std::string::npos;
  EXPECT_TRUE(said);
  const Eigen::VectorXd exact = sys.A.fullPivLu().solve(sys.b);
  EXPECT_LT((u - exact).norm(), 1e-9 * exact.norm());
}

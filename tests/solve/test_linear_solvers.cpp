// Every linear solver on the reduced system of a clamped 2D spring grid; the automatic
// rule; the CHOLMOD-to-UMFPACK fallback on an indefinite matrix.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "solve/linear_solver.hpp"
#include "support_spring_grid_problem.hpp"

namespace {
struct Reduced {
  pd::test::GridProblem pb{pd::test::linear_spring_2d(), {1.0e3}, 9, 7, 0.01, 0.0};
  pd::SparseMatrix K;
  std::unique_ptr<pd::ReducedSystem> red;
  Eigen::VectorXd b;
  Reduced() {
    Eigen::VectorXd f(pb.assembler->dofs());
    pb.assembler->stiffness(nullptr, K, f.data());
    red = std::make_unique<pd::ReducedSystem>(pb.dofs, K);
    red->update(K);
    const Eigen::VectorXd uc =
        Eigen::Map<const Eigen::VectorXd>(pb.dofs.prescribed().data(), pb.dofs.constrained_count());
    b = red->rhs(f, uc);  // f = 0 at u = 0: b = -K_fc u_c
  }
};
}  // namespace

TEST(LinearSolvers, EachSolverSolvesTheSpringGrid) {
  Reduced r;
  ASSERT_GT(r.b.norm(), 0.0);
  const Eigen::VectorXd ref = Eigen::MatrixXd(r.red->Kff()).llt().solve(r.b);
  using M = pd::LinearMethod;
  using P = pd::Preconditioner;
  struct Case {
    M method;
    P pre;
  };
  for (const Case& c :
       {Case{M::cholmod, P::automatic}, Case{M::umfpack, P::automatic}, Case{M::cg, P::ic},
        Case{M::cg, P::diagonal}, Case{M::bicgstab, P::ilut}, Case{M::automatic, P::automatic}}) {
    pd::LinearSolverOptions o;
    o.method = c.method;
    o.preconditioner = c.pre;
    o.tolerance = 1e-12;
    pd::AutoLinearSolver s(o, true);
    s.analyse(r.red->Kff());
    ASSERT_TRUE(s.factor(r.red->Kff())) << pd::name_of(c.method);
    Eigen::VectorXd x;
    const pd::LinearSolveStats st = s.solve(r.b, x);
    EXPECT_TRUE(st.converged) << pd::name_of(c.method);
    EXPECT_LT((r.red->Kff() * x - r.b).norm(), 1e-10 * r.b.norm())
        << pd::name_of(c.method) << "+" << pd::name_of(c.pre);
    EXPECT_LT((x - ref).norm(), 1e-8 * ref.norm()) << pd::name_of(c.method);
    if (c.method == M::cg || c.method == M::bicgstab) {
      EXPECT_GT(st.iterations, 0) << pd::name_of(c.method);
      EXPECT_LE(st.estimated_error, 1e-12) << pd::name_of(c.method);
    }
    // A second factor/solve on the same pattern (Newton does this) gives the same answer.
    ASSERT_TRUE(s.factor(r.red->Kff()));
    Eigen::VectorXd x2;
    s.solve(r.b, x2);
    EXPECT_LT((x2 - x).norm(), 1e-10 * x.norm()) << pd::name_of(c.method);
  }
}

TEST(LinearSolvers, AutomaticRule) {
  pd::LinearSolverOptions o;
  o.direct_max_nonzeros = 1000;
  auto choose = [&](std::int64_t nonzeros, bool symmetric) {
    return pd::choose_linear_solver(o.method, o.preconditioner, o.direct_max_nonzeros, 100, nonzeros,
                                    symmetric)
        .method;
  };
  EXPECT_EQ(choose(1000, true), pd::LinearMethod::cholmod);
  EXPECT_EQ(choose(1000, false), pd::LinearMethod::umfpack);
  EXPECT_EQ(choose(1001, true), pd::LinearMethod::cg);
  EXPECT_EQ(choose(1001, false), pd::LinearMethod::bicgstab);
  o.method = pd::LinearMethod::umfpack;
  EXPECT_EQ(choose(1e9, true), pd::LinearMethod::umfpack);
  // A pair that names no assembled solver (the scene reader rejects the words; the
  // factory still refuses the values).
  o.method = pd::LinearMethod::bicgstab;
  o.preconditioner = pd::Preconditioner::ic;
  EXPECT_THROW(pd::make_sparse_solver(o.method, o), std::invalid_argument);
  o.method = pd::LinearMethod::matrix_free;
  EXPECT_THROW(pd::AutoLinearSolver(o, true), std::invalid_argument);
}

TEST(LinearSolvers, IndefiniteMatrixFallsBackToUmfpack) {
  Reduced r;
  pd::SparseMatrix A = r.red->Kff();
  // Flip the sign of one diagonal entry far beyond the rest: symmetric, not definite.
  A.coeffRef(3, 3) = -10 * Eigen::MatrixXd(A).cwiseAbs().maxCoeff();
  std::vector<std::string> log;
  pd::LinearSolverOptions o;
  pd::AutoLinearSolver s(o, true, [&](const std::string& m) { log.push_back(m); });
  ASSERT_TRUE(s.factor(A));
  EXPECT_EQ(s.name(), "umfpack");
  bool said = false;
  for (const auto& m : log)
    said |= m.find("not positive definite") != std::string::npos && m.find("umfpack") != std::string::npos;
  EXPECT_TRUE(said);
  Eigen::VectorXd x;
  s.solve(r.b, x);
  EXPECT_LT((A * x - r.b).norm(), 1e-10 * r.b.norm());
}

TEST(LinearSolvers, SingularMatrixThrows) {
  pd::SparseMatrix A(4, 4);
  A.insert(0, 0) = 1.0;
  A.insert(1, 1) = 1.0;
  A.makeCompressed();
  pd::LinearSolverOptions o;
  o.method = pd::LinearMethod::umfpack;
  pd::AutoLinearSolver s(o, false);
  EXPECT_THROW(s.factor(A), std::runtime_error);
}

// UMFPACK's failure says what happened: a singular matrix is reported as singular (its
// status, not Eigen's one code for every failure), and a regular one factors and solves.
TEST(LinearSolvers, UmfpackNamesASingularMatrix) {
  const int n = 400;
  pd::SparseMatrix A(n, n);
  std::vector<Eigen::Triplet<double>> t;
  for (int i = 0; i < n; ++i) {
    t.emplace_back(i, i, 2.0 + (i % 3));
    if (i + 1 < n) t.emplace_back(i, i + 1, 0.5), t.emplace_back(i + 1, i, 0.5);
  }
  A.setFromTriplets(t.begin(), t.end());
  auto umfpack = pd::make_sparse_solver(pd::LinearMethod::umfpack, pd::LinearSolverOptions{});
  umfpack->analyse(A);
  ASSERT_TRUE(umfpack->factor(A)) << umfpack->failure();
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, 1.0, 2.0);
  Eigen::VectorXd x;
  umfpack->solve(b, x);
  EXPECT_LT((A * x - b).norm(), 1e-12 * b.norm());

  pd::SparseMatrix S = A;
  S.coeffRef(n / 2, n / 2) = 0, S.coeffRef(n / 2, n / 2 + 1) = 0,
                        S.coeffRef(n / 2, n / 2 - 1) = 0;  // a zero row
  auto singular = pd::make_sparse_solver(pd::LinearMethod::umfpack, pd::LinearSolverOptions{});
  singular->analyse(S);
  EXPECT_FALSE(singular->factor(S));
  EXPECT_NE(singular->failure().find("singular"), std::string::npos) << singular->failure();
}

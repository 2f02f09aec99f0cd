// Hash-consing and the cheap rewrites applied when nodes are built.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "pdgen/eval.hpp"
#include "pdgen/expr.hpp"
#include "pdgen/tensor.hpp"

using namespace pdgen;

TEST(Expr, SameExpressionBuiltTwiceIsTheSameNode) {
  const Expr x = symbol("x"), y = symbol("y");
  EXPECT_EQ(sqrt(x * x + y), sqrt(y + x * x));
  EXPECT_EQ(x * y, y * x);
  EXPECT_EQ(x + y, y + x);
  EXPECT_EQ(exp(x - y), exp(-y + x));
}

TEST(Expr, NeutralAndAbsorbingElements) {
  const Expr x = symbol("x");
  EXPECT_EQ(x * 1, x);
  EXPECT_EQ(x + 0, x);
  EXPECT_TRUE((x * 0).is_const(0.0));
  EXPECT_EQ(pow(x, 1.0), x);
  EXPECT_TRUE(pow(x, 0.0).is_const(1.0));
  EXPECT_TRUE((x - x).is_const(0.0));
  EXPECT_TRUE((x / x).is_const(1.0));
}

TEST(Expr, ConstantFolding) {
  EXPECT_TRUE((Expr(2.0) * 3 + 1).is_const(7.0));
  EXPECT_TRUE(sqrt(Expr(16.0)).is_const(4.0));
  EXPECT_TRUE(exp(Expr(0.0)).is_const(1.0));
}

// A NaN or infinite constant would be emitted into a kernel (as a wrong number, or as
// `inf`, which is not C++); folding refuses it and names the operation.
TEST(Expr, FoldingToNaNOrInfinityThrowsNamingTheOperation) {
  const Expr r = symbol("r");
  auto message = [](auto&& build) {
    try {
      build();
    } catch (const NonFiniteConstant& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message([] { sqrt(Expr(-1.0)); }), "constant folding: sqrt(-1) folds to NaN");
  EXPECT_EQ(message([] { log(Expr(-1.0)); }), "constant folding: log(-1) folds to NaN");
  EXPECT_EQ(message([&] { (r - r) / (r - r); }), "constant folding: 1/0 folds to inf");
  EXPECT_EQ(message([&] { 1 / (r - r); }), "constant folding: 1/0 folds to inf");
  EXPECT_EQ(message([] { Expr(std::nan("")) * 0 + 2; }), "constant folding: the constant NaN");
  EXPECT_EQ(message([] { exp(Expr(1e6)); }), "constant folding: exp(1000000) folds to inf");
  EXPECT_EQ(message([] { Expr(1e308) * 1e308; }), "constant folding: a product of constants folds to inf");
  EXPECT_EQ(message([] { Expr(1e308) + 1e308; }), "constant folding: a sum of constants folds to inf");
  EXPECT_EQ(message([&] { pow(r, std::numeric_limits<double>::infinity()); }),
            "constant folding: the exponent inf");
  // Finite folds are untouched.
  EXPECT_TRUE(sqrt(Expr(4.0)).is_const(2.0));
}

TEST(Expr, LikeTermsAndFactorsMerge) {
  const Expr x = symbol("x"), y = symbol("y");
  EXPECT_EQ(2 * x + 3 * x, 5 * x);
  EXPECT_EQ(x * x, pow(x, 2));
  EXPECT_EQ(x * y / x, y);
  EXPECT_EQ(pow(sqrt(x), 2), x);
  EXPECT_EQ(sqrt(x) * sqrt(x), x);
  EXPECT_EQ(log(exp(x)), x);
}

TEST(Expr, CanonicalOrderDoesNotDependOnConstructionOrder) {
  const Expr a = symbol("a"), b = symbol("b"), c = symbol("c");
  EXPECT_EQ(a * (b * c), (c * a) * b);
  EXPECT_EQ(a + (b + c), (c + a) + b);
}

TEST(Tensor, InverseTimesMatrixIsIdentity) {
  for (int d : {2, 3}) {
    Mat A(d);
    std::unordered_map<int, double> values;
    for (int i = 0; i < d; ++i)
      for (int j = 0; j < d; ++j) {
        A(i, j) = symbol("a");
        values[symbol_index(A(i, j))] = (i == j ? 3.0 : 0.0) + 0.37 * (i + 1) - 0.21 * (j * j) + 0.05 * i * j;
      }
    const Mat P = inverse(A) * A;
    for (int i = 0; i < d; ++i)
      for (int j = 0; j < d; ++j) EXPECT_NEAR(evaluate(P(i, j), values), i == j ? 1.0 : 0.0, 1e-13);
    // det(A^T) = det(A), trace and dot agree with their definitions.
    EXPECT_NEAR(evaluate(det(transpose(A)), values), evaluate(det(A), values), 1e-13);
    EXPECT_NEAR(evaluate(trace(outer(Vec{A(0, 0), A(0, 1)}, Vec{A(1, 0), A(1, 1)})), values),
                evaluate(A(0, 0) * A(1, 0) + A(0, 1) * A(1, 1), values), 1e-14);
  }
}

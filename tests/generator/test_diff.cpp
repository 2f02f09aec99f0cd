// Symbolic derivatives of randomly built expressions against central finite differences.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "pdgen/diff.hpp"
#include "pdgen/eval.hpp"

using namespace pdgen;

namespace {
// Builds a random expression over `vars` whose value stays finite and smooth near
// positive inputs: logs and fractional powers get positive arguments.
class RandomExpr {
 public:
  RandomExpr(std::vector<Expr> vars, unsigned seed) : vars_(std::move(vars)), rng_(seed) {}
  Expr build(int depth) {
    std::uniform_int_distribution<int> pick(0, depth <= 0 ? 1 : 11);
    switch (pick(rng_)) {
      case 0:
        return vars_[std::uniform_int_distribution<std::size_t>(0, vars_.size() - 1)(rng_)];
      case 1:
        return Expr(std::uniform_real_distribution<double>(-2.0, 2.0)(rng_));
      case 2:
        return build(depth - 1) + build(depth - 1);
      case 3:
        return build(depth - 1) - build(depth - 1);
      case 4:
        return build(depth - 1) * build(depth - 1);
      case 5:
        return build(depth - 1) / (2.5 + positive(depth - 1));
      case 6:
        return sqrt(1.0 + positive(depth - 1));
      case 7:
        return pow(0.5 + positive(depth - 1), std::uniform_int_distribution<int>(-3, 4)(rng_) * 0.5);
      case 8:
        return exp(0.3 * sinlike(depth - 1));
      case 9:
        return log(1.0 + positive(depth - 1));
      case 10:
        return abs(build(depth - 1) + 7.0);
      default:
        return select(build(depth - 1) + 11.0, build(depth - 1), build(depth - 1));
    }
  }

 private:
  Expr positive(int depth) { return pow(build(depth), 2); }
  Expr sinlike(int depth) { return build(depth) / (1.0 + positive(depth)); }
  std::vector<Expr> vars_;
  std::mt19937 rng_;
};
}  // namespace

TEST(Diff, FortyRandomExpressionsAgreeWithCentralDifferences) {
  const std::vector<Expr> vars{symbol("x"), symbol("y"), symbol("z")};
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.3, 1.2);
  int checked = 0;
  for (unsigned seed = 1; checked < 40; ++seed) {
    ASSERT_LT(seed, 400u) << "could not build enough non-constant expressions";
    const Expr e = RandomExpr(vars, seed).build(4);
    if (free_symbols(e).empty()) continue;
    std::unordered_map<int, double> at;
    for (Expr v : vars) at[symbol_index(v)] = u(rng);
    for (Expr v : vars) {
      const Expr d = diff(e, v);
      const double h = 1e-6;
      auto shifted = at;
      shifted[symbol_index(v)] += h;
      const double fp = evaluate(e, shifted);
      shifted[symbol_index(v)] -= 2 * h;
      const double fm = evaluate(e, shifted);
      const double fd = (fp - fm) / (2 * h);
      const double exact = evaluate(d, at);
      ASSERT_TRUE(std::isfinite(exact));
      EXPECT_NEAR(exact, fd, 1e-6 * (1.0 + std::fabs(fd))) << "seed " << seed;
    }
    ++checked;
  }
}

TEST(Diff, RulesOfEveryOperation) {
  const Expr x = symbol("x");
  EXPECT_EQ(diff(x * x, x), 2 * x);
  EXPECT_EQ(diff(exp(x), x), exp(x));
  EXPECT_EQ(diff(log(x), x), 1 / x);
  EXPECT_EQ(diff(sqrt(x), x), 0.5 / sqrt(x));
  EXPECT_EQ(diff(abs(x), x), sign(x));
  EXPECT_TRUE(diff(sign(x), x).is_const(0.0));
  EXPECT_TRUE(diff(Expr(3.0), x).is_const(0.0));
  EXPECT_EQ(diff(select(x, x * x, x), x), select(x, 2 * x, Expr(1.0)));
}

TEST(Diff, DerivativeOfAnUnrelatedSymbolIsZero) {
  const Expr x = symbol("x"), y = symbol("y");
  EXPECT_TRUE(diff(exp(x) * sqrt(x), y).is_const(0.0));
}

TEST(Substitute, RebuildsAndSimplifies) {
  const Expr x = symbol("x"), a = symbol("a");
  const Expr e = a * x + (1 - a) * x * x;
  EXPECT_EQ(substitute(e, {{symbol_index(a), Expr(1.0)}}), x);
}

// The lowering of expression nodes to the LIR (generator/emit/lower.cpp, lir.hpp): binary
// arithmetic with explicit subtraction, division and negation, powers expanded, equal code
// hash-consed into one node. The LIR has no evaluator of its own, so the one below reads its
// nodes directly (with the C++ meaning the emitter prints for each kind) and is compared with
// the expression interpreter (generator/eval).
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

#include "../../generator/emit/lir.hpp"
#include "pdgen/diff.hpp"
#include "pdgen/eval.hpp"

using namespace pdgen;

namespace {
// The value of LIR node `id`, the symbols' values given by symbol index.
double eval_lir(const lir::Graph& g, int id, const std::unordered_map<int, double>& values) {
  const lir::Node& n = g.node(id);
  auto a = [&](std::size_t i) { return eval_lir(g, n.args.at(i), values); };
  switch (n.kind) {
    case lir::Kind::Const:
      return n.value;
    case lir::Kind::Var:
      return values.at(g.var_symbols().at(id));
    case lir::Kind::Add:
      return a(0) + a(1);
    case lir::Kind::Sub:
      return a(0) - a(1);
    case lir::Kind::Mul:
      return a(0) * a(1);
    case lir::Kind::Div:
      return a(0) / a(1);
    case lir::Kind::Neg:
      return -a(0);
    case lir::Kind::Select:
      return a(0) > 0.0 ? a(1) : a(2);
    case lir::Kind::Call:
      if (n.text == "std::sqrt") return std::sqrt(a(0));
      if (n.text == "std::pow") return std::pow(a(0), a(1));
      if (n.text == "std::exp") return std::exp(a(0));
      if (n.text == "std::log") return std::log(a(0));
      if (n.text == "std::fabs") return std::fabs(a(0));
      ADD_FAILURE() << "unknown call " << n.text;
      return NAN;
  }
  return NAN;
}

int count(const lir::Graph& g, lir::Kind kind, const std::string& text = "") {
  int n = 0;
  for (int id = 0; id < g.size(); ++id)
    if (g.node(id).kind == kind && (text.empty() || g.node(id).text == text)) ++n;
  return n;
}

// Bindings of per-family and per-bond symbols to C++ variable names.
std::map<int, Binding> bindings(const std::vector<Expr>& family, const std::vector<Expr>& bond) {
  std::map<int, Binding> b;
  for (Expr s : family) b[symbol_index(s)] = {"f" + std::to_string(symbol_index(s)), "", false};
  for (Expr s : bond) b[symbol_index(s)] = {"b" + std::to_string(symbol_index(s)), "", true};
  return b;
}

// Random expressions that stay finite near positive inputs, with what lower.cpp treats
// specially: negative coefficients and constants, subtraction, negative and half-integer powers,
// fractional powers, calls, sign and select.
class RandomExpr {
 public:
  RandomExpr(std::vector<Expr> vars, unsigned seed) : vars_(std::move(vars)), rng_(seed) {}
  Expr build(int depth) {
    std::uniform_int_distribution<int> pick(0, depth <= 0 ? 1 : 14);
    switch (pick(rng_)) {
      case 0:
        return vars_[std::uniform_int_distribution<std::size_t>(0, vars_.size() - 1)(rng_)];
      case 1:
        return Expr(std::uniform_int_distribution<int>(-6, 6)(rng_) * 0.5);
      case 2:
        return build(depth - 1) + build(depth - 1);
      case 3:
        return build(depth - 1) - build(depth - 1);
      case 4:
        return build(depth - 1) * build(depth - 1);
      case 5:
        return build(depth - 1) / (1.5 + positive(depth - 1));
      case 6:  // half-integer and integer powers, negative ones included
        return pow(0.5 + positive(depth - 1), std::uniform_int_distribution<int>(-7, 7)(rng_) * 0.5);
      case 7:  // a fractional power that is not a half
        return pow(0.5 + positive(depth - 1), std::uniform_int_distribution<int>(0, 1)(rng_) ? 0.3 : -1.3);
      case 8:
        return -build(depth - 1);
      case 9:
        return exp(0.3 * build(depth - 1) / (1.0 + positive(depth - 1)));
      case 10:
        return log(1.0 + positive(depth - 1));
      case 11:
        return abs(build(depth - 1) - 0.25);
      case 12:
        return sign(build(depth - 1) - 0.1) * build(depth - 1);
      case 13:
        return max(build(depth - 1), build(depth - 1));
      default:
        return select(build(depth - 1) + 0.2, build(depth - 1), -3.0 * build(depth - 1));
    }
  }

 private:
  Expr positive(int depth) { return pow(build(depth), 2); }
  std::vector<Expr> vars_;
  std::mt19937 rng_;
};
}  // namespace

// The central promise: lowering changes the shape of the code, never its value. Many random
// expressions are lowered into ONE graph (as the emitter lowers every store of a kernel), so
// hash-consing across expressions is exercised too; each root must evaluate like the
// interpreter. The same pass checks the graph's invariants the emitter relies on.
TEST(Lower, RandomExpressionsEvaluateLikeTheInterpreter) {
  const Expr x = symbol("x", SymbolKind::BondInput), y = symbol("y", SymbolKind::Param),
             z = symbol("z", SymbolKind::Param);
  const std::map<int, Binding> b = bindings({y, z}, {x});
  lir::Graph g(b);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0.2, 1.6);
  int checked = 0;
  for (unsigned seed = 1; checked < 60; ++seed) {
    ASSERT_LT(seed, 600u) << "could not build enough non-constant expressions";
    Expr e;
    try {
      e = RandomExpr({x, y, z}, seed).build(4);
    } catch (const NonFiniteConstant&) {
      continue;
    }
    if (free_symbols(e).empty()) continue;
    const int root = g.lower(e);
    // Per-bond-ness decides what the emitter hoists out of the bond loop: the root must be
    // per bond exactly when the expression reads the per-bond symbol.
    const bool reads_x = depends_on(e, [&](int s) { return s == symbol_index(x); });
    EXPECT_EQ(g.node(root).per_bond, reads_x) << "seed " << seed;
    for (int point = 0; point < 3; ++point) {
      const std::unordered_map<int, double> at{
          {symbol_index(x), u(rng)}, {symbol_index(y), u(rng)}, {symbol_index(z), u(rng)}};
      const double expected = evaluate(e, at), got = eval_lir(g, root, at);
      ASSERT_TRUE(std::isfinite(expected)) << "seed " << seed;
      EXPECT_NEAR(got, expected, 1e-10 * (1.0 + std::fabs(expected)))
          << "seed " << seed << " point " << point;
    }
    ++checked;
  }
  for (int id = 0; id < g.size(); ++id) {
    const lir::Node n = g.node(id);
    // Operands exist before the nodes built from them: the graph's order is an evaluation order.
    for (int a : n.args) EXPECT_LT(a, id) << "node " << id;
    // Signs are operations (Neg, Sub), never literals: `x * -2.0` or `- -1.0` would not be
    // emitted, and a -0.0 literal would print as a negative number.
    if (n.kind == lir::Kind::Const) {
      EXPECT_FALSE(std::signbit(n.value)) << "node " << id << " " << n.value;
    }
    // Neutral constants are not multiplied or added in.
    for (int a : n.args) {
      const bool is_one = g.node(a).kind == lir::Kind::Const && g.node(a).value == 1.0;
      const bool is_zero = g.node(a).kind == lir::Kind::Const && g.node(a).value == 0.0;
      if (n.kind == lir::Kind::Mul) {
        EXPECT_FALSE(is_one) << "node " << id;
      }
      if (n.kind == lir::Kind::Add || n.kind == lir::Kind::Sub) {
        EXPECT_FALSE(is_zero) << "node " << id;
      }
    }
  }
}

// A repeated subexpression is lowered once: after s = x*y + z is in the graph, exp(s)*s + log(s)
// adds only its four new operations (exp, *, log, +), and lowering either expression again
// returns the same node without growing the graph.
TEST(Lower, RepeatedSubexpressionIsLoweredOnce) {
  const Expr x = symbol("x"), y = symbol("y"), z = symbol("z");
  const std::map<int, Binding> b = bindings({x, y, z}, {});
  lir::Graph g(b);
  const Expr s = x * y + z;
  const int s_id = g.lower(s);
  const int before = g.size();
  const Expr e = exp(s) * s + log(s);
  const int e_id = g.lower(e);
  EXPECT_EQ(g.size(), before + 4);
  EXPECT_EQ(count(g, lir::Kind::Add), 2);
  EXPECT_EQ(g.lower(s), s_id);
  EXPECT_EQ(g.lower(e), e_id);
  EXPECT_EQ(g.size(), before + 4);
  // A variable is one node however often it is read.
  EXPECT_EQ(count(g, lir::Kind::Var), 3);
}

// Half-integer powers of one base share a single sqrt call (x^1.5 = x sqrt(x), x^-0.5 =
// 1/sqrt(x)), no std::pow is emitted for them, and the negative ones cost at most two
// divisions for the base: 1/x and 1/sqrt(x).
TEST(Lower, HalfIntegerPowersOfOneBaseShareOneSqrt) {
  const Expr x = symbol("x");
  const std::map<int, Binding> b = bindings({x}, {});
  lir::Graph g(b);
  std::vector<int> roots;
  const std::vector<double> exponents{0.5, 1.5, 2.5, -0.5, -1.5, -2.5};
  for (double p : exponents) roots.push_back(g.lower(pow(x, p)));
  EXPECT_EQ(count(g, lir::Kind::Call, "std::sqrt"), 1);
  EXPECT_EQ(count(g, lir::Kind::Call, "std::pow"), 0);
  EXPECT_EQ(count(g, lir::Kind::Div), 2);
  for (std::size_t i = 0; i < roots.size(); ++i)
    EXPECT_NEAR(eval_lir(g, roots[i], {{symbol_index(x), 1.7}}), std::pow(1.7, exponents[i]), 1e-13)
        << exponents[i];
}

// Every quotient by the same base shares one reciprocal: x/r, y/r and x y / r^2 cost one division.
TEST(Lower, QuotientsByTheSameBaseShareOneReciprocal) {
  const Expr x = symbol("x"), y = symbol("y"), r = symbol("r");
  const std::map<int, Binding> b = bindings({x, y, r}, {});
  lir::Graph g(b);
  const int root = g.lower(x / r + y / r + x * y / (r * r));
  EXPECT_EQ(count(g, lir::Kind::Div), 1);
  EXPECT_NEAR(eval_lir(g, root, {{symbol_index(x), 0.3}, {symbol_index(y), 1.1}, {symbol_index(r), 0.7}}),
              0.3 / 0.7 + 1.1 / 0.7 + 0.3 * 1.1 / 0.49, 1e-14);
}

// Integer powers are products, by repeated squaring: x^8 is three multiplications and no call;
// a non-half fractional power is one std::pow of the fractional part only.
TEST(Lower, IntegerPowersAreProductsAndOtherPowersOneCall) {
  const Expr x = symbol("x");
  const std::map<int, Binding> b = bindings({x}, {});
  lir::Graph g(b);
  const int p8 = g.lower(pow(x, 8));
  EXPECT_EQ(count(g, lir::Kind::Mul), 3);
  EXPECT_EQ(count(g, lir::Kind::Call), 0);
  EXPECT_NEAR(eval_lir(g, p8, {{symbol_index(x), 1.3}}), std::pow(1.3, 8), 1e-13);

  lir::Graph h(b);
  const int p = h.lower(pow(x, 2.25));
  EXPECT_EQ(count(h, lir::Kind::Call, "std::pow"), 1);
  EXPECT_EQ(count(h, lir::Kind::Call), 1);
  EXPECT_NEAR(eval_lir(h, p, {{symbol_index(x), 1.3}}), std::pow(1.3, 2.25), 1e-13);
}

// Constants: a negative coefficient becomes a subtraction or a negation, a coefficient of
// magnitude 1 disappears, and a negative constant is Neg of its magnitude.
TEST(Lower, SignsOfConstantsBecomeOperations) {
  const Expr x = symbol("x"), y = symbol("y");
  const std::map<int, Binding> b = bindings({x, y}, {});
  lir::Graph g(b);

  const lir::Node diff_node = g.node(g.lower(x - 2 * y));  // x + (-2) y
  ASSERT_EQ(diff_node.kind, lir::Kind::Sub);
  EXPECT_EQ(g.node(diff_node.args[0]).kind, lir::Kind::Var);
  const lir::Node scaled = g.node(diff_node.args[1]);
  ASSERT_EQ(scaled.kind, lir::Kind::Mul);
  EXPECT_TRUE(g.node(scaled.args[0]).kind == lir::Kind::Const && g.node(scaled.args[0]).value == 2.0);

  const lir::Node neg = g.node(g.lower(-(x * y)));  // (-1) x y: no multiplication by 1
  ASSERT_EQ(neg.kind, lir::Kind::Neg);
  const lir::Node xy = g.node(neg.args[0]);
  ASSERT_EQ(xy.kind, lir::Kind::Mul);
  for (int a : xy.args) EXPECT_EQ(g.node(a).kind, lir::Kind::Var);

  const lir::Node c = g.node(g.lower(Expr(-3.0)));
  ASSERT_EQ(c.kind, lir::Kind::Neg);
  EXPECT_EQ(g.node(c.args[0]).value, 3.0);
}

// Products put per-family factors first, so their partial product is a per-family node the
// emitter hoists out of the bond loop (the per-family symbols are created first here, so that
// ordering by expression id alone would put them last), and the vector components, created
// before the other per-bond inputs as in a Law, come last so that the components share the
// product of everything else.
TEST(Lower, PerFamilyFactorsComeFirstAndComponentsShareTheRest) {
  const Expr p = symbol("p", SymbolKind::Param), q = symbol("q", SymbolKind::Param);
  const Expr Y0 = symbol("Y0", SymbolKind::BondInput), Y1 = symbol("Y1", SymbolKind::BondInput);
  const Expr w = symbol("w", SymbolKind::BondInput), V = symbol("V", SymbolKind::BondInput);
  const std::map<int, Binding> b = bindings({p, q}, {Y0, Y1, w, V});
  lir::Graph g(b);
  const lir::Node root = g.node(g.lower(w * p * Y0 * q));
  ASSERT_EQ(root.kind, lir::Kind::Mul);
  EXPECT_TRUE(root.per_bond);
  EXPECT_EQ(g.var_symbols().at(root.args[1]), symbol_index(Y0)) << "the component is not the last factor";
  int per_family_products = 0;
  for (int id = 0; id < g.size(); ++id)
    if (g.node(id).kind == lir::Kind::Mul && !g.node(id).per_bond) ++per_family_products;
  EXPECT_EQ(per_family_products, 1) << "p q is not one hoistable factor";
  g.lower(q * Y1 * p * w);  // the other component: one more multiplication
  EXPECT_EQ(count(g, lir::Kind::Mul), 4);

  lir::Graph h(b);
  h.lower(w * V * Y0);
  h.lower(w * V * Y1);
  EXPECT_EQ(count(h, lir::Kind::Mul), 3) << "w V should be shared by the two components";
}

// sign(x) lowers to selects with the interpreter's meaning at 0 as well.
TEST(Lower, SignIsMinusOneZeroOrOne) {
  const Expr x = symbol("x");
  const std::map<int, Binding> b = bindings({x}, {});
  lir::Graph g(b);
  const int root = g.lower(sign(x));
  for (double v : {-2.0, 0.0, 3.0})
    EXPECT_EQ(eval_lir(g, root, {{symbol_index(x), v}}), evaluate(sign(x), {{symbol_index(x), v}})) << v;
}

// A symbol the kernel does not bind is an error: a free symbol is the law author's mistake (an
// undeclared parameter, named in the message); any other kind is the generator's own.
TEST(Lower, UnboundSymbolsAreRefused) {
  const Expr x = symbol("x"), stray = symbol("stray_name"), s = symbol("some_sum", SymbolKind::Sum);
  const std::map<int, Binding> b = bindings({x}, {});
  lir::Graph g(b);
  try {
    g.lower(x + stray);
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("stray_name"), std::string::npos) << e.what();
  }
  try {
    g.lower(x * s);
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    FAIL() << "a generator error reported as the law's: " << e.what();
  } catch (const std::logic_error& e) {
    EXPECT_NE(std::string(e.what()).find("some_sum"), std::string::npos) << e.what();
  }
}

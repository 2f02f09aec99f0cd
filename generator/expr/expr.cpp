// Canonicalising builders: the cheap rewrites applied whenever a node is built.
#include "pdgen/expr.hpp"

#include <cmath>
#include <map>
#include <sstream>
#include <stdexcept>

namespace pdgen {

namespace {
Context& ctx() { return Context::global(); }
Expr node_expr(Op op, double value, std::vector<NodeId> args) {
  return Expr::from_id(ctx().intern(op, value, -1, std::move(args)));
}
bool is_integer(double e) { return std::nearbyint(e) == e; }

std::string number(double v) {
  if (std::isnan(v)) return "NaN";  // never "-nan": the sign of a NaN means nothing here
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
}

// The result of folding `what` (the operation as written, e.g. "log(-1)"): a law whose
// constant folds to NaN or infinity computes nonsense or emits C++ that does not
// compile, so building it stops here with the operation in the message.
Expr folded(double v, const std::string& what) {
  if (!std::isfinite(v)) throw NonFiniteConstant(what + " folds to " + number(v));
  return Expr(v);
}

std::string pow_text(double base, double e) {
  if (e == 0.5) return "sqrt(" + number(base) + ")";
  if (e == -1.0) return "1/" + number(base);
  return "pow(" + number(base) + ", " + number(e) + ")";
}

// Adds `term` (scaled by `scale`) into a like-terms accumulator keyed by its
// non-constant part, so that 2x + 3x becomes 5x.
void accumulate_term(Expr term, double scale, double& constant, std::map<NodeId, double>& terms) {
  const Node& n = term.node();
  if (n.op == Op::Const) {
    constant += scale * n.value;
  } else if (n.op == Op::Add) {
    for (NodeId a : n.args) accumulate_term(Expr::from_id(a), scale, constant, terms);
  } else if (n.op == Op::Mul && ctx().node(n.args[0]).op == Op::Const) {
    const double coef = ctx().node(n.args[0]).value;
    std::vector<NodeId> rest(n.args.begin() + 1, n.args.end());
    const NodeId base = rest.size() == 1 ? rest[0] : ctx().intern(Op::Mul, 0.0, -1, std::move(rest));
    terms[base] += scale * coef;
  } else {
    terms[term.id()] += scale;
  }
}

// Multiplies `factor` into a like-factors accumulator keyed by base, so that
// x * x^-1 cancels and x * x becomes x^2.
void accumulate_factor(Expr factor, double& coefficient, std::map<NodeId, double>& powers) {
  const Node& n = factor.node();
  if (n.op == Op::Const) {
    coefficient *= n.value;
  } else if (n.op == Op::Mul) {
    for (NodeId a : n.args) accumulate_factor(Expr::from_id(a), coefficient, powers);
  } else if (n.op == Op::Pow) {
    powers[n.args[0]] += n.value;
  } else {
    powers[factor.id()] += 1.0;
  }
}

Expr raw_pow(NodeId base, double e) {
  if (e == 1.0) return Expr::from_id(base);
  return node_expr(Op::Pow, e, {base});
}
}  // namespace

NodeId Expr::constant_id(double v) {
  if (!std::isfinite(v)) throw NonFiniteConstant("the constant " + number(v));
  return ctx().intern(Op::Const, v, -1, {});
}

Expr symbol(const std::string& name, SymbolKind kind) {
  const int s = ctx().add_symbol(SymbolInfo{name, kind});
  return Expr::from_id(ctx().intern(Op::Symbol, 0.0, s, {}));
}

int symbol_index(Expr e) {
  if (e.op() != Op::Symbol) throw std::logic_error("symbol_index: not a symbol");
  return e.node().symbol;
}

Expr add(const std::vector<Expr>& in) {
  double constant = 0.0;
  std::map<NodeId, double> terms;
  for (Expr t : in) accumulate_term(t, 1.0, constant, terms);
  std::vector<NodeId> args;
  if (constant != 0.0) args.push_back(folded(constant, "a sum of constants").id());
  for (auto [base, coef] : terms) {
    if (coef == 0.0) continue;
    args.push_back(coef == 1.0 ? base : mul({Expr(coef), Expr::from_id(base)}).id());
  }
  if (args.empty()) return Expr(0.0);
  if (args.size() == 1) return Expr::from_id(args[0]);
  return node_expr(Op::Add, 0.0, std::move(args));
}

Expr mul(const std::vector<Expr>& in) {
  double coefficient = 1.0;
  std::map<NodeId, double> powers;
  for (Expr f : in) accumulate_factor(f, coefficient, powers);
  if (!std::isfinite(coefficient)) folded(coefficient, "a product of constants");
  if (coefficient == 0.0) return Expr(0.0);
  std::vector<NodeId> factors;
  for (auto [base, e] : powers)
    if (e != 0.0) factors.push_back(raw_pow(base, e).id());
  if (factors.empty()) return Expr(coefficient);
  if (coefficient == 1.0 && factors.size() == 1) return Expr::from_id(factors[0]);
  std::vector<NodeId> args;
  if (coefficient != 1.0) args.push_back(Expr(coefficient).id());
  args.insert(args.end(), factors.begin(), factors.end());
  return node_expr(Op::Mul, 0.0, std::move(args));
}

Expr pow(Expr base, double e) {
  if (!std::isfinite(e)) throw NonFiniteConstant("the exponent " + number(e));
  if (e == 0.0) return Expr(1.0);
  if (e == 1.0) return base;
  const Node& n = base.node();
  if (n.op == Op::Const) return folded(std::pow(n.value, e), pow_text(n.value, e));
  if (n.op == Op::Pow && (is_integer(e) || !is_integer(n.value))) {
    // (b^a)^e = b^(ae) holds for integer e, and for any e when a is fractional (b >= 0).
    return pow(Expr::from_id(n.args[0]), n.value * e);
  }
  if (n.op == Op::Mul) {
    const Node& first = ctx().node(n.args[0]);
    const bool positive_coefficient = first.op == Op::Const && first.value > 0.0;
    if (is_integer(e) || positive_coefficient) {
      // (c x y)^e = c^e x^e y^e holds for integer e. For fractional e with c > 0 only the
      // constant is split off: (c z)^e = c^e z^e with z = x y, whatever the signs of x and y.
      if (is_integer(e)) {
        std::vector<Expr> f;
        for (NodeId a : n.args) f.push_back(pow(Expr::from_id(a), e));
        return mul(f);
      }
      std::vector<NodeId> rest(n.args.begin() + 1, n.args.end());
      const Expr r = rest.size() == 1 ? Expr::from_id(rest[0]) : node_expr(Op::Mul, 0.0, rest);
      return mul({folded(std::pow(first.value, e), pow_text(first.value, e)), raw_pow(r.id(), e)});
    }
  }
  return raw_pow(base.id(), e);
}

Expr sqrt(Expr x) { return pow(x, 0.5); }

Expr exp(Expr x) {
  if (x.is_const()) return folded(std::exp(x.value()), "exp(" + number(x.value()) + ")");
  if (x.op() == Op::Log) return Expr::from_id(x.node().args[0]);
  return node_expr(Op::Exp, 0.0, {x.id()});
}

Expr log(Expr x) {
  if (x.is_const()) return folded(std::log(x.value()), "log(" + number(x.value()) + ")");
  if (x.op() == Op::Exp) return Expr::from_id(x.node().args[0]);
  return node_expr(Op::Log, 0.0, {x.id()});
}

Expr abs(Expr x) {
  if (x.is_const()) return Expr(std::fabs(x.value()));
  const Node& n = x.node();
  if (n.op == Op::Abs) return x;
  if (n.op == Op::Pow && (!is_integer(n.value) || std::fmod(n.value, 2.0) == 0.0)) return x;  // nonnegative
  if (n.op == Op::Exp) return x;
  return node_expr(Op::Abs, 0.0, {x.id()});
}

Expr sign(Expr x) {
  if (x.is_const()) return Expr(x.value() > 0 ? 1.0 : (x.value() < 0 ? -1.0 : 0.0));
  return node_expr(Op::Sign, 0.0, {x.id()});
}

Expr select(Expr c, Expr a, Expr b) {
  if (c.is_const()) return c.value() > 0 ? a : b;
  if (a == b) return a;
  return node_expr(Op::Select, 0.0, {c.id(), a.id(), b.id()});
}

Expr max(Expr a, Expr b) { return select(a - b, a, b); }
Expr min(Expr a, Expr b) { return select(b - a, a, b); }

Expr operator+(Expr a, Expr b) { return add({a, b}); }
Expr operator-(Expr a, Expr b) { return add({a, mul({Expr(-1.0), b})}); }
Expr operator*(Expr a, Expr b) { return mul({a, b}); }
Expr operator/(Expr a, Expr b) { return mul({a, pow(b, -1.0)}); }
Expr operator-(Expr a) { return mul({Expr(-1.0), a}); }

Expr& Expr::operator+=(Expr b) { return *this = *this + b; }
Expr& Expr::operator-=(Expr b) { return *this = *this - b; }
Expr& Expr::operator*=(Expr b) { return *this = *this * b; }
Expr& Expr::operator/=(Expr b) { return *this = *this / b; }

}  // namespace pdgen

// The user-facing scalar expression handle and its arithmetic.
//
// Building an expression applies only cheap, always-valid rewrites: constant
// folding, neutral and absorbing elements, flattening and canonical ordering of
// sums and products, merging of like terms (2x + 3x -> 5x) and like factors
// (x * x^-1 -> 1, x * x -> x^2). Anything heavier is a separate pass.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "pdgen/context.hpp"

namespace pdgen {

// Thrown when a constant is, or folds to, NaN or infinity (sqrt(-1), log(-1), 1/(r-r)).
struct NonFiniteConstant : std::domain_error {
  explicit NonFiniteConstant(const std::string& what) : std::domain_error("constant folding: " + what) {}
};

class Expr {
 public:
  Expr() : id_(constant_id(0.0)) {}
  Expr(double v) : id_(constant_id(v)) {}  // NOLINT: numbers convert implicitly
  Expr(int v) : id_(constant_id(v)) {}     // NOLINT
  static Expr from_id(NodeId id) { return Expr(id, 0); }

  NodeId id() const { return id_; }
  const Node& node() const { return Context::global().node(id_); }
  Op op() const { return node().op; }
  bool is_const() const { return op() == Op::Const; }
  bool is_const(double v) const { return is_const() && node().value == v; }
  double value() const { return node().value; }

  friend bool operator==(Expr a, Expr b) { return a.id_ == b.id_; }
  friend bool operator!=(Expr a, Expr b) { return a.id_ != b.id_; }

  Expr& operator+=(Expr b);
  Expr& operator-=(Expr b);
  Expr& operator*=(Expr b);
  Expr& operator/=(Expr b);

 private:
  Expr(NodeId id, int) : id_(id) {}
  static NodeId constant_id(double v);
  NodeId id_;
};

// A new symbol of the given kind. Two calls create two distinct symbols.
Expr symbol(const std::string& name, SymbolKind kind = SymbolKind::Free);
// The symbol index of a Symbol expression (throws otherwise).
int symbol_index(Expr e);

Expr operator+(Expr a, Expr b);
Expr operator-(Expr a, Expr b);
Expr operator*(Expr a, Expr b);
Expr operator/(Expr a, Expr b);
Expr operator-(Expr a);

Expr add(const std::vector<Expr>& terms);
Expr mul(const std::vector<Expr>& factors);
Expr pow(Expr base, double exponent);
Expr sqrt(Expr x);
Expr exp(Expr x);
Expr log(Expr x);
Expr abs(Expr x);
Expr sign(Expr x);
// a if c > 0, else b.
Expr select(Expr c, Expr a, Expr b);
Expr max(Expr a, Expr b);
Expr min(Expr a, Expr b);

}  // namespace pdgen

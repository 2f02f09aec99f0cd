// Lowering of canonical expression nodes (n-ary sums and products with constant
// exponents) to binary C++-shaped operations.
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "emit/lir.hpp"

namespace pdgen::lir {

namespace {
const pdgen::Node& enode(NodeId id) { return Context::global().node(id); }
}  // namespace

int Graph::make(Kind kind, double value, std::string text, std::vector<int> args) {
  if (value == 0.0) value = 0.0;
  auto key = std::make_tuple(kind, value, text, args);
  if (auto it = table_.find(key); it != table_.end()) return it->second;
  bool per_bond = false;
  for (int a : args) per_bond = per_bond || nodes_[static_cast<std::size_t>(a)].per_bond;
  nodes_.push_back(Node{kind, value, std::move(text), std::move(args), per_bond});
  const int id = static_cast<int>(nodes_.size()) - 1;
  table_.emplace(std::move(key), id);
  return id;
}

int Graph::chain(Kind kind, const std::vector<int>& items) {
  int acc = items.front();
  for (std::size_t i = 1; i < items.size(); ++i) acc = make(kind, 0.0, "", {acc, items[i]});
  return acc;
}

int Graph::integer_power(int base, int n) {
  if (n == 1) return base;
  if (n % 2 == 0) {
    const int h = integer_power(base, n / 2);
    return make(Kind::Mul, 0.0, "", {h, h});
  }
  return make(Kind::Mul, 0.0, "", {integer_power(base, n - 1), base});
}

// base^e for e > 0: an integer part as products and at most one call for the
// fractional part (sqrt for 1/2), so x^1.5 and x^-0.5 share one sqrt(x).
int Graph::positive_power(int base, double e) {
  const double whole = std::floor(e);
  const double frac = e - whole;
  std::vector<int> parts;
  if (whole > 0) parts.push_back(integer_power(base, static_cast<int>(whole)));
  if (frac == 0.5)
    parts.push_back(make(Kind::Call, 0.0, "std::sqrt", {base}));
  else if (frac > 0.0)
    parts.push_back(make(Kind::Call, 0.0, "std::pow", {base, constant(frac)}));
  return chain(Kind::Mul, parts);
}

// Factors are ordered per-family first, then by decreasing node id, so that the
// components of a vector (x_c last) share the product of everything else.
int Graph::product(double coefficient, const std::vector<NodeId>& factors) {
  std::vector<std::pair<int, NodeId>> num, den;  // (lowered factor, expression id of its base)
  for (NodeId f : factors) {
    const pdgen::Node& n = enode(f);
    if (n.op == Op::Pow) {
      const int base = lower(Expr::from_id(n.args[0]));
      const double e = std::fabs(n.value);
      if (n.value < 0 && (e == std::floor(e) || e - std::floor(e) == 0.5)) {
        // b^-k as (1/b)^k and b^-(k+1/2) as (1/b)^k / sqrt(b): at most two divisions per
        // distinct base, shared by every product that divides by it (hash-consing) and
        // hoisted with it when b is per family. Dividing by each product separately cost
        // Silling's tangent 9 divisions per bond.
        const int whole = static_cast<int>(std::floor(e));
        std::vector<int> parts;
        if (whole > 0) parts.push_back(integer_power(make(Kind::Div, 0.0, "", {constant(1.0), base}), whole));
        if (e != whole)
          parts.push_back(
              make(Kind::Div, 0.0, "", {constant(1.0), make(Kind::Call, 0.0, "std::sqrt", {base})}));
        num.push_back({chain(Kind::Mul, parts), n.args[0]});
      } else {
        (n.value > 0 ? num : den).push_back({positive_power(base, e), n.args[0]});
      }
    } else {
      num.push_back({lower(Expr::from_id(f)), f});
    }
  }
  // Inputs are created before anything built from them, so decreasing expression id
  // puts vector components (Y_c, xi_c) last.
  auto order = [&](std::vector<std::pair<int, NodeId>>& v) {
    std::stable_sort(v.begin(), v.end(), [&](auto a, auto b) {
      const bool pa = node(a.first).per_bond, pb = node(b.first).per_bond;
      if (pa != pb) return !pa;
      return a.second > b.second;
    });
  };
  order(num);
  order(den);
  std::vector<int> n_items, d_items;
  const double mag = std::fabs(coefficient);
  if (mag != 1.0) n_items.push_back(constant(mag));
  for (auto& p : num) n_items.push_back(p.first);
  for (auto& p : den) d_items.push_back(p.first);
  if (n_items.empty()) n_items.push_back(constant(1.0));
  int r = 0;
  if (d_items.empty()) {
    r = chain(Kind::Mul, n_items);
  } else if (n_items.size() == 1) {
    r = make(Kind::Div, 0.0, "", {n_items[0], chain(Kind::Mul, d_items)});
  } else {
    // (a b / d) c: the quotient is shared by the components that differ only in c.
    const int last = n_items.back();
    n_items.pop_back();
    r = make(Kind::Mul, 0.0, "",
             {make(Kind::Div, 0.0, "", {chain(Kind::Mul, n_items), chain(Kind::Mul, d_items)}), last});
  }
  return coefficient < 0 ? make(Kind::Neg, 0.0, "", {r}) : r;
}

int Graph::sum(const std::vector<NodeId>& terms) {
  std::vector<int> pos, neg;
  for (NodeId t : terms) {
    const pdgen::Node& n = enode(t);
    if (n.op == Op::Const) {
      (n.value >= 0 ? pos : neg).push_back(constant(std::fabs(n.value)));
    } else if (n.op == Op::Mul && enode(n.args[0]).op == Op::Const && enode(n.args[0]).value < 0) {
      neg.push_back(product(-enode(n.args[0]).value, std::vector<NodeId>(n.args.begin() + 1, n.args.end())));
    } else {
      pos.push_back(lower(Expr::from_id(t)));
    }
  }
  int r = pos.empty() ? make(Kind::Neg, 0.0, "", {neg.front()}) : chain(Kind::Add, pos);
  for (std::size_t i = pos.empty() ? 1 : 0; i < neg.size(); ++i) r = make(Kind::Sub, 0.0, "", {r, neg[i]});
  return r;
}

int Graph::lower(Expr e) {
  if (auto it = memo_.find(e.id()); it != memo_.end()) return it->second;
  const pdgen::Node n = e.node();
  int r = -1;
  switch (n.op) {
    case Op::Const:
      r = n.value < 0 ? make(Kind::Neg, 0.0, "", {constant(-n.value)}) : constant(n.value);
      break;
    case Op::Symbol: {
      auto it = bindings_.find(n.symbol);
      if (it == bindings_.end()) {
        const SymbolInfo& info = Context::global().symbol(n.symbol);
        if (info.kind == SymbolKind::Free)
          throw std::invalid_argument(
              "symbol '" + info.name +
              "' is not an input of the law (a parameter is declared with law.param(\"" + info.name +
              "\"), a horizon sum with law.sum)");
        throw std::logic_error("emit: symbol '" + info.name + "' has no binding in this kernel");
      }
      r = make(Kind::Var, 0.0, it->second.var, {});
      nodes_[static_cast<std::size_t>(r)].per_bond = it->second.per_bond;
      var_symbol_[r] = n.symbol;
      break;
    }
    case Op::Add:
      r = sum(n.args);
      break;
    case Op::Mul: {
      const bool has_coef = enode(n.args[0]).op == Op::Const;
      r = product(has_coef ? enode(n.args[0]).value : 1.0,
                  std::vector<NodeId>(n.args.begin() + (has_coef ? 1 : 0), n.args.end()));
      break;
    }
    case Op::Pow:
      r = product(1.0, {e.id()});
      break;
    case Op::Exp:
      r = make(Kind::Call, 0.0, "std::exp", {lower(Expr::from_id(n.args[0]))});
      break;
    case Op::Log:
      r = make(Kind::Call, 0.0, "std::log", {lower(Expr::from_id(n.args[0]))});
      break;
    case Op::Abs:
      r = make(Kind::Call, 0.0, "std::fabs", {lower(Expr::from_id(n.args[0]))});
      break;
    case Op::Sign: {
      const int x = lower(Expr::from_id(n.args[0]));
      const int negative =
          make(Kind::Select, 0.0, "",
               {make(Kind::Neg, 0.0, "", {x}), make(Kind::Neg, 0.0, "", {constant(1.0)}), constant(0.0)});
      r = make(Kind::Select, 0.0, "", {x, constant(1.0), negative});
      break;
    }
    case Op::Select:
      r = make(Kind::Select, 0.0, "",
               {lower(Expr::from_id(n.args[0])), lower(Expr::from_id(n.args[1])),
                lower(Expr::from_id(n.args[2]))});
      break;
  }
  memo_[e.id()] = r;
  return r;
}

}  // namespace pdgen::lir

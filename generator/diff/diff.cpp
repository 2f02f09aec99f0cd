// One derivative rule per operation (switch over ops.def), memoised.
#include "pdgen/diff.hpp"

#include <algorithm>
#include <map>
#include <stdexcept>

namespace pdgen {

namespace {
Context& ctx() { return Context::global(); }
Expr arg(const Node& n, std::size_t i) { return Expr::from_id(n.args[i]); }

std::map<std::pair<NodeId, int>, NodeId>& diff_memo() {
  static std::map<std::pair<NodeId, int>, NodeId> memo;
  return memo;
}
std::map<NodeId, std::vector<int>>& symbols_memo() {
  static std::map<NodeId, std::vector<int>> memo;
  return memo;
}

Expr diff_node(Expr e, int s);

Expr diff_id(NodeId id, int s) {
  auto& memo = diff_memo();
  const auto key = std::make_pair(id, s);
  if (auto it = memo.find(key); it != memo.end()) return Expr::from_id(it->second);
  const auto& syms = free_symbols(Expr::from_id(id));
  const Expr d =
      std::binary_search(syms.begin(), syms.end(), s) ? diff_node(Expr::from_id(id), s) : Expr(0.0);
  memo[key] = d.id();
  return d;
}

Expr diff_node(Expr e, int s) {
  const Node n = e.node();  // copy: differentiation interns new nodes
  switch (n.op) {
    case Op::Const:
      return Expr(0.0);
    case Op::Symbol:
      return Expr(n.symbol == s ? 1.0 : 0.0);
    case Op::Add: {
      std::vector<Expr> t;
      for (NodeId a : n.args) t.push_back(diff_id(a, s));
      return add(t);
    }
    case Op::Mul: {
      // Product rule over the n-ary product.
      std::vector<Expr> t;
      for (std::size_t i = 0; i < n.args.size(); ++i) {
        const Expr di = diff_id(n.args[i], s);
        if (di.is_const(0.0)) continue;
        std::vector<Expr> f{di};
        for (std::size_t j = 0; j < n.args.size(); ++j)
          if (j != i) f.push_back(arg(n, j));
        t.push_back(mul(f));
      }
      return add(t);
    }
    case Op::Pow:
      return mul({Expr(n.value), pow(arg(n, 0), n.value - 1.0), diff_id(n.args[0], s)});
    case Op::Exp:
      return e * diff_id(n.args[0], s);
    case Op::Log:
      return diff_id(n.args[0], s) / arg(n, 0);
    case Op::Abs:
      return sign(arg(n, 0)) * diff_id(n.args[0], s);
    case Op::Sign:
      return Expr(0.0);
    case Op::Select:
      return select(arg(n, 0), diff_id(n.args[1], s), diff_id(n.args[2], s));
  }
  throw std::logic_error("diff: unknown operation");
}
}  // namespace

Expr diff(Expr e, Expr s) { return diff_id(e.id(), symbol_index(s)); }

const std::vector<int>& symbols_of(NodeId id) {
  auto& memo = symbols_memo();
  if (auto it = memo.find(id); it != memo.end()) return it->second;
  const Node n = ctx().node(id);
  std::vector<int> out;
  if (n.op == Op::Symbol) out.push_back(n.symbol);
  for (NodeId a : n.args) {
    const auto& sa = symbols_of(a);
    std::vector<int> merged;
    std::set_union(out.begin(), out.end(), sa.begin(), sa.end(), std::back_inserter(merged));
    out.swap(merged);
  }
  return memo[id] = out;
}

std::vector<int> free_symbols(Expr e) { return symbols_of(e.id()); }

namespace {
Expr substitute_id(NodeId id, const std::unordered_map<int, Expr>& map,
                   std::unordered_map<NodeId, NodeId>& memo) {
  if (auto it = memo.find(id); it != memo.end()) return Expr::from_id(it->second);
  const Node n = ctx().node(id);
  Expr out;
  std::vector<Expr> a;
  for (NodeId x : n.args) a.push_back(substitute_id(x, map, memo));
  switch (n.op) {
    case Op::Const:
      out = Expr::from_id(id);
      break;
    case Op::Symbol: {
      auto it = map.find(n.symbol);
      out = it == map.end() ? Expr::from_id(id) : it->second;
      break;
    }
    case Op::Add:
      out = add(a);
      break;
    case Op::Mul:
      out = mul(a);
      break;
    case Op::Pow:
      out = pow(a[0], n.value);
      break;
    case Op::Exp:
      out = exp(a[0]);
      break;
    case Op::Log:
      out = log(a[0]);
      break;
    case Op::Abs:
      out = abs(a[0]);
      break;
    case Op::Sign:
      out = sign(a[0]);
      break;
    case Op::Select:
      out = select(a[0], a[1], a[2]);
      break;
  }
  memo[id] = out.id();
  return out;
}
}  // namespace

Expr substitute(Expr e, const std::unordered_map<int, Expr>& map) {
  std::unordered_map<NodeId, NodeId> memo;
  return substitute_id(e.id(), map, memo);
}

}  // namespace pdgen

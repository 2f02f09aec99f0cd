// The low-level IR between the expression DAG and C++ text: binary arithmetic,
// division and negation made explicit, powers expanded (integer powers as products,
// one sqrt or pow call per base), hash-consed so that equal code is one node.
#pragma once

#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "pdgen/kernel_program.hpp"

namespace pdgen::lir {

enum class Kind { Const, Var, Add, Sub, Mul, Div, Neg, Call, Select };

struct Node {
  Kind kind = Kind::Const;
  double value = 0.0;  // Const
  std::string text;    // Var: variable name; Call: function name
  std::vector<int> args;
  bool per_bond = false;  // depends on a per-bond input
};

class Graph {
 public:
  explicit Graph(const std::map<int, Binding>& bindings) : bindings_(bindings) {}
  // Lowers an expression, memoised by expression node.
  int lower(Expr e);
  const Node& node(int id) const { return nodes_[static_cast<std::size_t>(id)]; }
  int size() const { return static_cast<int>(nodes_.size()); }
  // The symbols each Var node stands for (by Var id).
  const std::map<int, int>& var_symbols() const { return var_symbol_; }

 private:
  int make(Kind kind, double value, std::string text, std::vector<int> args);
  int constant(double v) { return make(Kind::Const, v, "", {}); }
  int product(double coefficient, const std::vector<NodeId>& factors);
  int sum(const std::vector<NodeId>& terms);
  int positive_power(int base, double e);
  int integer_power(int base, int n);
  int chain(Kind kind, const std::vector<int>& items);

  const std::map<int, Binding>& bindings_;
  std::vector<Node> nodes_;
  std::map<std::tuple<Kind, double, std::string, std::vector<int>>, int> table_;
  std::map<NodeId, int> memo_;
  std::map<int, int> var_symbol_;
};

}  // namespace pdgen::lir

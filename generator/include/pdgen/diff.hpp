// Symbolic differentiation, substitution and dependency queries over the DAG.
#pragma once

#include <unordered_map>

#include "pdgen/expr.hpp"

namespace pdgen {

// d e / d s, where s is a Symbol expression. Memoised per (node, symbol) for the
// life of the process, so shared subexpressions are differentiated once.
Expr diff(Expr e, Expr s);

// e with every symbol in `map` (symbol index -> replacement) replaced, rebuilt
// through the canonicalising builders so the result is simplified again.
Expr substitute(Expr e, const std::unordered_map<int, Expr>& map);

// True when e depends on any symbol for which pred(symbol index) is true.
template <class Pred>
bool depends_on(Expr e, Pred pred);

// The symbol indices e depends on, ascending.
std::vector<int> free_symbols(Expr e);

template <class Pred>
bool depends_on(Expr e, Pred pred) {
  for (int s : free_symbols(e))
    if (pred(s)) return true;
  return false;
}

}  // namespace pdgen

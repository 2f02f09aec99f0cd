// A double-precision interpreter of the expression DAG: the test oracle.
#pragma once

#include <unordered_map>

#include "pdgen/expr.hpp"

namespace pdgen {

// Values of symbols by symbol index. Throws when e needs a symbol not given.
double evaluate(Expr e, const std::unordered_map<int, double>& values);

}  // namespace pdgen

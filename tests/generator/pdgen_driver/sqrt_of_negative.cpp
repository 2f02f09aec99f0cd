// A law whose constant folds to NaN: sqrt(-1).
#include "pdgen/dsl.hpp"

using namespace pdgen;

PDGEN_LAW(sqrt_of_negative) {
  Law law("sqrt_of_negative", 2, "bad: sqrt(-1)");
  law.force(sqrt(Expr(-1.0)) * law.Y());
  return law;
}

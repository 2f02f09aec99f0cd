// A law whose constant folds to infinity: 1 / (r - r).
#include "pdgen/dsl.hpp"

using namespace pdgen;

PDGEN_LAW(one_over_zero) {
  Law law("one_over_zero", 2, "bad: 1/(r-r)");
  const Expr r = norm(law.xi());
  law.force(1 / (r - r) * law.Y());
  return law;
}

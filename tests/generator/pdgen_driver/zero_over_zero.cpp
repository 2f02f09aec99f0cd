// A law whose constant folds to NaN: (r - r) / (r - r).
#include "pdgen/dsl.hpp"

using namespace pdgen;

PDGEN_LAW(zero_over_zero) {
  Law law("zero_over_zero", 2, "bad: (r-r)/(r-r)");
  const Expr r = norm(law.xi());
  law.force((r - r) / (r - r) * law.Y());
  return law;
}

// A law with a NaN literal that later arithmetic would hide: NaN * 0 + 2.
#include <cmath>

#include "pdgen/dsl.hpp"

using namespace pdgen;

PDGEN_LAW(nan_literal) {
  Law law("nan_literal", 2, "bad: NaN*0+2");
  law.force((Expr(std::nan("")) * 0 + 2) * law.Y());
  return law;
}

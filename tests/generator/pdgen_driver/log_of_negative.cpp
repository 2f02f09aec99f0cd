// A law whose constant folds to NaN: log(-1).
#include "pdgen/dsl.hpp"

using namespace pdgen;

PDGEN_LAW(log_of_negative) {
  Law law("log_of_negative", 2, "bad: log(-1)");
  law.force(log(Expr(-1.0)) * law.Y());
  return law;
}

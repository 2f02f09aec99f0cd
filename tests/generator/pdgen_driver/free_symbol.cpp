// A law that uses a free symbol instead of declaring a parameter.
#include "pdgen/dsl.hpp"

using namespace pdgen;

PDGEN_LAW(free_symbol) {
  Law law("free_symbol", 2, "bad: free symbol beta");
  law.force(symbol("beta") * law.Y());
  return law;
}

// Influence functions w(r, delta), r = |xi|, delta the true horizon of the scene.
// Paper 000 section 3 names const, inv, linear, quadr, cubic and quarticA; the
// rational family (1 - r/delta)^a / r^n covers a, n in {0, 1, 2}.
// Add one by writing one PDGEN_INFLUENCE(name, "formula") { return ...; }.
#include "pdgen/dsl.hpp"

using namespace pdgen;

PDGEN_INFLUENCE(const, "1") { return Expr(1.0); }
PDGEN_INFLUENCE(inv, "delta / r") { return delta / r; }
PDGEN_INFLUENCE(linear, "1 - r/delta") { return 1 - r / delta; }
PDGEN_INFLUENCE(quadr, "(1 - r/delta)^2") { return pow(1 - r / delta, 2); }
PDGEN_INFLUENCE(cubic, "(1 - r/delta)^3") { return pow(1 - r / delta, 3); }
PDGEN_INFLUENCE(quarticA, "1 - 6 rho^2 + 8 rho^3 - 3 rho^4, rho = r/delta") {
  const Expr rho = r / delta;
  return 1 - 6 * pow(rho, 2) + 8 * pow(rho, 3) - 3 * pow(rho, 4);
}

#define PD_RATIONAL(a, n)                                                 \
  PDGEN_INFLUENCE(rational_a##a##_n##n, "(1 - r/delta)^" #a " / r^" #n) { \
    return pow(1 - r / delta, a) / pow(r, n);                             \
  }
PD_RATIONAL(0, 0)
PD_RATIONAL(0, 1)
PD_RATIONAL(0, 2)
PD_RATIONAL(1, 0)
PD_RATIONAL(1, 1)
PD_RATIONAL(1, 2)
PD_RATIONAL(2, 0)
PD_RATIONAL(2, 1)
PD_RATIONAL(2, 2)

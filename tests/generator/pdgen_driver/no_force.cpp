// A law that never calls law.force().
#include "pdgen/dsl.hpp"

using namespace pdgen;

PDGEN_LAW(no_force) {
  Law law("no_force", 2, "bad: no force state");
  law.energy(law.sum("e", law.w() * dot(law.Y(), law.Y())));
  return law;
}

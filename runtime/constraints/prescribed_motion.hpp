// The prescribed motion of a dynamic run's constrained dofs, kept on the DofMap: each
// constrained dof's kind and function of time f (a copy of its condition's `time`, or
// none: f = 1). With the dof's value a at full load (DofMap::prescribed):
//   fixed:                  u = 0,            v = 0
//   displacement or field:  u = a f(t),       v = a f'(t)   (no function: u = a, v = 0)
//   velocity:               u = a int_0^t f,  v = a f(t)    (no function: u = a t, v = a)
#pragma once

#include <vector>

#include "input/time_function.hpp"

namespace pd {

struct PrescribedMotion {
  enum class Kind : unsigned char { fixed, displacement, velocity };
  std::vector<Kind> kind;     // per constrained dof, in DofMap::constrained_dofs order
  std::vector<int> function;  // index into `functions`, -1 for none
  std::vector<TimeFunction> functions;
  bool empty() const { return kind.empty(); }
};

}  // namespace pd

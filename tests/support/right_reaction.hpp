// The x reaction on a body's right column after a run: minus the internal forces of its
// particles (the bar tests pull the right end by a prescribed displacement).
#pragma once

#include <algorithm>
#include <vector>

#include "run/simulation.hpp"

namespace pd::test {

inline double right_reaction(const pd::Simulation& sim) {
  const pd::Particles& P = sim.particles();
  std::vector<double> f(static_cast<std::size_t>(P.size() * P.dim));
  sim.assembler().assemble(sim.displacement().data(), f.data(), nullptr);
  double x_max = -1e300;
  for (int p = 0; p < P.size(); ++p) x_max = std::max(x_max, P.x[static_cast<std::size_t>(p * P.dim)]);
  double r = 0;
  for (int p = 0; p < P.size(); ++p)
    if (P.x[static_cast<std::size_t>(p * P.dim)] > x_max - 1e-9) r -= f[static_cast<std::size_t>(p * P.dim)];
  return r;
}

}  // namespace pd::test

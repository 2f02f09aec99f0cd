// Kinetic energy and the trapezoidal external work.
#include "dynamics/energies.hpp"

namespace pd {

double kinetic_energy(const std::vector<double>& mass, const std::vector<double>& v,
                      const std::vector<int>& dofs) {
  double e = 0;
  for (int i : dofs) e += mass[i] * v[i] * v[i];
  return 0.5 * e;
}

void ExternalWork::add(const std::vector<double>& g_old, const std::vector<double>& g_new,
                       const std::vector<double>& u_old, const std::vector<double>& u_new) {
  double dw = 0;
  for (std::size_t i = 0; i < u_new.size(); ++i) dw += 0.5 * (g_old[i] + g_new[i]) * (u_new[i] - u_old[i]);
  w_ += dw;
}

}  // namespace pd

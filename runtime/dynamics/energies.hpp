// Energies of a dynamic run: kinetic, strain (from the law's energy kernel, when the law
// has one) and the external work, accumulated with the trapezoidal rule.
#pragma once

#include <vector>

namespace pd {

// (1/2) sum_i m_i v_i^2 over the listed dofs.
double kinetic_energy(const std::vector<double>& mass, const std::vector<double>& v,
                      const std::vector<int>& dofs);

// W += (1/2) (g_old + g_new) . (u_new - u_old): the work of the external forces g (loads
// on free dofs, reactions on constrained ones) over one step.
class ExternalWork {
 public:
  void add(const std::vector<double>& g_old, const std::vector<double>& g_new,
           const std::vector<double>& u_old, const std::vector<double>& u_new);
  double value() const { return w_; }
  void restore(double w) { w_ = w; }

 private:
  double w_ = 0;
};

}  // namespace pd

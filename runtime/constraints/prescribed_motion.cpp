// DofMap::apply_motion: the constrained dofs' displacement and velocity at time t.
#include <stdexcept>

#include "constraints/dof_map.hpp"

namespace pd {

void DofMap::apply_motion(double t, std::vector<double>& u, std::vector<double>& v) const {
  using K = PrescribedMotion::Kind;
  if (motion_.kind.size() != constrained_.size())
    throw std::logic_error("DofMap::apply_motion: no prescribed motion set");
  for (std::size_t i = 0; i < constrained_.size(); ++i) {
    const int f = motion_.function[i];
    const TimeFunction* tf = f < 0 ? nullptr : &motion_.functions[static_cast<std::size_t>(f)];
    const double value = prescribed_[i];
    double x = 0, rate = 0;
    if (motion_.kind[i] == K::velocity) {
      x = value * (tf ? tf->integral(t) : t);
      rate = value * (tf ? tf->value_at(t) : 1.0);
    } else if (motion_.kind[i] != K::fixed) {
      x = value * (tf ? tf->value_at(t) : 1.0);
      rate = value * (tf ? tf->derivative(t) : 0.0);
    }
    u[static_cast<std::size_t>(constrained_[i])] = x;
    if (!v.empty()) v[static_cast<std::size_t>(constrained_[i])] = rate;
  }
  // A fictitious layer follows the body (and the constrained values just set): its
  // offsets are applied in full (the reader refuses a time function on a layer).
  apply_ties(u.data(), 1.0);
  for (const TiedDof& tie : ties_) {
    if (v.empty()) break;
    double rate = 0;
    for (std::size_t k = 0; k < tie.masters.size(); ++k)
      rate += tie.coefficients[k] * v[static_cast<std::size_t>(tie.masters[k])];
    v[static_cast<std::size_t>(tie.dof)] = rate;
  }
}

}  // namespace pd

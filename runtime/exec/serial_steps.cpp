// The serial step executor (serial_steps.hpp).
#include "exec/serial_steps.hpp"

#include <cmath>
#include <stdexcept>

#include "interrupt.hpp"

namespace pd {

void SerialSteps::forces(double t, std::vector<double>& f, std::vector<double>& g) {
  const Model& model = s_.model;
  f.resize(s_.u.size());
  g.assign(s_.u.size(), 0.0);
  model.assembler->internal_forces(s_.u.data(), f.data());
  // Each load at its time function's value (effects/timed_effect.cpp); relaxation has no
  // time functions (the reader refuses them), so its loads are in full. Inertia and
  // damping add no force here.
  for (const auto& e : model.effects) e->add_forces(s_.u.data(), t, g.data());
  for (std::size_t i = 0; i < f.size(); ++i) f[i] += g[i];
  // The reaction of a constraint, R = -(f_int + load), plus the load there: -f_int.
  for (int i : model.dofs.constrained_dofs()) g[i] = g[i] - f[i];
}

bool SerialSteps::after_step() {
  long long changes = 0;
  for (const auto& e : s_.model.effects) changes += e->after_step(s_.u.data(), FamilyScope{});
  return changes > 0;
}

double SerialSteps::free_square_sum(const std::vector<double>& values) const {
  double s = 0;
  for (int i : free_dofs()) s += values[i] * values[i];
  return s;
}

void SerialSteps::check_interrupt(const std::string& where) const {
  if (interrupt_signal() != 0) throw_if_interrupted(where);
}

void SerialSteps::check_finite(const std::string& message) const {
  for (double x : s_.u)
    if (!std::isfinite(x)) throw std::runtime_error(message);
}

}  // namespace pd

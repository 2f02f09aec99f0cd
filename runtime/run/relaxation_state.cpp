// The relaxation loops' reference force and checkpoint scalars (relaxation_state.hpp).
#include "run/relaxation_state.hpp"

#include <algorithm>
#include <stdexcept>

namespace pd {

double relaxation_reference(const Model& model, const std::vector<double>& u, const std::vector<double>& f,
                            const std::function<double(const std::vector<double>&)>& norm) {
  double reference = norm(f);
  for (const auto& e : model.effects) {
    if (!e->is_load()) continue;
    std::vector<double> load(u.size(), 0.0);
    e->add_forces(u.data(), 0.0, load.data());
    reference = std::max(reference, norm(load));
  }
  return reference == 0 ? 1 : reference;
}

namespace {
constexpr std::size_t kHead = 3;
}

std::vector<double> relaxation_scalars(const RelaxationRestart& state) {
  std::vector<double> scalars{static_cast<double>(state.iterations), state.reference,
                              static_cast<double>(state.broken_start)};
  scalars.insert(scalars.end(), state.v.begin(), state.v.end());
  scalars.insert(scalars.end(), state.f_prev.begin(), state.f_prev.end());
  return scalars;
}

RelaxationRestart relaxation_restart(const std::vector<double>& scalars, std::size_t N,
                                     const std::string& file) {
  if (scalars.size() != kHead + 2 * N)
    throw std::runtime_error(file + ": not a relaxation checkpoint of this scene");
  const auto v_begin = scalars.begin() + kHead, f_begin = v_begin + static_cast<std::ptrdiff_t>(N);
  RelaxationRestart state;
  state.iterations = static_cast<int>(scalars[0]);
  state.reference = scalars[1];
  state.broken_start = static_cast<long long>(scalars[2]);
  state.v.assign(v_begin, f_begin);
  state.f_prev.assign(f_begin, scalars.end());
  return state;
}

}  // namespace pd

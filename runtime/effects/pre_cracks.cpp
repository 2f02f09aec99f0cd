// The scene's pre-cracks as an effect: the bonds they cut stay broken (alpha = 0) and the
// kernels read alpha. It adds no force; it is listed so the run log and summary.json
// name every effect the model holds.
#include <fmt/core.h>

#include "effects/loads.hpp"

namespace pd {

namespace {
class PreCracks final : public Effect {
 public:
  explicit PreCracks(long long cut) : cut_(cut) {}
  std::string name() const override { return "pre-cracks"; }
  std::string describe() const override { return fmt::format("broken bonds: {} cut by cracks", cut_); }

 private:
  long long cut_;
};
}  // namespace

std::unique_ptr<Effect> make_pre_cracks(long long cut_bonds) {
  return cut_bonds > 0 ? std::make_unique<PreCracks>(cut_bonds) : nullptr;
}

}  // namespace pd

// A load of a dynamic run scaled by its own function of time: the inner effect at
// f(t) (the driver passes t where a static run passes the load factor). Forces only:
// the dynamic drivers form no tangent.
#include "effects/loads.hpp"

namespace pd {

namespace {
class TimedEffect final : public Effect {
 public:
  TimedEffect(std::unique_ptr<Effect> inner, TimeFunction time, std::string suffix)
      : inner_(std::move(inner)), time_(std::move(time)), suffix_(std::move(suffix)) {}
  std::string name() const override { return inner_->name(); }
  std::string describe() const override { return inner_->describe() + suffix_; }
  std::size_t allocated_bytes() const override { return inner_->allocated_bytes(); }
  bool is_load() const override { return inner_->is_load(); }
  void add_forces(const double* u, double t, double* r) const override {
    inner_->add_forces(u, time_.value_at(t), r);
  }

 private:
  std::unique_ptr<Effect> inner_;
  TimeFunction time_;
  std::string suffix_;
};
}  // namespace

std::unique_ptr<Effect> make_timed(std::unique_ptr<Effect> inner, TimeFunction time, std::string suffix) {
  return std::make_unique<TimedEffect>(std::move(inner), std::move(time), std::move(suffix));
}

}  // namespace pd

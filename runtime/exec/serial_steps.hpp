// The serial step executor: this process holds the whole body, so its steps are the
// model's own (every family, every dof) and its sums, gathers and syncs do nothing.
#pragma once

#include "exec/step_executor.hpp"

namespace pd {

class SerialSteps final : public StepExecutor {
 public:
  explicit SerialSteps(StepState state) : s_(state) {}
  bool root() const override { return true; }
  const std::vector<int>& free_dofs() const override { return s_.model.dofs.free_dofs(); }
  std::string describe(const std::string&, const std::string&, const std::string&) const override {
    return {};
  }
  void forces(double t, std::vector<double>& f, std::vector<double>& g) override;
  bool after_step() override;
  void commit_history() override { s_.model.commit_history(s_.u.data()); }
  void sync() override {}
  void gather(const std::vector<std::vector<double>*>&) override {}
  double sum(double local) const override { return local; }
  void sum_in_place(double*, int) const override {}
  double free_square_sum(const std::vector<double>& values) const override;
  void check_agrees(double, const std::string&) const override {}
  void check_interrupt(const std::string& where) const override;
  void check_finite(const std::string& message) const override;

 private:
  StepState s_;
};

}  // namespace pd

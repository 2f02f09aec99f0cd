// Progress lines with the remaining time extrapolated from the steps done so far.
#include "dynamics/progress.hpp"

#include <fmt/core.h>

namespace pd {

Progress::Progress(std::function<void(const std::string&)> log, double interval_seconds, int first_step,
                   int last_step)
    : log_(std::move(log)),
      interval_(interval_seconds),
      first_(first_step),
      last_(last_step),
      start_(std::chrono::steady_clock::now()),
      last_print_(start_) {}

void Progress::update(int step, double time, const std::string& extra) {
  if (interval_ <= 0 || !log_) return;
  const auto now = std::chrono::steady_clock::now();
  if (step != last_ && std::chrono::duration<double>(now - last_print_).count() < interval_) return;
  last_print_ = now;
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const int done = step - first_, total = last_ - first_;
  const double left = done > 0 ? elapsed * (total - done) / done : 0.0;
  log_(fmt::format("  step {}/{} ({:.0f}%) t = {:.6g}  elapsed {:.1f} s, about {:.1f} s left{}", step, last_,
                   total > 0 ? 100.0 * done / total : 100.0, time, elapsed, left, extra));
}

}  // namespace pd

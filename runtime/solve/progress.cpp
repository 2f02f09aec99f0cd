// The progress watchdog: one thread per long phase, asleep on a condition variable.
#include "solve/progress.hpp"

#include <fmt/format.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <mutex>
#include <thread>

namespace pd {

namespace {
thread_local ProgressLog sink_log;
thread_local double sink_interval = 5.0;
}  // namespace

struct ProgressPhase::State {
  std::string what;
  ProgressLog log;
  double interval = 5.0;
  std::mutex m;
  std::condition_variable done_cv;
  bool done = false;
  bool reported = false;
  std::atomic<int> iteration{-1};
  std::atomic<double> residual{0.0};
  std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
  std::thread watchdog;
  State* previous = nullptr;  // the enclosing phase, innermost again when this one ends
};

namespace {
thread_local ProgressPhase::State* innermost = nullptr;
}  // namespace

ProgressSink::ProgressSink(ProgressLog log, double interval_seconds)
    : previous_log_(std::move(sink_log)), previous_interval_(sink_interval) {
  sink_log = std::move(log);
  sink_interval = interval_seconds;
}

ProgressSink::~ProgressSink() {
  sink_log = std::move(previous_log_);
  sink_interval = previous_interval_;
}

ProgressPhase::ProgressPhase(std::string what) {
  if (!sink_log) return;
  state_ = std::make_shared<State>();
  state_->what = std::move(what);
  state_->log = sink_log;
  state_->interval = sink_interval;
  state_->previous = innermost;
  innermost = state_.get();
  state_->watchdog = std::thread([s = state_] {
    std::unique_lock lock(s->m);
    const auto period = std::chrono::duration<double>(s->interval);
    for (int k = 1;; ++k) {
      if (s->done_cv.wait_until(
              lock, s->start + k * std::chrono::duration_cast<std::chrono::steady_clock::duration>(period),
              [&] { return s->done; }))
        return;
      const double seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - s->start).count();
      std::string line = fmt::format("    {}: {:.0f} s so far", s->what, seconds);
      if (const int it = s->iteration.load(); it >= 0)
        line += fmt::format(", iteration {}, |r|/|b| = {:.2e}", it, s->residual.load());
      s->reported = true;
      s->log(line);
    }
  });
}

ProgressPhase::~ProgressPhase() {
  if (!state_) return;
  {
    std::lock_guard lock(state_->m);
    state_->done = true;
  }
  state_->done_cv.notify_all();
  state_->watchdog.join();
  if (innermost == state_.get()) innermost = state_->previous;
  if (state_->reported)
    state_->log(
        fmt::format("    {}: done in {:.1f} s", state_->what,
                    std::chrono::duration<double>(std::chrono::steady_clock::now() - state_->start).count()));
}

void progress_iteration(int iteration, double relative_residual) {
  if (!innermost) return;
  innermost->residual.store(relative_residual, std::memory_order_relaxed);
  innermost->iteration.store(iteration, std::memory_order_relaxed);
}

}  // namespace pd

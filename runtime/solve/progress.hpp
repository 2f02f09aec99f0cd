// Progress from inside one Newton step: a factorisation or a Krylov solve that runs longer
// than a few seconds says so on the log while it runs (issue 21: a long static solve must
// not be silent between its Newton lines).
//
// The Newton solver installs its log as the sink (ProgressSink) for the duration of a
// solve. Each long operation opens a ProgressPhase; a watchdog thread writes a line every
// `interval` seconds while the phase lasts ("    CHOLMOD factorisation of 123456 unknowns:
// 10 s so far"), and a Krylov loop adds its iteration and relative residual to that line
// (progress_iteration). A phase shorter than the interval writes nothing, so short solves
// keep their logs unchanged; a phase that wrote a progress line closes with its time.
#pragma once

#include <functional>
#include <memory>
#include <string>

namespace pd {

using ProgressLog = std::function<void(const std::string&)>;

// Installs `log` for this thread's phases while it lives (the previous sink is restored
// after). interval_seconds: the time between progress lines (default 5 s).
class ProgressSink {
 public:
  explicit ProgressSink(ProgressLog log, double interval_seconds = 5.0);
  ~ProgressSink();
  ProgressSink(const ProgressSink&) = delete;
  ProgressSink& operator=(const ProgressSink&) = delete;

 private:
  ProgressLog previous_log_;
  double previous_interval_;
};

// One long operation, named for the log ("CHOLMOD factorisation of 123456 unknowns").
// Without a sink it does nothing.
class ProgressPhase {
 public:
  explicit ProgressPhase(std::string what);
  ~ProgressPhase();
  ProgressPhase(const ProgressPhase&) = delete;
  ProgressPhase& operator=(const ProgressPhase&) = delete;
  struct State;  // shared with the watchdog thread (progress.cpp)

 private:
  std::shared_ptr<State> state_;
};

// The innermost phase's iteration and relative residual, shown on its next progress line.
void progress_iteration(int iteration, double relative_residual);

}  // namespace pd

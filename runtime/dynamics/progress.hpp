// The progress line of a long run: step, time, fraction done and the estimated time left,
// at most once per interval of wall-clock seconds (0: never).
#pragma once

#include <chrono>
#include <functional>
#include <string>

namespace pd {

class Progress {
 public:
  Progress(std::function<void(const std::string&)> log, double interval_seconds, int first_step,
           int last_step);
  // Logs when the interval has passed since the last line (and always at the last step).
  void update(int step, double time, const std::string& extra = "");

 private:
  std::function<void(const std::string&)> log_;
  double interval_;
  int first_, last_;
  std::chrono::steady_clock::time_point start_, last_print_;
};

}  // namespace pd

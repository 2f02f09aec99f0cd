// Functions of time that scale a boundary condition in a dynamic run
// (docs/scene_format.md, `time_function`): constant, ramp, sine, piecewise-linear table.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace pd {

struct YamlAt;

struct TimeFunction {
  enum class Kind { Constant, Ramp, Sine, Table } kind = Kind::Constant;
  double value = 1;                              // constant: f = value
  double duration = 0;                           // ramp: f = t / duration up to duration, then 1
  double period = 0, phase = 0;                  // sine: f = sin(2 pi t / period + phase)
  std::vector<std::pair<double, double>> table;  // (t, f), t strictly increasing; held constant outside

  double value_at(double t) const;
  double derivative(double t) const;  // df/dt (one-sided at kinks: the right derivative)
  double integral(double t) const;    // the integral of f from 0 to t (exact for every kind)
  std::string describe() const;
};

// Reads `{constant: v}`, `{ramp: duration}`, `{sine: {period, phase}}` or
// `{table: [[t, f], ...]}`; errors name file:line:key.
TimeFunction read_time_function(const YamlAt& at);

}  // namespace pd

// Time functions: values, derivatives, exact integrals, and the YAML reader.
#include "input/time_function.hpp"

#include <fmt/core.h>

#include <cmath>
#include <numbers>

#include "input/yaml_keys.hpp"

namespace pd {

namespace {
// Integral of the table's piecewise-linear interpolant from t0 (the first abscissa or
// earlier) to t, with constant extension on both sides.
double table_integral(const std::vector<std::pair<double, double>>& tab, double t) {
  double s = 0, prev_t = 0, prev_f = tab.front().second;
  // Before the first abscissa f is constant tab[0].f; integrate from 0.
  if (t <= tab.front().first) return tab.front().second * t;
  s = tab.front().second * tab.front().first;
  prev_t = tab.front().first;
  for (std::size_t i = 1; i < tab.size(); ++i) {
    const double t1 = tab[i].first, f1 = tab[i].second;
    if (t <= t1) {
      const double ft = prev_f + (f1 - prev_f) * (t - prev_t) / (t1 - prev_t);
      return s + 0.5 * (prev_f + ft) * (t - prev_t);
    }
    s += 0.5 * (prev_f + f1) * (t1 - prev_t);
    prev_t = t1, prev_f = f1;
  }
  return s + prev_f * (t - prev_t);
}
}  // namespace

double TimeFunction::value_at(double t) const {
  switch (kind) {
    case Kind::Constant:
      return value;
    case Kind::Ramp:
      return t <= 0 ? 0.0 : t >= duration ? 1.0 : t / duration;
    case Kind::Sine:
      return std::sin(2 * std::numbers::pi * t / period + phase);
    case Kind::Table: {
      if (t <= table.front().first) return table.front().second;
      for (std::size_t i = 1; i < table.size(); ++i)
        if (t <= table[i].first) {
          const auto [t0, f0] = table[i - 1];
          const auto [t1, f1] = table[i];
          return f0 + (f1 - f0) * (t - t0) / (t1 - t0);
        }
      return table.back().second;
    }
  }
  return 0;
}

double TimeFunction::derivative(double t) const {
  switch (kind) {
    case Kind::Constant:
      return 0;
    case Kind::Ramp:
      return t >= 0 && t < duration ? 1.0 / duration : 0.0;
    case Kind::Sine:
      return 2 * std::numbers::pi / period * std::cos(2 * std::numbers::pi * t / period + phase);
    case Kind::Table:
      for (std::size_t i = 1; i < table.size(); ++i)
        if (t >= table[i - 1].first && t < table[i].first)
          return (table[i].second - table[i - 1].second) / (table[i].first - table[i - 1].first);
      return 0;
  }
  return 0;
}

double TimeFunction::integral(double t) const {
  switch (kind) {
    case Kind::Constant:
      return value * t;
    case Kind::Ramp:
      if (t <= 0) return 0;
      return t <= duration ? 0.5 * t * t / duration : 0.5 * duration + (t - duration);
    case Kind::Sine: {
      const double w = 2 * std::numbers::pi / period;
      return (std::cos(phase) - std::cos(w * t + phase)) / w;
    }
    case Kind::Table:
      return table_integral(table, t);
  }
  return 0;
}

std::string TimeFunction::describe() const {
  switch (kind) {
    case Kind::Constant:
      return fmt::format("constant {:.6g}", value);
    case Kind::Ramp:
      return fmt::format("ramp over {:.6g}", duration);
    case Kind::Sine:
      return fmt::format("sine, period {:.6g}, phase {:.6g}", period, phase);
    case Kind::Table:
      return fmt::format("table of {} points", table.size());
  }
  return "";
}

TimeFunction read_time_function(const YamlAt& at) {
  MapReader m(at);
  TimeFunction f;
  int kinds = 0;
  if (m.has("constant")) f.kind = TimeFunction::Kind::Constant, f.value = m.number("constant"), ++kinds;
  if (m.has("ramp")) {
    f.kind = TimeFunction::Kind::Ramp;
    f.duration = m.number("ramp");
    if (!(f.duration > 0)) m.get("ramp").fail("the ramp duration must be positive");
    ++kinds;
  }
  if (m.has("sine")) {
    f.kind = TimeFunction::Kind::Sine;
    MapReader s(m.get("sine"));
    f.period = s.number("period");
    if (!(f.period > 0)) s.get("period").fail("the period must be positive");
    f.phase = s.number("phase", 0.0);
    s.finish();
    ++kinds;
  }
  if (m.has("table")) {
    f.kind = TimeFunction::Kind::Table;
    const YamlAt list = m.get("table");
    require_list(list);
    for (std::size_t i = 0; i < list.node.size(); ++i) {
      const YamlAt e = list.element(list.node[i], i);
      const auto v = as_numbers(e);
      if (v.size() != 2) e.fail("a table row is [t, f]");
      if (!f.table.empty() && !(v[0] > f.table.back().first))
        e.fail("the times of a table must increase strictly");
      f.table.emplace_back(v[0], v[1]);
    }
    if (f.table.size() < 2) list.fail("a table needs at least two rows");
    ++kinds;
  }
  if (kinds != 1) at.fail("give exactly one of constant, ramp, sine, table");
  m.finish();
  return f;
}

}  // namespace pd

// Reading a reference time series and measuring a run's probe against it.
#include "study/time_history.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace pd {

namespace {
std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream ss(line);
  std::string cell;
  while (std::getline(ss, cell, ',')) {
    const auto b = cell.find_first_not_of(" \t\r"), e = cell.find_last_not_of(" \t\r");
    out.push_back(b == std::string::npos ? std::string() : cell.substr(b, e - b + 1));
  }
  return out;
}
}  // namespace

TimeSeries read_time_series(const std::string& file, const std::string& time, const std::string& value) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error(file + ": cannot open the reference time series");
  std::string line;
  if (!std::getline(in, line)) throw std::runtime_error(file + ": empty");
  const std::vector<std::string> header = split(line);
  auto column = [&](const std::string& name) {
    const auto it = std::find(header.begin(), header.end(), name);
    if (it == header.end())
      throw std::runtime_error(fmt::format("{}:1: no column '{}' in the header", file, name));
    return static_cast<std::size_t>(it - header.begin());
  };
  const std::size_t ct = column(time), cv = column(value);
  TimeSeries s;
  for (int n = 2; std::getline(in, line); ++n) {
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    const std::vector<std::string> cells = split(line);
    auto number = [&](std::size_t c) {
      if (c >= cells.size()) throw std::runtime_error(fmt::format("{}:{}: too few columns", file, n));
      try {
        std::size_t used = 0;
        const double x = std::stod(cells[c], &used);
        if (used != cells[c].size() || !std::isfinite(x)) throw std::invalid_argument("");
        return x;
      } catch (const std::exception&) {
        throw std::runtime_error(fmt::format("{}:{}: '{}' is not a finite number", file, n, cells[c]));
      }
    };
    const double t = number(ct), v = number(cv);
    if (!s.t.empty() && !(t > s.t.back()))
      throw std::runtime_error(fmt::format("{}:{}: the times must increase", file, n));
    s.t.push_back(t);
    s.v.push_back(v);
  }
  if (s.t.size() < 2) throw std::runtime_error(file + ": a reference time series needs at least two rows");
  return s;
}

TimeHistoryError time_history_error(const std::vector<double>& t, const std::vector<double>& v,
                                    const TimeSeries& ref) {
  if (t.empty() || t.size() != v.size())
    throw std::invalid_argument("time history: no samples, or times and values differ in size");
  double scale = 0;
  for (double x : ref.v) scale = std::max(scale, std::abs(x));
  if (!(scale > 0))
    throw std::invalid_argument(
        "time history: the reference is zero throughout; a relative error is undefined");
  const double slack = 1e-9 * (ref.t.back() - ref.t.front());
  double sum = 0, peak = 0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (t[i] < ref.t.front() - slack || t[i] > ref.t.back() + slack)
      throw std::invalid_argument(fmt::format(
          "time history: the run's time {:.6g} lies outside the reference's span [{:.6g}, {:.6g}]", t[i],
          ref.t.front(), ref.t.back()));
    const auto it = std::upper_bound(ref.t.begin(), ref.t.end(), t[i]);
    const std::size_t k =
        std::clamp<std::size_t>(static_cast<std::size_t>(it - ref.t.begin()), 1, ref.t.size() - 1);
    const double a = std::clamp((t[i] - ref.t[k - 1]) / (ref.t[k] - ref.t[k - 1]), 0.0, 1.0);
    const double r = (1 - a) * ref.v[k - 1] + a * ref.v[k];
    const double d = std::abs(v[i] - r);
    if (!std::isfinite(d))
      throw std::invalid_argument(
          fmt::format("time history: the run's value at t = {:.6g} is not finite", t[i]));
    sum += d * d;
    peak = std::max(peak, d);
  }
  return {std::sqrt(sum / static_cast<double>(t.size())) / scale, peak / scale};
}

}  // namespace pd

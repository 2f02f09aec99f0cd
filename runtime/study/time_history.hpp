// Time-history errors of a dynamic run (paper 003 section 5.1): a probe's displacement
// against a reference time series (a finite-element curve), RMS and peak of the
// difference relative to the reference's largest magnitude.
#pragma once

#include <string>
#include <vector>

namespace pd {

struct TimeSeries {
  std::vector<double> t, v;  // t strictly increasing
};

// Columns `time` and `value` (by header name) of a comma-separated file with a header
// line. Throws std::runtime_error naming the file (and line) when it cannot be read, a
// column is missing, a value is not a number, or the times do not increase.
TimeSeries read_time_series(const std::string& file, const std::string& time, const std::string& value);

struct TimeHistoryError {
  double rms = 0, peak = 0;  // relative to max |reference|
};

// The run's samples (t[i], v[i]) against the reference interpolated linearly at t[i].
// Throws std::invalid_argument when a sample lies outside the reference's time span, or
// when there is no sample, or the reference is zero.
TimeHistoryError time_history_error(const std::vector<double>& t, const std::vector<double>& v,
                                    const TimeSeries& reference);

}  // namespace pd

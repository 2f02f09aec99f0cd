// `pd study` over dynamic scenes (study/time_history.hpp): the first probe's displacement
// against a reference time series, RMS and peak relative to the reference's largest
// magnitude. The metric by hand on a three-point series; end to end on a body in free
// flight, whose probe moves as u = v0 t exactly (no internal force in a rigid translation),
// against that analytic series and against the series shifted by a known constant.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "study/study.hpp"
#include "study/time_history.hpp"

namespace {
std::string write_file(const std::string& name, const std::string& text) {
  const std::string path = testing::TempDir() + "/" + name;
  std::ofstream(path) << text;
  return path;
}
}  // namespace

TEST(TimeHistory, RmsAndPeakAgainstTheInterpolatedReference) {
  const pd::TimeSeries ref{{0, 1, 2}, {0, 2, 0}};
  // Reference at 0.5, 1.5: 1 and 1; differences 0.5 and -0.25; scale max |ref| = 2.
  const pd::TimeHistoryError e = pd::time_history_error({0.5, 1.5}, {1.5, 0.75}, ref);
  EXPECT_DOUBLE_EQ(e.rms, std::sqrt((0.25 + 0.0625) / 2) / 2);
  EXPECT_DOUBLE_EQ(e.peak, 0.25);
  EXPECT_THROW(pd::time_history_error({2.5}, {0.0}, ref), std::invalid_argument);  // outside the span
  EXPECT_THROW(pd::time_history_error({}, {}, ref), std::invalid_argument);
  EXPECT_THROW(pd::time_history_error({1}, {0}, pd::TimeSeries{{0, 1}, {0, 0}}), std::invalid_argument);
  EXPECT_THROW(pd::time_history_error({1}, {NAN}, ref), std::invalid_argument);
}

TEST(TimeHistory, ReaderNamesTheFileAndLine) {
  const auto good =
      pd::read_time_series(write_file("th_good.csv", "t,ux,uy\n0,1,2\n1e-3, 3 ,4\n"), "t", "ux");
  EXPECT_EQ(good.t, (std::vector<double>{0, 1e-3}));
  EXPECT_EQ(good.v, (std::vector<double>{1, 3}));
  auto message = [](const std::string& file, const std::string& column) {
    try {
      pd::read_time_series(file, "t", column);
    } catch (const std::runtime_error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message(write_file("th_col.csv", "t,ux\n0,1\n1,2\n"), "uz").find("th_col.csv:1: no column 'uz'"),
            std::string::npos);
  EXPECT_NE(message(write_file("th_nan.csv", "t,ux\n0,1\n1,x\n"), "ux").find("th_nan.csv:3:"),
            std::string::npos);
  EXPECT_NE(message(write_file("th_order.csv", "t,ux\n0,1\n0,2\n"), "ux")
                .find("th_order.csv:3: the times must increase"),
            std::string::npos);
}

TEST(TimeHistory, DynamicStudyPointMeasuresTheProbeHistory) {
  const double v0 = 2e-3, t_end = 0.05;  // dt 1e-3, 50 steps
  write_file("flight.yaml",
             "dimension: 2\n"
             "domain: {box: {min: [0, 0], max: [1, 1]}, count: 4}\n"
             "horizon: {ratio: 2}\n"
             "law: silling_plane_strain\n"
             "materials:\n  - {E: 1, nu: 0.25, density: 1}\n"
             "probes:\n  - {name: ux, region: {box: {min: [0.5, 0.5], max: [1, 1]}}, component: x}\n"
             "dynamics:\n  method: explicit\n  dt: 0.001\n  steps: 50\n  output_every: 5\n"
             "  progress_seconds: 0\n"
             "  initial:\n    - {region: {all: true}, velocity: [0.002, 0]}\n");
  std::string exact = "t,ux,shifted\n";
  for (int k = 0; k <= 10; ++k) {
    const double t = k * 0.1 * t_end;
    exact += fmt::format("{:.17g},{:.17g},{:.17g}\n", t, v0 * t, v0 * t + 1e-5);
  }
  write_file("flight_ref.csv", exact);
  for (const std::string column : {"ux", "shifted"}) {
    const std::string study = write_file("flight_study.yaml",
                                         "problems: [flight.yaml]\n"
                                         "laws: [silling_plane_strain]\n"
                                         "influences: [const]\n"
                                         "ratios: [2, 3]\n"
                                         "counts: [6]\n"
                                         "time_reference: {file: flight_ref.csv, value: " +
                                             column + "}\n");
    const std::string out = testing::TempDir() + "/pd_study_flight_" + column;
    std::filesystem::remove_all(out);
    const pd::StudySpec spec = pd::read_study(study);
    pd::run_study(spec, out, false, [](const std::string&) {});
    std::ifstream csv(out + "/points.csv");
    std::string header, line;
    std::getline(csv, header);
    int rows = 0;
    while (std::getline(csv, line)) {
      ++rows;
      // error is the 8th column, peak_error the 21st.
      std::vector<std::string> cells;
      std::string cell;
      bool quoted = false;
      for (char c : line) {
        if (c == '"')
          quoted = !quoted;
        else if (c == ',' && !quoted)
          cells.push_back(cell), cell.clear();
        else
          cell += c;
      }
      cells.push_back(cell);
      ASSERT_GE(cells.size(), 21u) << line;
      EXPECT_EQ(cells[6], "1") << line;
      const double rms = std::stod(cells[7]), peak = std::stod(cells[20]);
      // Verlet integrates a constant velocity exactly; the rest is rounding.
      const double expected = column == "ux" ? 0.0 : 1e-5 / (v0 * t_end + 1e-5);
      EXPECT_NEAR(rms, expected, 1e-9) << line;
      EXPECT_NEAR(peak, expected, 1e-9) << line;
    }
    EXPECT_EQ(rows, 2);
  }
}

// What the tests of laws with memory share (tests/laws/test_history.cpp,
// tests/laws/test_correspondence_plastic.cpp): the parameterised cases, vector norms, the
// scaling of a family's deformation along a load path, and the check of the algorithmic
// tangent against central differences of the incremental residual.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "kernel_abi.hpp"
#include "verify/random_family.hpp"
#include "verify/tangent_check.hpp"

namespace pd::test {

struct HistoryCase {
  const char* law;
  verify::Truncation truncation;
  bool broken;
};

inline std::string history_case_name(const testing::TestParamInfo<HistoryCase>& info) {
  const char* t[] = {"Interior", "Edge", "Corner"};
  return std::string(info.param.law) + "_" + t[static_cast<int>(info.param.truncation)] +
         (info.param.broken ? "_Broken" : "");
}

inline double max_abs(const std::vector<double>& v) {
  double m = 0;
  for (double x : v) m = std::max(m, std::fabs(x));
  return m;
}

inline double max_diff(const std::vector<double>& a, const std::vector<double>& b) {
  double m = 0;
  for (std::size_t i = 0; i < a.size(); ++i) m = std::max(m, std::fabs(a[i] - b[i]));
  return m;
}

// y = x + lambda (y_full - x): the family's deformation scaled back toward the reference.
inline void scale_deformation(verify::TestFamily& f, const std::vector<double>& y_full, double lambda) {
  std::vector<double> y(y_full.size());
  for (std::size_t i = 0; i < y.size(); ++i) y[i] = f.x[i] + lambda * (y_full[i] - f.x[i]);
  f.set_positions(y);
}

// The generated tangent against central differences with the committed history fixed.
inline void expect_tangent_matches_differences(const abi::LawDescriptor& law, verify::TestFamily& f,
                                               const char* state) {
  const auto M = f.tangent_matrix(law.damaged);
  const auto err = verify::block_errors(f, M, f.fd_matrix(law.damaged, 1e-6 * f.delta));
  EXPECT_LT(err.worst(), 1e-6) << state << ": center " << err.center << ", on-diagonal " << err.on_diagonal
                               << ", off-diagonal " << err.off_diagonal << ", coupling "
                               << err.center_coupling;
}

// Load past yield from a virgin state, commit, then unload elastically, unload far enough to
// yield in reverse, and reload past the committed state; the tangent is checked with the
// committed history fixed (the incremental residual) in each state. scale_of(f): the
// independent return map's scale of the state (1 elastic, < 1 yielding). After a first
// yielding step of scale s1 the elastic part is s1 times the deformation, so scaling the
// deformation by lambda gives a trial size |lambda - 1 + s1| / s1 times the yield value (up
// to the nonlinearity of the kinematics).
template <class ScaleOf>
void check_tangent_along_a_reversal(const abi::LawDescriptor& law, verify::TestFamily& f, ScaleOf scale_of) {
  const std::vector<double> y1 = f.y;
  const double s1 = scale_of(f);
  ASSERT_LT(s1, 1.0) << "the first step must yield";
  expect_tangent_matches_differences(law, f, "yielding from virgin");
  f.commit_update(law.damaged);
  scale_deformation(f, y1, 1 - 0.5 * s1);
  ASSERT_EQ(scale_of(f), 1.0) << "the partial unloading must be elastic";
  expect_tangent_matches_differences(law, f, "elastic unloading");
  scale_deformation(f, y1, 1 - 3 * s1);
  ASSERT_LT(scale_of(f), 1.0) << "the full unloading must yield in reverse";
  expect_tangent_matches_differences(law, f, "reverse yielding");
  scale_deformation(f, y1, 1.5);
  ASSERT_LT(scale_of(f), 1.0) << "the reloading must yield";
  expect_tangent_matches_differences(law, f, "reloading past the committed state");
}

}  // namespace pd::test

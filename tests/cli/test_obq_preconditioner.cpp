// With quadrature: obq the matrix-free path's preconditioner is the collocation tangent
// itself. Before, it was the volume rule's stiffness on a shorter horizon, which does not
// approximate the collocation operator: on scenes/paper001_hole.yaml GMRES stalled at a
// relative residual of 1.8e-2 and the run failed after 20 000 iterations.
#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <string>

#include "run_pd.hpp"

namespace {
// The §4 RMS error the log prints, as text (the same digits for the same answer).
std::string rms_line(const std::string& log) {
  std::smatch m;
  EXPECT_TRUE(std::regex_search(log, m, std::regex("RMS error over the [0-9]+ free particles[^\n]*"))) << log;
  return m.size() ? m.str(0) : "";
}
}  // namespace

TEST(ObqPreconditioner, MatrixFreeNewtonSolvesTheHoleInOneKrylovIteration) {
  const auto dir = pdtest::fresh_directory("obq_preconditioner");
  const std::string scene = pdtest::slurp(std::string(PD_SOURCE_SCENES) + "/paper001_hole.yaml");
  std::ofstream(dir / "mf.yaml") << scene << "\nsolver: {linear: matrix_free}\n";
  const auto direct = pdtest::run_pd(
      {"run", std::string(PD_SOURCE_SCENES) + "/paper001_hole.yaml", "--out", (dir / "direct").string()});
  const auto mf = pdtest::run_pd({"run", (dir / "mf.yaml").string(), "--out", (dir / "mf").string()});
  ASSERT_EQ(direct.status, 0) << direct.err;
  ASSERT_EQ(mf.status, 0) << mf.err;
  EXPECT_NE(mf.out.find("the preconditioner is the collocation tangent itself"), std::string::npos) << mf.out;
  EXPECT_NE(mf.out.find(" 1 linear its"), std::string::npos) << mf.out;
  EXPECT_EQ(rms_line(mf.out), rms_line(direct.out));
}

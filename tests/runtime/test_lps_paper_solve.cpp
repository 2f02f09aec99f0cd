// Paper 001's LPS as written (lps_paper_*, analytic m(delta); docs/laws.md) in the §4
// solve: where no bond is broken, OBQ weights integrate m(delta) and M = I exactly, so the
// discrete-m law, the paper's and the paper's corrected one are the same law; bonds broken
// by the hole of Fig. 1 make m(delta) and M act. The solver follows the law's energy.
#include <gtest/gtest.h>

#include <cmath>

#include "fields/michell.hpp"
#include "run/manufactured_solve.hpp"

namespace {
pd::ManufacturedResult solve_with(const char* law, const pd::ManufacturedField& field,
                                  pd::ManufacturedSetup s) {
  s.law = law;
  return pd::solve_manufactured(field, s);
}

pd::ManufacturedField michell_field(double lambda, double mu) {
  pd::MichellHole hole;
  hole.T = 1, hole.a = 0.2, hole.x0 = 0.5, hole.y0 = 0.5, hole.lambda = lambda, hole.mu = mu;
  return {"michell", [hole](double x, double y) { return hole.displacement(x, y); },
          [](double, double, double, double) {
            return std::array<double, 2>{0.0, 0.0};
          }};
}
}  // namespace

// u2 on a perturbed 20^2 cloud, lambda != mu so that the dilatation term counts.
TEST(LpsPaperSolve, WithoutBrokenBondsObqMakesTheAnalyticVolumeTheDiscreteOne) {
  pd::ManufacturedSetup s;
  s.n = 20;
  s.lambda = 0.7, s.mu = 0.3;
  const double discrete = solve_with("lps_plane_strain", pd::paper001_u2(), s).rms_error;
  const double paper = solve_with("lps_paper_plane_strain", pd::paper001_u2(), s).rms_error;
  const double corrected = solve_with("lps_paper_corrected_plane_strain", pd::paper001_u2(), s).rms_error;
  EXPECT_NEAR(paper, discrete, 1e-9 * discrete);
  EXPECT_NEAR(corrected, discrete, 1e-9 * discrete);
}

// The hole of Fig. 1 (perturbed 24^2): the families that lost bonds keep m(delta), so the
// error is worse than the discrete-m law's (measured 9.91e-3 against 5.69e-3 at lambda = mu),
// and with lambda != mu the corrected dilatation changes it again.
TEST(LpsPaperSolve, BondsBrokenByTheHoleMakeTheAnalyticVolumeAndTheCorrectionAct) {
  pd::ManufacturedSetup s;
  s.n = 24;
  s.collar_outside = true;
  s.hole_radius = 0.2;
  const double discrete = solve_with("lps_plane_strain", michell_field(0.5, 0.5), s).rms_error;
  const double paper = solve_with("lps_paper_plane_strain", michell_field(0.5, 0.5), s).rms_error;
  // m(delta) over-counts every family the hole cut (its bonds into the hole are gone), so
  // the analytic volume must be worse there, not merely different: measured 1.74 times.
  EXPECT_GT(paper, 1.5 * discrete);
  s.lambda = 1.7, s.mu = 0.3;
  const double plain = solve_with("lps_paper_plane_strain", michell_field(1.7, 0.3), s).rms_error;
  const double corrected =
      solve_with("lps_paper_corrected_plane_strain", michell_field(1.7, 0.3), s).rms_error;
  // No direction is claimed for the correction at nu = 0.425 (paper 001 motivates M+ in
  // theta by near-incompressibility): it must act (measured 9.86e-3 -> 1.06e-2, +7.5 %).
  EXPECT_GT(std::fabs(plain - corrected), 0.05 * plain);
}

// With the volume quadrature the matrix of a law with an energy is symmetric (CHOLMOD); the
// corrected paper law has none, and its non-symmetric matrix must go to UMFPACK.
TEST(LpsPaperSolve, ALawWithoutEnergyIsNotSolvedAsSymmetric) {
  pd::ManufacturedSetup s;
  s.n = 16;
  s.obq = false;
  s.lambda = 0.7, s.mu = 0.3;
  EXPECT_TRUE(solve_with("lps_paper_plane_strain", pd::paper001_u2(), s).symmetric_matrix);
  EXPECT_FALSE(solve_with("lps_paper_corrected_plane_strain", pd::paper001_u2(), s).symmetric_matrix);
}

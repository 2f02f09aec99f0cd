// Closed-form ball moments against numerical integration in polar / spherical coordinates,
// and against the weighted volumes paper 001 quotes (m = 2 pi delta^3 / 3, pi delta^4).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "discretize/ball_moments.hpp"
#include "discretize/reproducing_space.hpp"
#include "polar_quadrature.hpp"

namespace {

using pd_test::integrate_numerically;

}  // namespace

TEST(BallMoments, MatchNumericalIntegrationIn2DAnd3D) {
  const double delta = 0.37;
  for (int dim : {2, 3})
    for (int s : {0, 1, 2, 3})
      for (const pd::BondMonomial& f : pd::monomials(dim, std::max(0, s + 1 - dim), 6, s)) {
        const double exact = pd::ball_moment(dim, f, delta);
        const double scale = std::pow(delta, f.degree() - s + dim);
        // Relative to the moment (or to delta^p when it vanishes by symmetry).
        EXPECT_NEAR(exact, integrate_numerically(dim, f, delta), 1e-13 * std::max(std::abs(exact), scale))
            << dim << "D, powers " << f.powers[0] << f.powers[1] << f.powers[2] << ", 1/r^" << s;
      }
}

TEST(BallMoments, WeightedVolumesOfPaper001) {
  // m(delta) = int_B K r^2 with K = 1/r, i.e. int_B xi_1^2/r + xi_2^2/r (+ xi_3^2/r).
  const double delta = 0.2;
  for (int dim : {2, 3}) {
    double m = 0;
    for (int c = 0; c < dim; ++c) {
      pd::BondMonomial f;
      f.powers[c] = 2;
      f.inverse_r_power = 1;
      m += pd::ball_moment(dim, f, delta);
    }
    const double paper = dim == 2 ? 2 * M_PI * std::pow(delta, 3) / 3 : M_PI * std::pow(delta, 4);
    EXPECT_NEAR(m, paper, 1e-15 * paper) << dim << "D";
  }
}

TEST(BallMoments, NonIntegrableSingularityIsAnError) {
  pd::BondMonomial f;
  f.inverse_r_power = 2;  // 1/r^2 in 2D: log-divergent at the origin
  EXPECT_THROW(pd::ball_moment(2, f, 1.0), std::invalid_argument);
  EXPECT_NO_THROW(pd::ball_moment(3, f, 1.0));
}

TEST(ReproducingSpace, Paper001SpaceHas15FunctionsIn2DAnd35In3D) {
  EXPECT_EQ(pd::paper001_space(2).terms.size(), 15u);
  EXPECT_EQ(pd::paper001_space(3).terms.size(), 35u);
  EXPECT_EQ(pd::paper001_odd_space(2).terms.size(), 21u);
  EXPECT_EQ(pd::paper001_odd_space(3).terms.size(), 56u);
}

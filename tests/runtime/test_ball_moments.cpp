// Closed-form ball moments against numerical integration in polar / spherical coordinates,
// and against the weighted volumes paper 001 quotes (m = 2 pi delta^3 / 3, pi delta^4).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "discretize/ball_moments.hpp"
#include "discretize/reproducing_space.hpp"

namespace {

// Gauss-Legendre nodes and weights on [-1, 1] (Newton on P_n from the Chebyshev guess).
void gauss_legendre(int n, std::vector<double>& x, std::vector<double>& w) {
  x.assign(n, 0.0);
  w.assign(n, 0.0);
  for (int i = 0; i < n; ++i) {
    double z = std::cos(M_PI * (i + 0.75) / (n + 0.5)), dp = 0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1, p1 = z;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2 * k - 1) * z * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = n * (z * p1 - p0) / (z * z - 1);
      const double step = p1 / dp;
      z -= step;
      if (std::abs(step) < 1e-16) break;
    }
    x[i] = z;
    w[i] = 2 / ((1 - z * z) * dp * dp);
  }
}

// int_B f by quadrature: Gauss-Legendre in r (and cos(polar angle) in 3D), the
// trapezoid rule (exact for these trigonometric polynomials) in the azimuth.
double integrate_numerically(int dim, const pd::BondMonomial& f, double delta) {
  std::vector<double> gx, gw;
  gauss_legendre(12, gx, gw);  // exact for radial and polar degrees <= 23
  const int n_phi = 16;  // exact for the azimuthal degree <= 6 used here
  double sum = 0;
  for (size_t a = 0; a < gx.size(); ++a) {
    const double r = 0.5 * delta * (gx[a] + 1), wr = 0.5 * delta * gw[a];
    for (int k = 0; k < n_phi; ++k) {
      const double phi = 2 * M_PI * k / n_phi, wphi = 2 * M_PI / n_phi;
      if (dim == 2) {
        const double xi[2] = {r * std::cos(phi), r * std::sin(phi)};
        sum += wr * wphi * r * f.value(2, xi, r);
      } else {
        for (size_t c = 0; c < gx.size(); ++c) {
          const double ct = gx[c], st = std::sqrt(1 - ct * ct);
          const double xi[3] = {r * st * std::cos(phi), r * st * std::sin(phi), r * ct};
          sum += wr * wphi * gw[c] * r * r * f.value(3, xi, r);
        }
      }
    }
  }
  return sum;
}

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

// Test support: integrals over the ball B_delta(0) by quadrature in polar / spherical
// coordinates, independent of the closed-form moments they check (ball_moments.hpp).
#pragma once

#include <cmath>
#include <functional>
#include <vector>

#include "discretize/ball_moments.hpp"

namespace pd_test {

// Gauss-Legendre nodes and weights on [-1, 1] (Newton on P_n from the Chebyshev guess).
inline void gauss_legendre(int n, std::vector<double>& x, std::vector<double>& w) {
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
// `weight` (optional) multiplies the integrand by w(r/delta).
inline double integrate_numerically(int dim, const pd::BondMonomial& f, double delta,
                                    const std::function<double(double)>& weight = {}) {
  std::vector<double> gx, gw;
  gauss_legendre(12, gx, gw);  // exact for radial and polar degrees <= 23
  const int n_phi = 16;        // exact for the azimuthal degree <= 6 used here
  double sum = 0;
  for (size_t a = 0; a < gx.size(); ++a) {
    const double r = 0.5 * delta * (gx[a] + 1), wr = 0.5 * delta * gw[a];
    for (int k = 0; k < n_phi; ++k) {
      const double phi = 2 * M_PI * k / n_phi, wphi = 2 * M_PI / n_phi;
      if (dim == 2) {
        const double xi[2] = {r * std::cos(phi), r * std::sin(phi)};
        sum += wr * wphi * r * f.value(2, xi, r) * (weight ? weight(r / delta) : 1.0);
      } else {
        for (size_t c = 0; c < gx.size(); ++c) {
          const double ct = gx[c], st = std::sqrt(1 - ct * ct);
          const double xi[3] = {r * st * std::cos(phi), r * st * std::sin(phi), r * ct};
          sum += wr * wphi * gw[c] * r * r * f.value(3, xi, r) * (weight ? weight(r / delta) : 1.0);
        }
      }
    }
  }
  return sum;
}

}  // namespace pd_test

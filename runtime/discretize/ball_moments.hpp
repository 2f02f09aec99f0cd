// Closed-form moments of the ball B_delta(0) in 2D and 3D: the right-hand sides of the
// equality constraints of paper 001's optimisation-based quadrature (eq. 2.12).
//
// An integrand of a reproducing space is a monomial of the bond, divided by a power of
// its length:  f(xi) = xi_1^b1 xi_2^b2 (xi_3^b3) / |xi|^s.  In polar / spherical
// coordinates it separates into a radial power and a monomial of the unit direction n:
//     I[f] = int_0^delta r^(|b| - s + d - 1) dr  *  int_{S^(d-1)} n^b dS
//          = delta^p / p  *  A_d(b),                p = |b| - s + d  (> 0 to be integrable)
// with the classical sphere integral (Folland, "How to integrate a polynomial over a
// sphere", Amer. Math. Monthly 108, 2001)
//     A_d(b) = 0 if any b_i is odd, else 2 prod_i Gamma((b_i + 1)/2) / Gamma((|b| + d)/2).
#pragma once

#include <array>

namespace pd {

// One integrand xi^powers / |xi|^inverse_r_power (powers[2] ignored in 2D).
struct BondMonomial {
  std::array<int, 3> powers{0, 0, 0};
  int inverse_r_power = 0;

  int degree() const { return powers[0] + powers[1] + powers[2]; }
  // The integrand at bond xi (length r = |xi| > 0).
  double value(int dim, const double* xi, double r) const;
};

// int_{S^(d-1)} n^powers dS, d = 2 or 3.
double sphere_monomial_integral(int dim, const std::array<int, 3>& powers);

// int_{B_delta(0)} f(xi) dxi in closed form. Throws std::invalid_argument when the
// integrand is not integrable at the origin (|b| - s + d <= 0) or dim is not 2 or 3.
double ball_moment(int dim, const BondMonomial& f, double delta);

}  // namespace pd

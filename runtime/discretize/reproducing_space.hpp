// The reproducing space of an optimisation-based quadrature: the integrands a family's
// weights must integrate exactly over the ball (paper 001, eq. 2.12 and §2.2).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "discretize/ball_moments.hpp"

namespace pd {

// One term c rho^k of a radial weight w(rho) = sum c rho^k, rho = |xi| / delta.
struct RadialPower {
  double coefficient = 1;
  int power = 0;
};

struct ReproducingSpace {
  std::string name;
  int dim = 2;
  std::vector<BondMonomial> terms;  // a basis: linearly independent as functions on the ball
  // Every function of the space is w(|xi|/delta) * term: the influence a law's horizon sums
  // carry (law_space.hpp). Empty: w = 1 (paper 001's spaces).
  std::vector<RadialPower> weight;
};

// w(rho) of the space (1 when it has no weight).
double radial_weight(const ReproducingSpace& space, double rho);

// The term w(|xi|/delta) f(xi) as a sum of monomials of the bond scaled by 1/delta:
// c_k rho^k f(xi/delta) = c_k (xi/delta)^b / |xi/delta|^(s - k). Each pair is a
// coefficient and a monomial; their ball moments are closed-form (ball_moments.hpp).
std::vector<std::pair<double, BondMonomial>> weighted_term(const ReproducingSpace& space,
                                                           const BondMonomial& f);

// Every monomial xi^b with min_degree <= |b| <= max_degree, divided by |xi|^inverse_r_power.
std::vector<BondMonomial> monomials(int dim, int min_degree, int max_degree, int inverse_r_power);

// Paper 001's V_h = P2 u S_{K,2,x} for K = 1/r (eq. 2.5): the quadratic polynomials,
// and the quadratic vector fields against the tensor kernel xi (x) xi / |xi|^3, whose
// components xi_a xi_b (p(y) - p(x)) / |xi|^3 span xi^b / |xi|^3 with |b| = 3 and 4
// (p(y) - p(x) has no constant term). 15 functions in 2D, 35 in 3D. The same span holds
// the dilatation-force integrand K xi (theta_i + theta_j) for theta in P1
// (xi_a / r = xi_a |xi|^2 / |xi|^3).
ReproducingSpace paper001_space(int dim);

// paper001_space plus xi^b / |xi|^3 with |b| = 5 (6 functions in 2D, 21 in 3D: 21 and 56
// in all). These odd integrands vanish on the ball but not on a perturbed family: the
// cubic Taylor term of u in the shear integrand (xi (x) xi / |xi|^3) [xi, xi, xi], and
// the quadratic term of u in the dilatation integrand xi . H[xi, xi] / |xi| (=
// xi^b |xi|^2 / |xi|^3). Without them the force density has an O(delta) consistency
// error of random sign on a perturbed cloud, and theta is not exact for quadratic u
// (docs/paper001.md).
ReproducingSpace paper001_odd_space(int dim);

}  // namespace pd

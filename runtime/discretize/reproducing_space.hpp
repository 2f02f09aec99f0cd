// The reproducing space of an optimisation-based quadrature: the integrands a family's
// weights must integrate exactly over the ball (paper 001, eq. 2.12 and §2.2).
#pragma once

#include <string>
#include <vector>

#include "discretize/ball_moments.hpp"

namespace pd {

struct ReproducingSpace {
  std::string name;
  int dim = 2;
  std::vector<BondMonomial> terms;  // a basis: linearly independent as functions on the ball
};

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

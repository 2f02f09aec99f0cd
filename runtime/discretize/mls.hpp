// Moving least squares (paper 002 §3.3.2, eqs. 3.19-3.44): shape functions phi_a(x) that
// give a field at a point from the values at the nodes around it, u(x) = sum_a phi_a u_a.
#pragma once

#include <span>
#include <string>
#include <vector>

namespace pd {

// Quartic spline weight of eq. (3.24): 1 - 6d^2 + 8d^3 - 3d^4 for d = |x - x_a| / r_w <= 1.
double mls_quartic_weight(double d);

// The number of terms of the complete polynomial basis of degree 2 in dim dimensions,
// eq. (3.20): 6 in 2D, 10 in 3D.
int mls_basis_size(int dim);

struct MlsShape {
  std::vector<int> node;    // indices (as given) of the nodes with phi != 0 (inside the support)
  std::vector<double> phi;  // phi_a(x), same order
  double condition = 0.0;   // row-sum-norm condition number of the moment matrix A, eq. (3.39)-(3.40)
};

// Shape functions at x (dim components) from the candidate nodes `candidates` (indices
// into positions, [n*dim]); only those within support r_w of x take part.
//
// The basis is the complete quadratic of eq. (3.21), written in the shifted and scaled
// coordinates s = (x_a - x) / r_w instead of the raw x_a. It spans the same polynomials,
// so phi is the same function (MLS shape functions depend on the space, not its basis);
// but the moment matrix of raw coordinates has entries from 1 to |x|^4 and a condition
// number of 1e8 already at |x| ~ 100 h, which the paper's test would reject for a
// well-placed point. In scaled coordinates kappa measures only how well the nodes
// determine a quadratic (about 1e2-1e4 for a lattice at r_w = 3h).
//
// Throws std::runtime_error naming `what` and the point when fewer nodes than basis
// terms are in the support or kappa > max_condition (the paper's 1e8, §3.3.2 (1)).
MlsShape mls_shape_functions(const double* x, int dim, std::span<const double> positions,
                             std::span<const int> candidates, double support, const std::string& what,
                             double max_condition = 1e8);

}  // namespace pd

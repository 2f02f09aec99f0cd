// Fixed Gauss points in the neighbour cells (paper 002 §3.3.1, eqs. 3.9-3.15) with their
// displacements from a moving-least-squares fit of the nodal ones (§3.3.2, mls.hpp).
//
// Each particle j stands for a cell of side h around it. The cell holds n^dim fixed
// Gauss-Legendre points x_g = x_j + (h/2) (zeta_r, zeta_s[, zeta_t]) (eq. 3.10) with the
// volume V_g = V_j prod(w/2) (eqs. 3.11-3.12: (h/2)^dim prod w for a lattice cell). The
// family of particle i integrates over the Gauss points of its neighbours' cells (j != i,
// eq. 3.13), each with the reduction factor beta_g of eq. (3.14) on the effective subcell
// size h_g = (h/2) (prod w)^(1/dim). A Gauss bond is then an ordinary bond to a point:
// xi = x_g - x_i, Y = xi + u_g - u_i, V = beta_g V_g, and the kernels see nothing new.
//
// u_g = sum_a phi_a(x_g) u_a over the nodes within r_w of x_g (quadratic basis, quartic
// spline, r_w = 3h by default). With one point per axis the point is the node itself and
// u_g = u_j (the paper's exception, §3.3.1): the rule is then `domain.quadrature:
// partial_linear` exactly.
//
// The paper's forces are eq. (3.15) for a pairwise (bond-based) force. For every law this
// runtime uses the family-energy reading instead: the family of i contributes
// V_i W_i(Y_i1 .. Y_iL) with Y_ig linear in the nodal displacements through phi, so its
// nodal forces are P_i^T f_loc and its stiffness P_i^T M P_i (docs/paper002.md, "Gauss
// points"); for a bond-based law in the interior it is eq. (3.15) with the reaction on
// the Gauss point's MLS nodes, which keeps momentum balance and a symmetric stiffness.
#pragma once

#include <string>
#include <vector>

#include "particles.hpp"

namespace pd {

struct GaussPointOptions {
  int per_axis = 2;            // Gauss-Legendre points per axis of a cell: 1, 2 or 3
  double support = 3.0;        // MLS support radius r_w in units of h (paper: 3)
  double max_condition = 1e8;  // the paper's bound on the moment matrix's condition number
};

struct GaussPoints {
  int dim = 2;
  int per_axis = 2;
  double h = 0.0, support = 0.0;  // support: r_w (a length)
  double (*influence)(double r, double delta) = nullptr;
  // Points, [G]: position, the particle whose cell holds it, V_g.
  std::vector<double> x;  // [G*dim]
  std::vector<int> cell;
  std::vector<double> volume;
  // MLS shape functions of each point, compressed rows: phi[phi_start[g] .. phi_start[g+1]).
  std::vector<int> phi_start, phi_node;
  std::vector<double> phi;
  double max_condition = 0.0;  // the largest kappa met (for the log)
  // Families, compressed rows over particles: Gauss bond b of particle p is to point[b]
  // with reduction factor beta[b] (eq. 3.14); delta[p] the horizon.
  std::vector<int> offsets, point;
  std::vector<double> beta, delta;

  int points() const { return static_cast<int>(volume.size()); }
  int particle_count() const { return static_cast<int>(offsets.size()) - 1; }
  int family_size(int p) const { return offsets[p + 1] - offsets[p]; }
  int bond_count() const { return static_cast<int>(point.size()); }
  double mean_support_size() const {
    return points() ? static_cast<double>(phi_node.size()) / points() : 0.0;
  }
  std::string describe() const;
};

// Gauss-Legendre abscissae and weights on [-1, 1] for n = 1, 2, 3 points.
void gauss_legendre(int n, double* zeta, double* weight);

// Eq. (3.14): 1 for r <= delta - h_g/2, falling linearly to 0 at delta + h_g/2.
double gauss_reduction_factor(double r, double delta, double hg);

// Builds the points, their MLS shape functions and the Gauss families of every particle
// for horizon delta on a body of spacing h. Throws std::invalid_argument for per_axis
// outside 1..3 or support <= 0, and std::runtime_error from the MLS condition check
// (naming the point and the cell's particle).
GaussPoints build_gauss_points(const Particles& particles, double h, double delta,
                               double (*influence)(double r, double delta), const GaussPointOptions& options);

// Displacements of the points: ug[g*dim + c] = sum_a phi_a(x_g) u[a*dim + c].
void gauss_point_displacements(const GaussPoints& gp, const double* u, double* ug);

}  // namespace pd

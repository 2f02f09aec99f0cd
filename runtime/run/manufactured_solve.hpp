// A manufactured-solution solve of paper 001 §4 on the unit square: the lattice of
// spacing h = 1/n perturbed by `perturbation` h, delta = horizon_ratio h, the exact
// displacement imposed on every particle closer than layer_horizons * delta to the
// boundary (the paper's Dirichlet layer of size delta), the body force of the field on
// the others, one linear solve (the laws used are linear), and the RMS error of §4,
//   ||e||_l2 = sqrt(sum_i |u_i - u(x_i)|^2 / N)   over the N solved particles.
#pragma once

#include <string>
#include <vector>

#include "fields/manufactured.hpp"

namespace pd {

struct ManufacturedSetup {
  int n = 24;                  // particles per side
  double lo = 0, hi = 1;       // the square [lo, hi]^2 (the paper's: the unit square); h = (hi - lo) / n
  double horizon_ratio = 3.5;  // delta / h
  double perturbation = 0.2;   // uniform, times h
  int seed = 1;
  double layer_horizons = 1.0;  // Dirichlet layer width in horizons
  // false: the layer is the outer part of the square (the paper's "layer of size delta
  // around the boundary of Omega", read as inside); true: a collar of ceil(layer / h)
  // lattice rows is added outside the square and every particle of the square is solved.
  bool collar_outside = false;
  // With the layer inside (collar_outside false): also add the collar outside, so that the
  // layer's families are whole balls. The solved particles are the same as without it;
  // what changes is the layer's own families -- their OBQ weights and the dilatation
  // theta they give, which enters the solved particles' LPS forces -- computed over a
  // whole neighbourhood instead of one cut by the square's edge. A test of what the cut
  // layer families cost (docs/paper001.md, Table 1).
  bool whole_layer_families = false;
  double lambda = 0.5, mu = 0.5;
  std::string law = "lps_plane_strain";  // takes (lambda, mu)
  std::string influence = "inv";         // K = 1/r up to a constant (the law divides by m)
  bool obq = true;                       // OBQ weights + collocation; false: the volume quadrature
  bool odd_terms = false;                // OBQ space: paper001_odd_space instead of paper001_space
  // 0: the error over all solved particles (the paper's); > 0: only over those at least
  // this far from the boundary, a region that does not change with h.
  double error_margin = 0;
  // A traction-free hole (paper 001 §4.2, Fig. 1), off when hole_radius = 0: after the
  // weights are computed on the whole cloud, every bond whose segment meets the circle is
  // broken (the paper's "break all bonds crossing the circle"); the particles inside are
  // neither solved nor measured (their bonds to the body are all broken).
  double hole_radius = 0;
  double hole_center[2] = {0.5, 0.5};
  // > 0: the error only over particles at least this far from the hole's circle (a region
  // that does not change with h), to tell the hole's surface layer from the rest.
  double hole_error_margin = 0;
  // Not the paper's (§4 keeps the whole-ball weights, a broken bond weighing 0): the
  // families that lost bonds to the hole get new weights over their intact bonds, exact
  // over the part of the ball they see past the hole. A test of what the whole-ball
  // weights of a cut family cost (docs/paper001.md, Fig. 1).
  bool hole_cut_weights = false;
  bool symmetric_weights = false;  // symmetric_pair_weights (collocation.hpp) on the OBQ weights
  // A circular inclusion (paper 001 §4.3) when inclusion_radius > 0: the particles closer
  // than the radius to inclusion_centre take (inclusion_lambda, inclusion_mu), the others
  // (lambda, mu); a law with pair parameters (LPS) averages them bond by bond (eq. 2.4).
  double inclusion_radius = 0;
  double inclusion_centre[2] = {0.5, 0.5};
  double inclusion_lambda = 0, inclusion_mu = 0;
  bool keep_solution = false;  // fill ManufacturedResult::x, u, exact
};

struct ManufacturedResult {
  double rms_error = 0;
  double rms_component[2] = {0, 0};  // the same norm of u_x - u_x,ex and u_y - u_y,ex alone
  int particles = 0, solved = 0, measured = 0;
  int broken_bonds = 0;  // by the hole, each direction counted
  // hole_cut_weights: the families reweighed over their cut ball, and those that kept the
  // whole-ball weights (too few intact bonds for the space).
  int cut_weight_families = 0, cut_weight_fallbacks = 0;
  bool symmetric_matrix = false;  // the solver used: CHOLMOD when true, UMFPACK otherwise
  double weights_seconds = 0, assembly_seconds = 0, solve_seconds = 0;
  // With keep_solution: every particle's position, computed and exact displacement, [n*2].
  std::vector<double> x, u, exact;
};

// Throws NotUnisolventError when a family that reaches a solved particle is not unisolvent.
ManufacturedResult solve_manufactured(const ManufacturedField& field, const ManufacturedSetup& setup);

}  // namespace pd

// The nonlocal J-integral of paper 004 (Hu, Ha, Bobaru, Silling 2012), eqs. (20)-(21)
// and its Table 1, in the form that holds for every law with an energy kernel.
//
// For a rectangular contour dR around a crack tip (the crack running in -x1 from the
// tip), R the particles inside and Q = Omega \ R the rest:
//
//   J = sum_{right side} W h - sum_{left side} W h                       (W n1 dS)
//     - sum_{i in R} sum_{j in Q} V_i V_j [ t_i<j> . du_j/dx1 - t_j<i> . du_i/dx1 ]
//
// t_i<j> is particle i's force state on bond (i,j): the residual kernel of family i
// writes -V_i V_j t_i<j> as the nodal force of neighbour j (kernel_abi.hpp). The
// derivation is the paper's (virtual crack extension, eqs. 10-19) with
// dW_i/dY_ij = V_j t_i<j> for a general energy W_i of the family, instead of the
// pairwise f/2: docs/paper004.md. For a bond-based law t_j<i> = -t_i<j> = f/2 and it
// is exactly the paper's eq. (21). `pairwise` is eq. (21) applied literally with the
// pair force f_ij = t_i<j> - t_j<i>; it differs from J only for state-based laws.
//
// Discretisation (the paper's): a uniform lattice; du/dx1 by central differences
// along the lattice row (one-sided where a neighbour is missing); W at the contour
// by linear interpolation between the two particles on either side, midpoint rule
// at the lattice rows. R is the particles whose centres lie in the given (closed) box;
// the contour runs halfway between them and the first particles outside.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "assembly/assembler.hpp"
#include "input/scene.hpp"

namespace pd {

struct JIntegralResult {
  JContour contour;              // as given
  Point edge_min{}, edge_max{};  // the contour actually integrated (halfway between lattice lines)
  double contour_term = 0;       // sum W n1 dS
  double bond_term = 0;          // the double sum over bonds leaving R
  double load_term = 0;          // sum_{i in R} b_i . du_i/dx1 (external loads inside R)
  double J = 0;                  // contour_term - bond_term - load_term
  double pairwise = 0;           // contour_term - (eq. 21 with the pair force), = J for bond-based laws
  int inside = 0;                // particles in R
  long long crossing_bonds = 0;  // bonds from R to Q (each once)
};

// Throws std::runtime_error (naming contour.where) when the law has no energy kernel,
// the cloud is not a uniform 2D lattice of spacing h, or the box holds no particle.
// A contour closer than delta to the body's boundary is computed as given (the paper's
// contour (c) is one horizon from it); the skin effect there is the user's to judge.
//
// `external` (may be null): the nodal external forces b_i at u ([n*2], e.g. crack-face
// pressure). Loads on particles inside R add - sum_{i in R} b_i . du_i/dx1 (equilibrium
// with a body force in the derivation; the classical loaded-crack-face term), which keeps
// J path independent when the crack faces inside the contour are loaded.
JIntegralResult j_integral(const FamilyAssembler& assembler, const double* u, double h,
                           const JContour& contour, const double* external = nullptr);

// One line for the run log, and the summary.json entries (docs/scene_format.md).
std::string j_integral_line(const JIntegralResult& r);
nlohmann::ordered_json j_integral_json(const std::vector<JIntegralResult>& results);

}  // namespace pd

// Collocation assembly with non-symmetric quadrature weights (paper 001, eq. 2.13):
// the force density at x_i is  F_i = sum_j (t_i<j> - t_j<i>) omega_{j,i},  where
// omega_{j,i} is the weight of x_j in the quadrature of B_delta(x_i) and in general
// omega_{j,i} != omega_{i,j} (obq_weights.hpp).
//
// How the family-based kernels serve it, without a new kernel ABI. The family of p is
// evaluated with V[k] = omega_{q,p} (its own weights: they enter its horizon sums m,
// theta, K, ... and its force) and V0 = V_p, so the kernel's nodal forces are
//   center p:      V_p sum_q omega_{q,p} t_p<q>        (the first term of F_p, times V_p)
//   neighbour q:  -V_p omega_{q,p} t_p<q>
// while the second term of F_q wants -V_q omega_{p,q} t_p<q>. Every output row of
// neighbour q -- force, tangent row, tangent-vector product -- is therefore multiplied
// by  s = (V_q omega_{p,q}) / (V_p omega_{q,p}).  Rows scale exactly (multiplication and
// division keep relative accuracy), so residual, tangent and JVP stay consistent; the
// result is nodal forces V_q F_q as the rest of the runtime expects. Rows scaled
// differently make the stiffness non-symmetric, and there is no energy.
#pragma once

#include <string>
#include <vector>

#include "discretize/ball_box_moments.hpp"
#include "discretize/reproducing_space.hpp"
#include "particles.hpp"

namespace pd {

struct Collocation {
  std::vector<double> weight;     // [nb] omega_{q,p} for bond b = (p -> q), in the rows of Bonds
  std::vector<double> row_scale;  // [nb] s of the header comment
  // Every pair has V_p w_{q,p} = V_q w_{p,q} (to 1e-13; symmetric_pair_weights makes it so):
  // every row scale is then 1 (set exactly), the pair forces are equal and opposite and
  // the assembly is the energy-based one with weights w as the neighbours' volumes, so
  // an energy law's stiffness is symmetric and its forces are -dE/du.
  bool pair_symmetric = false;
};

// Collocation data from per-bond weights (obq_weights). Needs every bond in both
// directions (a common horizon). Throws std::invalid_argument naming the bond when a
// reverse bond is missing or a weight is exactly zero while its reverse is not (the
// row scale would be infinite). Sets pair_symmetric from the weights themselves.
Collocation make_collocation(const Particles& particles, const Bonds& bonds, std::vector<double> weights);

// Multiplies the rows of a family's local output that belong to neighbours (local
// particles 1..L of particle p's family) by their row scales. `values` holds
// (L+1)*dim rows of `row_length` numbers each (1 for a force vector, (L+1)*dim for
// the dense local tangent).
void scale_neighbour_rows(const Collocation& c, const Bonds& bonds, int p, int row_length, double* values);

// `domain.quadrature: obq`: OBQ weights for `space` (paper 001's, or the law's:
// law_space.hpp) on every unisolvent family, the volume quadrature on the others (corners
// of the body), as collocation data. `description` is set to one line for the run log.
// `body` (a 2D box, nullptr: none): families cut by its faces integrate over the cut ball
// (obq_weights.hpp).
// `symmetric`: the weights are then replaced by symmetric_pair_weights.
Collocation make_obq_collocation(const Particles& particles, const Bonds& bonds,
                                 const ReproducingSpace& space, std::string& description,
                                 const Box2* body = nullptr, bool symmetric = false);

// Pair weights with V_p w'_{q,p} = V_q w'_{p,q} = (V_p w_{q,p} + V_q w_{p,q}) / 2: the pair
// forces of eq. (2.13) are then equal and opposite (linear momentum is conserved), at the
// price of each family's exactness where its weights and its neighbours' differ (faces,
// perturbed clouds). On a regular lattice interior weights already satisfy it.
std::vector<double> symmetric_pair_weights(const Particles& particles, const Bonds& bonds,
                                           const std::vector<double>& weights);

}  // namespace pd

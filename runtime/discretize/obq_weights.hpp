// Optimisation-based quadrature weights (paper 001, eq. 2.12): for each family, the
// least-norm weights omega_{j,i} that integrate every function of a reproducing space
// exactly over the ball B_delta(x_i):
//     argmin sum_j omega_j^2   such that   sum_j f(xi_j) omega_j = int_B f   for f in V_h.
// With A the (m x n) matrix A_fj = f(xi_j) and b the closed-form ball moments, the
// solution is omega = A^T (A A^T)^-1 b, computed from a pivoted QR of A^T (no normal
// equations). The weights are not symmetric: omega_{j,i} != omega_{i,j} in general.
#pragma once

#include <functional>
#include <stdexcept>
#include <vector>

#include "discretize/ball_box_moments.hpp"
#include "discretize/reproducing_space.hpp"
#include "particles.hpp"

namespace pd {

// A family whose bonds cannot integrate the space exactly (too few neighbours, all on
// a line or a conic): A has rank < m. Names the particle.
class NotUnisolventError : public std::runtime_error {
 public:
  NotUnisolventError(int particle, const std::string& message)
      : std::runtime_error(message), particle_(particle) {}
  int particle() const { return particle_; }

 private:
  int particle_;
};

// The weights of one family of n bonds xi[n*dim] with horizon delta (bonds may reach
// delta). `particle` and `center` (its position, dim values) only name it in errors.
// `body` (2D only; nullptr: the whole ball): a family whose ball the body's faces cut
// integrates over B_delta ∩ body instead (ball_box_moments.hpp), the region its bonds
// cover near a free surface.
std::vector<double> obq_family_weights(const ReproducingSpace& space, const double* xi, int n, double delta,
                                       int particle, const double* center, const Box2* body = nullptr);
// The same over any region of the ball: unit_moment(f) is the integral of f over the
// region scaled by 1/delta (the unit ball's moment for the whole ball). Used for the
// families a hole cut (ball_disk_shadow_moment_2d), over their intact bonds.
std::vector<double> obq_family_weights_over(const ReproducingSpace& space, const double* xi, int n,
                                            double delta, int particle, const double* center,
                                            const std::function<double(const BondMonomial&)>& unit_moment);

// The weights of every family, one per bond in the compressed rows of `bonds`. Every bond
// counts whatever its alpha: paper 001 (§4) computes the weights on the perturbed points
// before bonds are broken, and a broken bond then carries weight 0 (eq. 3.1) through alpha.
// `needed` (empty: all) marks the families that get OBQ weights; the others keep the
// volume quadrature (each bond weighs its neighbour's volume): the outer part of a
// Dirichlet layer, whose truncated families may not be unisolvent and whose forces do
// not reach the solved particles.
std::vector<double> obq_weights(const Particles& particles, const Bonds& bonds, const ReproducingSpace& space,
                                const std::vector<char>& needed = {});

// OBQ weights on every family that is unisolvent for the space, the volume quadrature
// on the others (too few bonds near a corner of the body): what a scene with
// `domain.quadrature: obq` uses, reporting the fallback rather than failing, since a
// scene's Dirichlet regions need no exact quadrature.
struct CloudWeights {
  std::vector<double> weights;   // one per bond
  int volume_families = 0;       // families that kept the volume quadrature
  int first_volume_family = -1;  // the lowest such particle, -1 if none
};
CloudWeights obq_weights_where_unisolvent(const Particles& particles, const Bonds& bonds,
                                          const ReproducingSpace& space, const Box2* body = nullptr);

}  // namespace pd

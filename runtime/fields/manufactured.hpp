// Manufactured solutions of paper 001 §4.1 (plane strain, isotropic): a displacement
// field and the body force density that makes it an equilibrium of eq. (1.1).
//
// Sign: the paper's f_1 = <2 lambda + 4 mu, 8 lambda + 16 mu> (eq. 4.2) and
// f_2 = -2 (lambda + 2 mu) u_2 (eq. 4.4) are div(sigma), the opposite of eq. 1.1's
// -div(sigma) = f. The runtime's equilibrium is internal force + body force = 0, so the
// body force density here is b = -div(sigma) = -f_paper.
#pragma once

#include <array>
#include <functional>
#include <string>

namespace pd {

struct ManufacturedField {
  std::string name;
  std::function<std::array<double, 2>(double x, double y)> displacement;
  std::function<std::array<double, 2>(double x, double y, double lambda, double mu)>
      div_stress;  // the paper's f

  std::array<double, 2> body_force(double x, double y, double lambda, double mu) const {
    const auto f = div_stress(x, y, lambda, mu);
    return {-f[0], -f[1]};
  }
};

// u_1 = <x^2, 4 y^2> (eqs. 4.1-4.2): the quadratic patch test.
ManufacturedField paper001_u1();
// u_2 = <sin x sin y, -cos x cos y> (eqs. 4.3-4.4): smooth, for the convergence order.
ManufacturedField paper001_u2();
// u_2 at wavenumber k: <sin kx sin ky, -cos kx cos ky>, div sigma = -2 k^2 (lambda + 2 mu) u.
// k = 1 is the paper's; the others test what set-up would give the paper's Table 1
// magnitudes (docs/paper001.md).
ManufacturedField paper001_u2_wavenumber(double k);

// The hydrostatically loaded circular inclusion of paper 001 §4.3 (eqs. 4.8-4.12), plane
// strain: radius a, inclusion (lambda1, mu1) inside, matrix (lambda2, mu2) outside,
//   u_r = C_A r (r < a),  C_B r + C_C / r (r >= a),  u_theta = 0,
//   C_A = P / (2 (lambda1 + mu1)),
//   C_B = P (lambda1 + mu1 + mu2) / (2 (lambda1 + mu1) (lambda2 + 2 mu2)),
//   C_C = -P a^2 (lambda1 - lambda2 + mu1 - mu2) / (2 (lambda1 + mu1) (lambda2 + 2 mu2)).
// P is the stress inside the inclusion (sigma_rr = sigma_tt = 2 (lambda1 + mu1) C_A = P);
// the paper calls it the far-field stress, but the remote sigma_rr is 2 (lambda2 + mu2) C_B.
struct InclusionCoefficients {
  double A = 0, B = 0, C = 0;
};
InclusionCoefficients paper001_inclusion_coefficients(double P, double a, double lambda1, double mu1,
                                                      double lambda2, double mu2);
// The field centred at (cx, cy); no body force (each phase is in equilibrium, and
// displacement and traction are continuous at r = a).
ManufacturedField paper001_inclusion(double P, double a, double cx, double cy, double lambda1, double mu1,
                                     double lambda2, double mu2);

// Plane-strain Lame parameters from Young's modulus and Poisson's ratio.
std::array<double, 2> lame_from_young_poisson(double E, double nu);

}  // namespace pd

// The Michell (Kirsch) solution of paper 001 §4.2: a traction-free circular hole of radius
// a in an infinite plate under far-field uniaxial tension T along x (eqs. 4.5-4.7).
//
//   u_x = T a / (8 mu) [ r/a (kappa + 1) cos t + 2 a/r ((1 + kappa) cos t + cos 3t) - 2 a^3/r^3 cos 3t ]
//   u_y = T a / (8 mu) [ r/a (kappa - 3) sin t + 2 a/r ((1 - kappa) sin t + sin 3t) - 2 a^3/r^3 sin 3t ]
//
// with (r, t) polar about the hole's centre. kappa = 3 - 4 nu in plane strain and
// (3 - nu)/(1 + nu) in plane stress; in terms of the 2D Lame constants of either case it
// is (lambda + 3 mu)/(lambda + mu), which is the form used here: the runtime's 2D laws take
// (lambda, mu) and are 2D elasticity with those constants. The stress (Kirsch) does not
// depend on kappa:
//   s_xx = T [1 - a^2/r^2 (3/2 cos 2t + cos 4t) + 3/2 a^4/r^4 cos 4t]
//   s_yy = T [ - a^2/r^2 (1/2 cos 2t - cos 4t) - 3/2 a^4/r^4 cos 4t]
//   s_xy = T [ - a^2/r^2 (1/2 sin 2t + sin 4t) + 3/2 a^4/r^4 sin 4t]
// Both are tested against each other (Hooke's law on finite differences of u), against
// equilibrium, the traction-free hole and the far field (tests/runtime/test_michell.cpp).
// Inside the hole (r < a) the formulas are evaluated as written (no physical meaning);
// at r = 0 the displacement is returned as zero.
#pragma once

#include <array>

namespace pd {

struct MichellHole {
  double T = 1;                   // far-field tension along x
  double a = 0.2;                 // hole radius
  double x0 = 0, y0 = 0;          // hole centre
  double lambda = 0.5, mu = 0.5;  // 2D Lame constants (plane strain: those of E, nu)

  double kappa() const { return (lambda + 3 * mu) / (lambda + mu); }
  std::array<double, 2> displacement(double x, double y) const;
  // {s_xx, s_yy, s_xy}
  std::array<double, 3> stress(double x, double y) const;
};

}  // namespace pd

// The elastic part and the yield calibration Mitchell's plastic laws share
// (laws/elastic_plastic.cpp, laws/elastic_plastic_hardening.cpp; equations there and in
// docs/laws.md): Silling's dilatation split of the bond extension, the deviatoric
// stiffness alpha, and the factor that turns the norm of a deviatoric force state into a
// von Mises stress.
#pragma once

#include "pdgen/dsl.hpp"

namespace pdgen {

struct MitchellElasticPart {
  Expr r, l;       // |xi|, |Y| (regularised)
  Expr wa;         // w alpha
  Expr m;          // weighted volume, sum w a |xi|^2 V
  Expr q;          // sum w^2 a |xi|^2 V (the deviatoric moment of the calibration)
  Expr theta;      // dilatation, (n/m) sum w a |xi| e V
  Expr ed;         // deviatoric extension e - theta |xi| / n
  double c = 0;    // 8 in plane strain, 15 in 3D
  Expr stiffness;  // c G / m: t_d = stiffness w a (e_d - e_p)
  // sqrt(2 psi0) / sigma_y: a deviatoric force state of norm ||t_d|| has the von Mises
  // stress ||t_d|| / von_mises_scale in a homogeneous deviatoric state.
  Expr von_mises_scale;
  Expr dilatation_force;  // the isotropic force state's magnitude, (w a / m) n kappa theta |xi|
};

// Declares the sums m, deviatoric_moment and theta, in that order.
inline MitchellElasticPart mitchell_elastic_part(Law& law, int dim, Expr K, Expr G) {
  MitchellElasticPart p;
  p.r = norm(law.xi());
  p.l = law.deformed_length();
  const Expr e = p.l - p.r;
  p.wa = law.w() * law.alpha();
  p.m = law.sum("m", p.wa * p.r * p.r * law.V());
  p.q = law.sum("deviatoric_moment", law.w() * p.wa * p.r * p.r * law.V());
  const double n = dim;
  p.theta = law.dilatation_sum("theta", Expr(n) / p.m * p.wa * p.r * e * law.V());
  p.ed = e - p.theta * p.r / n;
  const Expr kappa = dim == 2 ? K + G / 3 : K;
  p.c = dim == 2 ? 8.0 : 15.0;
  p.stiffness = p.c * G / p.m;
  // psi0 = c^2 q sigma_y^2 / (48 m^2) in plane strain, / (90 m^2) in 3D (elastic_plastic.cpp).
  p.von_mises_scale = p.c * sqrt(p.q / (dim == 2 ? 24.0 : 45.0)) / p.m;
  p.dilatation_force = p.wa / p.m * n * kappa * p.theta * p.r;
  return p;
}

}  // namespace pdgen

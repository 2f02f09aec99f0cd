// The kinematics and the zero-energy-mode control that the correspondence laws share
// (laws/correspondence.cpp, laws/correspondence_plastic.cpp; paper 000 section 2.4, paper
// 003 eqs. 13-15): the shape tensors, F = N K^-1 and the small strain, and Silling's
// stabilisation term on the non-affine part of each bond.
#pragma once

#include <cmath>

#include "pdgen/dsl.hpp"

namespace pdgen {

struct CorrespondenceKinematics {
  Expr wa;    // w alpha
  Mat Kinv;   // the inverse shape tensor, K = sum w a xi (x) xi V
  Mat F;      // N K^-1, N = sum w a Y (x) xi V
  Mat eps;    // (F + F^T) / 2 - I
  Expr bulk;  // the bond-based micromodulus c of the stabilisation (laws/bond_based.cpp)
};

// Declares the sums "shape" and "deformed_shape", in that order.
inline CorrespondenceKinematics correspondence_kinematics(Law& law, int dim, Expr Kb, Expr G) {
  CorrespondenceKinematics k;
  k.wa = law.w() * law.alpha();
  const Mat K = law.sum("shape", k.wa * law.V() * outer(law.xi(), law.xi()));
  const Mat N = law.sum("deformed_shape", k.wa * law.V() * outer(law.Y(), law.xi()));
  k.Kinv = inverse(K);
  k.F = N * k.Kinv;
  k.eps = Expr(0.5) * (k.F + transpose(k.F)) - identity(dim);
  const Expr delta = law.delta();
  k.bulk = dim == 2 ? 12 * (Kb + G / 3) / (M_PI * pow(delta, 3)) : 18 * Kb / (M_PI * pow(delta, 4));
  return k;
}

// Silling's stabilisation force wa (G_s c / (w_bar delta)) z, z = Y - F xi, with the mean
// influence w_bar = sum w a V / sum a V (laws/correspondence.cpp says why) and G_s the
// parameter `stab` (default 1); declares the sums "influence_volume" and "intact_volume",
// then the parameter. *stiffness gets G_s c / (w_bar delta).
inline Vec silling_stabilisation(Law& law, const CorrespondenceKinematics& k, Expr* stiffness = nullptr) {
  const Expr w_bar =
      law.sum("influence_volume", k.wa * law.V()) / law.sum("intact_volume", law.alpha() * law.V());
  const Expr s = law.param("stab", 1.0) * k.bulk / (w_bar * law.delta());
  if (stiffness) *stiffness = s;
  return k.wa * s * (law.Y() - k.F * law.xi());
}

}  // namespace pdgen

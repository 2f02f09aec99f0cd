// Silling's deformation-gradient (correspondence) law, paper 000 section 2.4:
//   K = sum w a xi (x) xi V          (shape tensor: a moment, eq. 18)
//   N = sum w a Y (x) xi V           (deformed shape tensor: a state, eq. 19)
//   F = N K^-1                       (per particle, eq. 20)
//   eps = (F + F^T)/2 - I,  sigma = lambda tr(eps) I + 2 G eps,  lambda = K_bulk - 2G/3
//   t = w a sigma K^-1 xi            (eq. 21)
// The paper prints eps = (F + F^T)/2; the identity must be subtracted for a linear
// strain (otherwise the undeformed body is stressed). In plane strain the 2D
// components obey the same law with the 3D lambda. The force is the exact derivative
// of W = lambda/2 tr(eps)^2 + G eps:eps through F (sigma is symmetric), so the law
// declares that energy. The linear strain is not objective: a rigid rotation stresses
// the body (tests/laws/test_law_physics.cpp documents it).
//
// Zero-energy-mode control (the law's deformations that leave F unchanged):
// * Silling's stabilisation (paper 003 eqs. 13-15): t += w a (G_s c / (w_bar delta)) z,
//   z = Y - F xi the non-affine part of the bond. As printed, the term divides by
//   w0 = integral of w dV, which has units of volume and makes the term inconsistent
//   with P K^-1 xi (stress/length^(d+1)); we divide by the *mean* influence
//   w_bar = sum w a V / sum a V (dimensionless) instead, so G_s (parameter "stab") is a
//   pure number. c is the bond-based micromodulus of laws/bond_based.cpp (12 kappa2 /
//   (pi delta^3) in 2D, 18 K / (pi delta^4) in 3D, with kappa2 = K + G/3). The term is
//   the exact derivative of W_s = (G_s c / (2 w_bar delta)) sum w a |z|^2 V, since
//   sum w a z (x) xi V = N - F K = 0, so the law keeps an energy.
// * Littlewood's bond-level hourglass penalty: t += w a C_h c ((z . n) / |xi|) n, n = Y/|Y|,
//   a spring on the non-affine stretch of each bond (parameter "hourglass" = C_h). It is
//   not the derivative of an energy (the law declares none; its tangent is not symmetric).
#include <cmath>

#include "correspondence_kinematics.hpp"
#include "pdgen/dsl.hpp"

using namespace pdgen;

namespace {
enum class Stabilisation { None, Silling, Littlewood };

Law correspondence(const std::string& name, int dim, Stabilisation stab, const std::string& summary) {
  Law law(name, dim, summary);
  const Expr Kb = law.param("K"), G = law.param("G");
  const CorrespondenceKinematics kin = correspondence_kinematics(law, dim, Kb, G);
  const Expr wa = kin.wa;
  const Mat &Kinv = kin.Kinv, &F = kin.F, &eps = kin.eps;
  const Expr lambda = Kb - 2 * G / 3;
  const Mat sigma = lambda * trace(eps) * identity(dim) + 2 * G * eps;
  Vec t = wa * (sigma * (Kinv * law.xi()));
  Expr W = lambda / 2 * trace(eps) * trace(eps) + G * ddot(eps, eps);
  if (stab != Stabilisation::None) {
    const Expr r = norm(law.xi());
    const Expr c = kin.bulk;
    const Vec z = law.Y() - F * law.xi();
    if (stab == Stabilisation::Silling) {
      Expr k;
      t = t + silling_stabilisation(law, kin, &k);
      W = W + k / 2 * law.sum("nonaffine_energy", wa * dot(z, z) * law.V());
    } else {
      const Expr l = law.deformed_length();
      const Vec n = law.Y() / l;
      t = t + wa * law.param("hourglass", 1.0) * c * dot(z, n) / r * n;
    }
  }
  law.force(t);
  // F = N K^-1 is exact for any weights: the force sum needs w xi, K needs w xi (x) xi. The
  // stabilisation terms vanish under a homogeneous deformation (z = 0), so need nothing.
  law.reproducing_terms(1, 2, 0);
  if (stab != Stabilisation::Littlewood) law.energy(W);
  for (int i = 0; i < dim; ++i)
    for (int j = i; j < dim; ++j) law.output("strain_" + std::to_string(i) + std::to_string(j), eps(i, j));
  return law;
}
}  // namespace

PDGEN_LAW(correspondence_plane_strain) {
  return correspondence(
      "correspondence_plane_strain", 2, Stabilisation::None,
      "deformation-gradient law, linear elastic, plane strain (paper 000 eqs. 18-21); params K (3D bulk), G");
}
PDGEN_LAW(correspondence_3d) {
  return correspondence("correspondence_3d", 3, Stabilisation::None,
                        "deformation-gradient law, linear elastic, 3D (paper 000 eqs. 18-21); params K, G");
}
PDGEN_LAW(correspondence_silling_plane_strain) {
  return correspondence("correspondence_silling_plane_strain", 2, Stabilisation::Silling,
                        "correspondence with Silling's zero-energy-mode control (paper 003 eqs. 13-15), "
                        "plane strain; params K, G, stab");
}
PDGEN_LAW(correspondence_silling_3d) {
  return correspondence(
      "correspondence_silling_3d", 3, Stabilisation::Silling,
      "correspondence with Silling's zero-energy-mode control (paper 003 eqs. 13-15), 3D; params K, G, stab");
}
PDGEN_LAW(correspondence_littlewood_plane_strain) {
  return correspondence(
      "correspondence_littlewood_plane_strain", 2, Stabilisation::Littlewood,
      "correspondence with Littlewood's bond-level hourglass penalty, plane strain; params K, G, hourglass");
}
PDGEN_LAW(correspondence_littlewood_3d) {
  return correspondence(
      "correspondence_littlewood_3d", 3, Stabilisation::Littlewood,
      "correspondence with Littlewood's bond-level hourglass penalty, 3D; params K, G, hourglass");
}

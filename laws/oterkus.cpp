// Oterkus's dilatation law, paper 000 section 2.3, plane strain, with a, b, d generalised
// to any influence function through discrete horizon sums (moments):
//   theta = d sum w a e (n . xi/|xi|) V,  e = |Y| - |xi|, n = Y/|Y|             (eq. 8)
//   t = 2 w a [ a_ d (n . xi/|xi|) theta + b e ] n                              (eq. 9)
//   d = 2 / sum w a |xi| V                                                      (eq. 12)
//   b = G / (2 sum w a xi_1^2 xi_2^2 / |xi|^2 V)                                (eqs. 15-16)
//   a_ = (2 kappa2 - b sum w a |xi|^2 V) / 4                                    (eqs. 13, 17)
// Eqs. (16)-(17) are garbled in the text; these forms follow from the paper's own
// matching conditions: theta = 2s and W = 2 kappa2 s^2 under isotropic stretch s, and
// W = G s^2 / 2 under simple shear Y = (I + sA) xi, with W = a_ theta^2 + b sum w a e^2 V
// (eq. 10). The force (9) keeps only the component of dW/dY along n (it drops the
// derivative of n . xi/|xi|), so it is not the exact derivative of (10): the law declares
// no energy and its tangent is not symmetric.
// 3D (paper 003 eqs. 7-8; Madenci & Oterkus's 3D constants d = 9/(4 pi delta^4),
// b = 15 mu/(2 pi delta^5), a = (K - 5 mu/3)/2 for the constant influence) with the same
// discrete matching: theta = 3s under isotropic stretch gives d = 3 / sum w a |xi| V; simple
// shear gives the same b = G / (2 sum w a xi_1^2 xi_2^2/|xi|^2 V); W = 9 K s^2 / 2 under
// isotropic stretch gives a = (9 K / 2 - b sum w a |xi|^2 V) / 9. On a full ball with a
// constant weight these are the book's constants (sum xi_1^2 xi_2^2/|xi|^2 = m2 / 15).
#include <cmath>

#include "pdgen/dsl.hpp"

using namespace pdgen;

namespace {
// d_moment: the horizon sum whose inverse (times 2) is d. Eq. (12) matched to theta = 2s
// gives sum w a |xi| V; paper 000 section 3 says instead that d's sum "is identical to the
// summation for m" (sum w a |xi|^2 V). The second variant is kept to test whether that
// reading explains the paper's non-convergence on biaxial compression (docs/paper000.md).
Law oterkus(const std::string& name, const std::string& summary, bool d_from_m, int dim = 2) {
  Law law(name, dim, summary);
  // 2D: W = 2 kappa2 s^2 and theta = 2 s under isotropic stretch; 3D: W = 9 K s^2 / 2, theta = 3 s.
  const Expr bulk_energy = dim == 2 ? 2 * law.param("kappa2") : 4.5 * law.param("K");
  const double theta_per_s = dim;
  const Expr G = law.param("G");
  const Expr r = norm(law.xi()), l = law.deformed_length(), e = l - r;
  const Expr wa = law.w() * law.alpha();
  const Expr cosine = dot(law.Y(), law.xi()) / (l * r);
  const Expr m1 = d_from_m ? law.sum("m2", wa * r * r * law.V()) : law.sum("m1", wa * r * law.V());
  const Expr m2 = d_from_m ? m1 : law.sum("m2", wa * r * r * law.V());
  const Expr mx = law.sum("mx", wa * pow(law.xi()[0] * law.xi()[1], 2) / (r * r) * law.V());
  const Expr d = theta_per_s / m1;
  const Expr b = G / (2 * mx);
  const Expr a = (bulk_energy - b * m2) / (theta_per_s * theta_per_s);
  const Expr theta = law.dilatation_sum("theta", d * wa * e * cosine * law.V());
  law.force(2 * wa * (a * d * cosine * theta + b * e) * law.Y() / l);
  law.claim_angular_momentum_balance();  // ordinary: t is parallel to Y
  // Linearised: the stress w xi^4 / |xi|^2 and force w xi^3 / |xi|^2 of the b e term, and
  // theta's w xi (x) xi / |xi| with its force sum w xi / |xi| (law_space.hpp).
  law.reproducing_terms(3, 4, 2);
  law.reproducing_terms(1, 2, 1);
  return law;
}
}  // namespace

PDGEN_LAW(oterkus_plane_strain) {
  return oterkus("oterkus_plane_strain",
                 "Oterkus dilatation law, plane strain (paper 000 eqs. 8-17, a, b, d from discrete sums); "
                 "params kappa2, G",
                 false);
}

PDGEN_LAW(oterkus_3d) {
  return oterkus("oterkus_3d",
                 "Oterkus dilatation law, 3D (paper 003 eqs. 7-8, a, b, d from discrete sums); params K, G",
                 false, 3);
}

PDGEN_LAW(oterkus_paper_d_plane_strain) {
  return oterkus(
      "oterkus_paper_d_plane_strain",
      "Oterkus law with d = 2 / sum w a |xi|^2 V (paper 000 section 3's reading of eq. 12; a study variant, "
      "not dimensionally consistent); params kappa2, G",
      true);
}

// Paper 003's OSB law with its continuum constants (Madenci & Oterkus's 2D constants for
// the constant influence w = 1 on a whole disc of radius delta, per unit thickness):
//   d = 2 / int |xi| dA = 3 / (pi delta^3),   b = G / (2 int xi_1^2 xi_2^2/|xi|^2 dA) = 8 G / (pi delta^4),
//   a = (2 kappa2 - b int |xi|^2 dA) / 4 = (kappa2 - 2 G) / 2,
// the same for every particle, instead of oterkus_plane_strain's sums over each particle's
// own (discrete, possibly truncated) family. Inside a whole lattice family the two differ
// by the quadrature error of the sums; near a free edge the continuum constants leave the
// cut family softer (the surface effect the discrete sums partly correct). A study
// variant for paper 003's horizon sweep (docs/paper003.md). The influence is fixed to
// w = 1, as the constants assume: the scene's influence function is not read.
PDGEN_LAW(oterkus_continuum_plane_strain) {
  Law law(
      "oterkus_continuum_plane_strain", 2,
      "Oterkus dilatation law, plane strain, with paper 003's continuum constants for w = 1 "
      "(d = 3/(pi delta^3), b = 8G/(pi delta^4), a = (kappa2 - 2G)/2; the scene's influence is not read); "
      "params kappa2, G");
  const Expr kappa2 = law.param("kappa2"), G = law.param("G"), delta = law.delta();
  const Expr r = norm(law.xi()), l = law.deformed_length(), e = l - r;
  const Expr cosine = dot(law.Y(), law.xi()) / (l * r);
  const Expr d = 3 / (M_PI * pow(delta, 3));
  const Expr b = 8 * G / (M_PI * pow(delta, 4));
  const Expr a = (kappa2 - 2 * G) / 2;
  const Expr theta = law.dilatation_sum("theta", d * law.alpha() * e * cosine * law.V());
  law.force(2 * law.alpha() * (a * d * cosine * theta + b * e) * law.Y() / l);
  law.claim_angular_momentum_balance();  // ordinary: t is parallel to Y
  law.built_in_kernel("constant influence w = 1", {{1.0, 0}});
  law.reproducing_terms(3, 4, 2);
  law.reproducing_terms(1, 2, 1);
  return law;
}

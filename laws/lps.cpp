// The linear peridynamic solid (LPS) of paper 001, eqs. (2.1)-(2.3) with the signs of
// (2.13) (eq. 2.1 prints u(x) - u(y) in the second term; (2.13) has u_j - u_i, which is
// the one consistent with the first term and with Silling's law). Linear in the
// displacement eta = Y - xi, so a Newton solve converges in one step. Per family (the
// pair equation 2.13 sums the families of x and y):
//   theta = (d/m) sum w a xi . eta V,  m = sum w a |xi|^2 V
//   t = (w a / m) [ C_a (lambda - mu) theta xi + (C_b / 2) mu (xi (x) xi / |xi|^2) eta ]
// with C_a = 2, C_b = 16 in 2D and C_a = 3, C_b = 30 in 3D (paper 001); w plays the
// role of the paper's kernel K(r) (the paper uses K = 1/r: influence "inv" with delta=1
// scaled). Energy: W = C_a (lambda - mu)/(2d) theta^2 + (C_b mu / (4m)) sum w a (n . eta)^2 V.
// Heterogeneous materials: lambda and mu in the force are the bond's pair values, the
// harmonic mean of eq. 2.4 (Law::pair_param), so the two families of a pair give
// (lambda_ij - mu_ij)(theta_i + theta_j) and C_b mu_ij as eq. (2.13) has them. That force
// has no potential when the pair values differ within a family (a bond's coefficient
// multiplies its own family's theta only, so the tangent is not symmetric there): the
// energy below keeps the center's lambda - mu in the dilatation term and is the
// potential only where the family's material is uniform (the shear term, bond by bond,
// uses mu_ij and stays exact).
//
// Corrected dilatation (eqs. 3.2-3.5): theta = (d/m) sum w a xi . M^+ eta V with
// M = (d/m) sum w a xi (x) xi V (M = I for a full interior family), exact for linear
// fields near free surfaces and broken bonds. Eqs. (3.3) and (3.4) disagree on whether
// M or its inverse appears; the consistent reading (theta = div u for linear u) is M^+.
// M^+ is the Tikhonov pseudo-inverse M (M^2 + eps I)^-1, eps = (1e-8 tr M)^2: the inverse
// for well-conditioned M, and zero on the null space of a singular M (collinear bonds).
// lps_corrected_* use M^+ xi in the force's dilatation term too, so that the force is
// the derivative of the energy (an energy, a symmetric tangent).
//
// Paper 001 exactly as written (lps_paper_*, lps_paper_corrected_*):
//  - the kernel is the paper's K = 1/r (eq. 2.5), built in: the scene's influence
//    function is not used (as the bond-based laws do not use it);
//  - m is the analytic weighted volume m(delta) of eq. (2.3) for every family, broken or
//    cut or not: 2 pi delta^3 / 3 (2D) and pi delta^4 (3D), the paper's values after
//    eq. (2.5), delta the particle's horizon. A family that lost bonds keeps m(delta),
//    where lps_* divide by the discrete m over the intact bonds;
//  - lps_paper_corrected_* put M^+ into the dilatation only (eqs. 3.4-3.5): the force's
//    dilatation term keeps xi as eq. (2.13) has it. That force is not the derivative of
//    any energy (dtheta/deta carries M^+ xi, the force xi), so the law declares none and
//    its tangent is not symmetric. With the analytic m the d/m(delta) of eq. (3.4)
//    cancels against that of M in (3.5): theta = sum K a xi . (sum K a xi (x) xi V)^+ eta V.
#include <numbers>

#include "pdgen/dsl.hpp"

using namespace pdgen;

namespace {
enum class Volume { discrete, analytic };  // m = sum w a |xi|^2 V, or m(delta)
enum class Dilatation { plain, corrected_with_energy, corrected_dilatation_only };

Law lps(const std::string& name, int dim, Volume volume, Dilatation dilatation, const std::string& summary) {
  Law law(name, dim, summary);
  const Expr lambda = law.param("lambda"), mu = law.param("mu");
  const double Ca = dim == 2 ? 2.0 : 3.0, Cb = dim == 2 ? 16.0 : 30.0;
  const Expr r = norm(law.xi());
  const bool paper = volume == Volume::analytic;
  // The kernel: the scene's influence w, or the paper's K = 1/r.
  const Expr wa = (paper ? 1 / r : law.w()) * law.alpha();
  const Vec eta = law.Y() - law.xi();
  const Expr m = paper ? (dim == 2 ? 2 * std::numbers::pi / 3 * pow(law.delta(), 3)
                                   : std::numbers::pi * pow(law.delta(), 4))
                       : law.sum("m", wa * r * r * law.V());
  Vec g = law.xi();  // the bond vector the dilatation sees
  if (dilatation != Dilatation::plain) {
    const Mat M = law.sum("dilatation_moment", Expr(dim) / m * wa * law.V() * outer(law.xi(), law.xi()));
    const Expr eps = pow(1e-8 * trace(M), 2);
    const Mat Mplus = M * inverse(M * M + eps * identity(dim));
    g = Mplus * law.xi();
  }
  const Expr theta = law.dilatation_sum("theta", Expr(dim) / m * wa * dot(g, eta) * law.V());
  const Vec force_dir = dilatation == Dilatation::corrected_dilatation_only ? law.xi() : g;
  const Expr stretch = dot(law.xi(), eta) / (r * r);  // (n . eta) / |xi|
  const Expr lambda_ij = law.pair_param("lambda", PairMean::harmonic),
             mu_ij = law.pair_param("mu", PairMean::harmonic);
  law.force(wa / m * (Ca * (lambda_ij - mu_ij) * theta * force_dir + Cb / 2 * mu_ij * stretch * law.xi()));
  // Linearised: the shear term w xi^3 / |xi|^2 : eps, its stress w xi^4 / |xi|^2; m, theta
  // and M are traces of those (law_space.hpp). The paper's kernel replaces w there.
  law.reproducing_terms(3, 4, 2);
  if (paper) law.built_in_kernel("its built-in kernel K = 1/r", {{1.0, -1}});  // (r/delta)^-1 up to 1/delta
  if (dilatation != Dilatation::corrected_dilatation_only) {
    const Expr shear = law.sum("bond_energy", mu_ij * wa * pow(dot(law.xi(), eta), 2) / (r * r) * law.V());
    law.energy(Ca * (lambda - mu) / (2 * dim) * theta * theta + Cb / (4 * m) * shear);
  }
  return law;
}
}  // namespace

PDGEN_LAW(lps_plane_strain) {
  return lps("lps_plane_strain", 2, Volume::discrete, Dilatation::plain,
             "linear peridynamic solid (paper 001 eqs. 2.1-2.3, 2.13) with the discrete m of the intact "
             "bonds, plane strain; params lambda, mu");
}
PDGEN_LAW(lps_3d) {
  return lps("lps_3d", 3, Volume::discrete, Dilatation::plain,
             "linear peridynamic solid (paper 001 eqs. 2.1-2.3, 2.13) with the discrete m of the intact "
             "bonds, 3D; params lambda, mu");
}
PDGEN_LAW(lps_corrected_plane_strain) {
  return lps("lps_corrected_plane_strain", 2, Volume::discrete, Dilatation::corrected_with_energy,
             "LPS with the corrected dilatation of paper 001 eqs. 3.2-3.5 (pseudo-inverse), M+ also in the "
             "force (an energy), plane strain; params lambda, mu");
}
PDGEN_LAW(lps_corrected_3d) {
  return lps("lps_corrected_3d", 3, Volume::discrete, Dilatation::corrected_with_energy,
             "LPS with the corrected dilatation of paper 001 eqs. 3.2-3.5 (pseudo-inverse), M+ also in the "
             "force (an energy), 3D; params lambda, mu");
}
PDGEN_LAW(lps_paper_plane_strain) {
  return lps("lps_paper_plane_strain", 2, Volume::analytic, Dilatation::plain,
             "paper 001's LPS as written: K = 1/r built in (the scene's influence is not used), analytic "
             "m(delta) = 2 pi delta^3/3 for every family, plane strain; params lambda, mu");
}
PDGEN_LAW(lps_paper_3d) {
  return lps("lps_paper_3d", 3, Volume::analytic, Dilatation::plain,
             "paper 001's LPS as written: K = 1/r built in (the scene's influence is not used), analytic "
             "m(delta) = pi delta^4 for every family, 3D; params lambda, mu");
}
PDGEN_LAW(lps_paper_corrected_plane_strain) {
  return lps("lps_paper_corrected_plane_strain", 2, Volume::analytic, Dilatation::corrected_dilatation_only,
             "paper 001's LPS as written with the corrected dilatation (eqs. 3.4-3.5, M+ in the dilatation "
             "only; no energy): K = 1/r built in, analytic m(delta), plane strain; params lambda, mu");
}
PDGEN_LAW(lps_paper_corrected_3d) {
  return lps("lps_paper_corrected_3d", 3, Volume::analytic, Dilatation::corrected_dilatation_only,
             "paper 001's LPS as written with the corrected dilatation (eqs. 3.4-3.5, M+ in the dilatation "
             "only; no energy): K = 1/r built in, analytic m(delta), 3D; params lambda, mu");
}

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
// For the energy to stay exact the force uses M^+ xi in the dilatation term.
#include "pdgen/dsl.hpp"

using namespace pdgen;

namespace {
Law lps(const std::string& name, int dim, bool corrected, const std::string& summary) {
  Law law(name, dim, summary);
  const Expr lambda = law.param("lambda"), mu = law.param("mu");
  const double Ca = dim == 2 ? 2.0 : 3.0, Cb = dim == 2 ? 16.0 : 30.0;
  const Expr wa = law.w() * law.alpha();
  const Expr r = norm(law.xi());
  const Vec eta = law.Y() - law.xi();
  const Expr m = law.sum("m", wa * r * r * law.V());
  Vec g = law.xi();  // the bond vector the dilatation sees
  if (corrected) {
    const Mat M = law.sum("dilatation_moment", Expr(dim) / m * wa * law.V() * outer(law.xi(), law.xi()));
    const Expr eps = pow(1e-8 * trace(M), 2);
    const Mat Mplus = M * inverse(M * M + eps * identity(dim));
    g = Mplus * law.xi();
  }
  const Expr theta = law.sum("theta", Expr(dim) / m * wa * dot(g, eta) * law.V());
  const Expr stretch = dot(law.xi(), eta) / (r * r);  // (n . eta) / |xi|
  const Expr lambda_ij = law.pair_param("lambda", PairMean::harmonic), mu_ij = law.pair_param("mu", PairMean::harmonic);
  law.force(wa / m * (Ca * (lambda_ij - mu_ij) * theta * g + Cb / 2 * mu_ij * stretch * law.xi()));
  const Expr shear = law.sum("bond_energy", mu_ij * wa * pow(dot(law.xi(), eta), 2) / (r * r) * law.V());
  law.energy(Ca * (lambda - mu) / (2 * dim) * theta * theta + Cb / (4 * m) * shear);
  law.output("dilatation", theta);
  return law;
}
}  // namespace

PDGEN_LAW(lps_plane_strain) {
  return lps("lps_plane_strain", 2, false, "linear peridynamic solid (paper 001 eqs. 2.1-2.3, 2.13), plane strain; params lambda, mu");
}
PDGEN_LAW(lps_3d) { return lps("lps_3d", 3, false, "linear peridynamic solid (paper 001 eqs. 2.1-2.3, 2.13), 3D; params lambda, mu"); }
PDGEN_LAW(lps_corrected_plane_strain) {
  return lps("lps_corrected_plane_strain", 2, true,
             "LPS with the corrected dilatation of paper 001 eqs. 3.2-3.5 (pseudo-inverse), plane strain; params lambda, mu");
}
PDGEN_LAW(lps_corrected_3d) {
  return lps("lps_corrected_3d", 3, true, "LPS with the corrected dilatation of paper 001 eqs. 3.2-3.5 (pseudo-inverse), 3D; params lambda, mu");
}

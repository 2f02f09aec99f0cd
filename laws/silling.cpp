// Silling's dilatation (linear peridynamic solid) law, paper 000 section 2.2.
//
// Plane strain, eqs. (5)-(7) in the energy-matched form (papers/README.md):
//   m = sum w a |xi|^2 V,  theta = (2/m) sum w a |xi| e V,  e = |Y| - |xi|,
//   t = (w a / m) [ 2 kappa2 theta |xi| + 8 G (e - theta |xi| / 2) ] Y/|Y|,
// with kappa2 = K + G/3 the plane-strain bulk modulus (K the 3D bulk modulus) and a
// the bond factor (1 intact, 0 broken). The strain-energy density
//   W = kappa2 theta^2 / 2 + (4 G / m) sum w a (e - theta |xi|/2)^2 V
// gives t = dW/de exactly (the deviatoric sum's derivative through theta vanishes).
// 3D, eqs. (2)-(4): theta = (3/m) sum ..., t = (w a/m) [3 K theta |xi| + 15 G e_d],
// e_d = e - theta |xi|/3, W = K theta^2/2 + (15 G/(2m)) sum w a e_d^2 V.
#include "pdgen/dsl.hpp"

using namespace pdgen;

namespace {
Law silling(const std::string& name, int dim, const std::string& summary) {
  Law law(name, dim, summary);
  const Expr K = law.param("K"), G = law.param("G");
  const Expr r = norm(law.xi()), l = law.deformed_length();  // |Y|, finite at Y = 0
  const Expr e = l - r;
  const Expr wa = law.w() * law.alpha();
  const Expr m = law.sum("m", wa * r * r * law.V());
  const double n = dim;  // theta = (n/m) sum ..., deviatoric extension e - theta r / n
  const Expr theta = law.dilatation_sum("theta", Expr(n) / m * wa * r * e * law.V());
  const Expr ed = e - theta * r / n;
  const Expr bulk = dim == 2 ? K + G / 3 : K;
  const double shear = dim == 2 ? 8.0 : 15.0;
  law.force(wa / m * (n * bulk * theta * r + shear * G * ed) * law.Y() / l);
  law.claim_angular_momentum_balance();  // ordinary: t is parallel to Y
  // Linearised (u = eps x): e = xi . eps xi / |xi|, so t ~ w xi^3 / |xi|^2 : eps and its
  // stress w xi^4 / |xi|^2; m and theta are traces of those (law_space.hpp).
  law.reproducing_terms(3, 4, 2);
  const Expr dev = law.sum("deviatoric_energy", wa * ed * ed * law.V());
  law.energy(bulk / 2 * theta * theta + shear / 2 * G / m * dev);
  return law;
}
}  // namespace

PDGEN_LAW(silling_plane_strain) {
  return silling("silling_plane_strain", 2,
                 "Silling dilatation law, plane strain (paper 000 eqs. 5-7); params K (3D bulk), G");
}

PDGEN_LAW(silling_3d) {
  return silling("silling_3d", 3, "Silling dilatation law, 3D (paper 000 eqs. 2-4); params K, G");
}

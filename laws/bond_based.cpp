// Bond-based microelastic (PMB without breaking) laws, papers 002 section 1 and 004
// eqs. (1)-(7): pairwise force f = c(|xi|) s e, s = (|Y| - |xi|)/|xi|, e = Y/|Y|,
// energy w = c s^2 |xi| / 2 per bond pair. With the nodal-force convention each of the
// two families carries half the pair force: t = a c s e / 2, W = (1/4) sum a c s^2 |xi| V.
// The micromodulus constants match the bulk energy density under isotropic stretch
// (derivation in docs/laws.md), with kappa the 2D bulk modulus (kappa2 = lambda + G:
// plane strain, or plane stress through the equivalent material) or K in 3D:
//   2D constant c = 12 kappa / (pi delta^3)   conical c = 48 kappa / (pi delta^3) (1 - |xi|/delta)
//   3D constant c = 18 K / (pi delta^4)       conical c = 90 K / (pi delta^4) (1 - |xi|/delta)
// (2D plane stress, nu = 1/3: 12 kappa = 9E and 48 kappa = 36E = 24E/(1 - nu), paper 004 eq. 7.)
// Bond-based models have a fixed Poisson ratio (1/4 plane strain and 3D, 1/3 plane stress);
// only the bulk modulus is matched.
#include <cmath>

#include "pdgen/dsl.hpp"

using namespace pdgen;

namespace {
Law bond_based(const std::string& name, int dim, bool conical, const std::string& summary) {
  Law law(name, dim, summary);
  const Expr kappa = law.param(dim == 2 ? "kappa2" : "K");
  const Expr r = norm(law.xi()), l = law.deformed_length();
  const Expr delta = law.delta();
  const double coef = dim == 2 ? (conical ? 48.0 : 12.0) : (conical ? 90.0 : 18.0);
  Expr c = coef * kappa / (M_PI * pow(delta, dim + 1));
  if (conical) c = c * (1 - r / delta);
  const Expr s = (l - r) / r;
  law.force(law.alpha() * c * s / 2 * law.Y() / l);
  law.energy(law.sum("bond_energy", law.alpha() * c * s * s * r * law.V() / 4));
  law.claim_angular_momentum_balance();  // t is parallel to Y
  law.fixed_poisson_ratio(0.25);
  // Linearised: t ~ c(r) xi^3 / |xi|^3 : eps (s = xi . eps xi / |xi|^2), stress c(r) xi^4 / |xi|^3.
  law.reproducing_terms(3, 4, 3);
  if (conical)
    law.built_in_kernel("micromodulus 1 - r/delta", {{1.0, 0}, {-1.0, 1}});
  else
    law.built_in_kernel("constant micromodulus", {{1.0, 0}});
  return law;
}
}  // namespace

PDGEN_LAW(bond_based_constant_2d) {
  return bond_based("bond_based_constant_2d", 2, false,
                    "bond-based microelastic, constant micromodulus, 2D (plane strain, or plane stress via "
                    "the material); param kappa2");
}
PDGEN_LAW(bond_based_conical_2d) {
  return bond_based("bond_based_conical_2d", 2, true,
                    "bond-based microelastic, conical micromodulus (paper 004 eq. 7), 2D; param kappa2");
}
PDGEN_LAW(bond_based_constant_3d) {
  return bond_based("bond_based_constant_3d", 3, false,
                    "bond-based microelastic, constant micromodulus, 3D; param K");
}
PDGEN_LAW(bond_based_conical_3d) {
  return bond_based("bond_based_conical_3d", 3, true,
                    "bond-based microelastic, conical micromodulus, 3D; param K");
}

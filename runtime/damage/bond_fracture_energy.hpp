// The fracture energy of a pairwise (bond-based) law as a function of its critical
// stretch, from the law's own generated energy kernel: G0 = s0^2 * g(delta).
//
// G0 is the work to break every bond crossing a unit length of a straight crack (unit
// area in 3D) in the bulk, each bond at stretch s0 (Silling & Askari 2005; paper 004
// section 2 for the 2D micromodulus). With the pair energy omega(xi, s) = c(xi) s^2 xi / 2
// (paper 004 eq. 3), counting the bonds of length xi that cross the plane:
//   2D: G0 = s0^2 int_0^delta c(xi) xi^3 dxi          (the bonds of length xi at distance
//       z < xi cos(theta) from the plane: int_0^xi 2 acos(z/xi) dz = 2 xi per unit area)
//   3D: G0 = (pi/2) s0^2 int_0^delta c(xi) xi^4 dxi   (solid angle of the cap: pi xi)
// so G0 = 3 kappa delta s0^2 / pi for the 2D constant micromodulus, 2.4 kappa delta s0^2 / pi
// for the conical one (paper 004 eq. 7), 9 K delta s0^2 / 5 and 3 K delta s0^2 / 2 in 3D.
//
// c(xi) is read off the kernel: a family of one bond of length xi (unit volumes, the
// scene's influence weight) stretched by a small s_ref has energy omega / 2 (each end's
// family carries half the pair, kernel_abi.hpp). The quadrature is composite
// Gauss-Legendre over (0, delta), exact for the polynomial micromoduli.
#pragma once

#include <vector>

#include "kernel_abi.hpp"

namespace pd {

// Pairwise laws: no moments and no state components, so a bond's force depends only on
// that bond. Only these have a G0(s0) independent of the deformation of the families.
bool is_pairwise_law(const abi::LawDescriptor& law);

// g = G0 / s0^2 for a pairwise law of dimension law.dim with parameters `params` (one
// material) and influence `weight`. Throws std::invalid_argument when the law is not
// pairwise or has no energy kernel, and std::runtime_error when its bond energy is not
// quadratic in the stretch (then G0(s0) is not s0^2 g).
double pairwise_fracture_energy_per_stretch2(const abi::LawDescriptor& law, const std::vector<double>& params,
                                             double (*weight)(double r, double delta), double delta);

}  // namespace pd

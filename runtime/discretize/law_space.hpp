// The reproducing space a law needs (issue 14): the integrands of the law's horizon sums
// for a homogeneous deformation, so that OBQ weights exact for them make a family's
// discrete response equal the continuum law's -- its moduli, and zero force.
//
// Linearise a law at u = 0 under u = eps x (eps symmetric): every bond's extension is
// e = xi . eps xi / |xi| and its force state is a sum of terms (scalar) * xi. The two
// quantities that decide a homogeneous deformation are the family's force sum
// sum_j t_j omega_j (zero in the continuum: the collocation force 2 sum_j t_i<j> omega_ji
// when every family is exact) and its stress sum_j t_j (x) xi_j omega_j (the continuum
// stress of a homogeneous deformation, Silling & Lehoucq 2008). With w the influence:
//
//  - silling_*, lps_* (also lps_corrected_*): m = S w r^2 and theta ~ S w xi(x)xi : eps are
//    traces of the stress sum S w xi^4/r^2 : eps; the force sum needs w xi^3/r^2 (and
//    w xi, its trace). Space: w xi^b / r^2, |b| = 3 and 4. lps_paper_* (paper 001 as
//    written) have K = 1/r built in: xi^b / r^3 whatever the scene's influence.
//  - oterkus_*: e = xi . eps xi / r, n (x) xi = xi (x) xi / r: theta ~ S w xi(x)xi/r : eps,
//    d = dim / S w r (its trace), stress ~ S w xi^4/r^2 : eps, a from S w r^2 and b from
//    S w xi1^2 xi2^2/r^2 (both in that span), force sum S w xi/r and S w xi^3/r^2.
//    Space: w xi^b / r^2, |b| = 3, 4, and w xi^b / r, |b| = 1, 2.
//  - correspondence_*: F = N K^-1 is exact for any weights, so the stress is; the force
//    sum needs S w xi = 0 and K = S w xi(x)xi the continuum's. Space: w xi^b, |b| = 1, 2.
//  - bond_based_*: the kernel ignores w; its micromodulus c(r) (constant, or conical
//    1 - r/delta) plays its part. Space: c(r)/c(0) xi^b / r^3, |b| = 3, 4.
//
// Each law declares its groups in its source (law.reproducing_terms, the rows above) and
// a law that ignores w its built-in kernel (law.built_in_kernel); pdgen copies them into
// the LawDescriptor, and whether the weight is the influence or that kernel is the
// generator's derived ignores_influence. Nothing here reads a law's name.
//
// Counts in 2D / 3D: Silling and LPS 9 / 25, Oterkus 14 / 34, correspondence 5 / 9,
// bond-based 9 / 25 (paper 001's space: 15 / 35). The stabilised correspondence laws'
// extra sums (S w alpha V, S alpha V) scale a term that vanishes under a homogeneous
// deformation, so they need no exactness.
//
// The influence enters as a radial weight, which the closed-form ball moments handle
// when w(r, delta) is a sum of powers of rho = r/delta (rho^-2 ... rho^6): every
// influence of laws/influence.cpp is. influence_power_series finds the powers by a fit
// and refuses a function that is not such a sum.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "discretize/reproducing_space.hpp"
#include "kernel_abi.hpp"

namespace pd {

// w(rho delta, delta) = C(delta) sum_k c_k rho^k for every delta, checked at delta = 1 and
// 2.7 to 1e-11 relative (the constant C does not change OBQ weights). Throws
// std::invalid_argument naming the influence when no such sum with -2 <= k <= 6 fits.
std::vector<RadialPower> influence_power_series(double (*weight)(double r, double delta),
                                                std::string_view name);

// The space of the table above for the law `law` from its descriptor alone: the groups
// LawDescriptor::reproducing_groups (the law declares them, pdgen Law::reproducing_terms)
// in dimension `dim`, times the influence `weight` when the law reads it, or the kernel
// the law declares built in when it ignores the influence (LawDescriptor::kernel_terms;
// the constant 1 is the empty weight). Throws std::invalid_argument naming the law when
// it declares no groups, or ignores the influence and declares no kernel, or when a sum is
// not integrable at r = 0 for this influence (the continuum law itself diverges there).
ReproducingSpace law_reproducing_space(const abi::LawDescriptor& law, int dim,
                                       double (*weight)(double r, double delta), std::string_view influence);
// The same for the law named `law` in the generated law table (abi::find_law); throws
// std::invalid_argument naming it when the table has no such law.
ReproducingSpace law_reproducing_space(std::string_view law, int dim,
                                       double (*weight)(double r, double delta), std::string_view influence);

}  // namespace pd

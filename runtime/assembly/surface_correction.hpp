// Surface correction factors (paper 003 eq. 19; Madenci & Oterkus's dilatation and
// distortion factors), for any generated law.
//
// A particle near a free surface has a truncated family and answers a homogeneous strain
// with a response that differs from an interior particle's. Madenci & Oterkus correct
// the OSB law's dilatation term and its distortion (deviatoric) term separately, one
// factor each per particle, from two trial deformations. A generic law has no labelled
// terms, so the generated kernels take two per-bond factors (abi::Family):
//   - dilatation_factor scales the bond's term in the sum a law marks as its dilatation
//     (pdgen Law::dilatation_sum: Silling, LPS, Oterkus);
//   - force_factor scales the bond's whole force state.
// For Oterkus's force t = 2w[a d cos theta + b e] n the first corrects the dilatation
// term (theta's bond sum, as the references' G_d) and the second, with the first, the
// whole force (the references' G_b on the b e term).
//
// The trials, for the response R(eps) = -(1/V0) sum_a df_a . (eps x_a), df = (df/dy) dy,
// dy_a = eps x_a (the quadratic form of the family's stiffness, 2W for an energy law),
// through the law's generated JVP kernel at the reference configuration, so it is exact,
// linear in eps, and defined for laws without an energy (Oterkus's):
//   dilatation  eps = I;
//   deviatoric  the sum of R over an orthonormal basis of traceless strains (each of
//               Frobenius norm sqrt 2): in 2D diag(1,-1) and the symmetric shear, in 3D
//               five; the sum does not depend on the basis, so no direction is chosen.
// The reference is the full family of an infinite lattice (discretize/lattice_family.hpp).
// Two ways to choose particle i's factors s_d, s_f (SurfaceMatch):
//   terms      (the references' recipe) s_d = theta_full / theta_i under the dilatation
//              trial (the law's output "dilatation"), then s_f matches the deviatoric
//              response with s_d in place. Always defined. For a law whose constants come
//              from its own family's moments (every dilatation law here: d = 2 / m1,
//              theta / m) theta is already exact, s_d = 1, and s_f also scales the
//              dilatation response, which was right: it ends s_f too stiff there.
//   responses  both responses matched at once: R = s_f (A + s_d B) is linear in
//              (s_f, s_f s_d), a 2x2 system. Exact for both trials, but singular where the
//              dilatation term moves both trials alike: for Silling's and Oterkus's laws
//              its weight (2 kappa2 - 4 G, plane strain) vanishes at Poisson ratio 1/4, and
//              factors that are not positive throw.
//   directions (Madenci and Oterkus's 3D recipe) one pair of factors per axis k from the
//              uniaxial stretch eps = e_k e_k: s_d,k = theta_full / theta_i, then s_f,k
//              matches R with the dilatation factors in place. A bond of direction n
//              carries the ellipsoid's radius (sum_k (n_k / s_k)^2)^(-1/2) -- s_k along
//              axis k. The summed trials above cannot see a cut family's anisotropy: for
//              Silling's 3D law, whose constants come from the family's own m, a family cut
//              through its centre answers the dilatation and the sum over the deviatoric
//              basis exactly as the full one does (every factor 1, to rounding), yet at a
//              free face under uniaxial stress its theta is 1.3x the continuum's, because
//              the bonds in the face plane count in full. Only a trial along each axis sees
//              that (docs/paper003.md "The 3D cube").
// A law without a dilatation sum gets s_d = 1 and s_f from the dilatation trial (paper
// 002's trial, so for a pairwise law s_f equals paper 002's compensation factor); under
// directions, from each axis' stretch.
//
// Per bond, as in the references, the mean of the two ends' factors (per axis under
// directions, before the ellipsoid). With a factor not 1
// an energy law's force is no longer the derivative of its energy (the references'
// corrected force is not either): the assembler then reports no energy and a
// non-symmetric stiffness. The kernels run with alpha folded to 1, so a pre-crack's cut
// bonds count as present, as in paper 002's compensation.
#pragma once

#include <vector>

#include "input/quadrature.hpp"
#include "input/surface_match.hpp"
#include "kernel_abi.hpp"
#include "particles.hpp"

namespace pd {

struct SurfaceCorrectionInputs {
  const abi::LawDescriptor* law = nullptr;
  const std::vector<std::vector<double>>* params = nullptr;  // per material, law order
  double delta = 0, h = 0;                                   // horizon, lattice spacing
  Quadrature quadrature = Quadrature::Volume;
  double (*influence)(double r, double delta) = nullptr;
  SurfaceMatch match = SurfaceMatch::Terms;
};

// Per particle, [n * components]: one factor each (terms, responses) or one per axis
// (directions: components = dim).
struct SurfaceFactors {
  int components = 1;
  std::vector<double> dilatation, force;
};

// The two trial responses of one family whose every bond carries dilatation factor s_d
// and force factor s_f (f.moments must be set; f.Y is ignored: the reference is used).
struct TrialResponse {
  double dilatation = 0, deviatoric = 0;
};
TrialResponse trial_response(const abi::LawDescriptor& law, const abi::Family& f, double s_d, double s_f);

// s_d and s_f of every particle. Throws std::runtime_error naming the particle when a
// factor is not a positive finite number.
SurfaceFactors surface_correction_factors(const Particles& p, const Bonds& b,
                                          const SurfaceCorrectionInputs& in);

// Bonds::surface_dilatation (only for a law with a dilatation sum) and
// Bonds::surface_force: per bond the mean of its two ends' factors, and with one factor
// per axis the ellipsoid's radius along the bond.
void apply_surface_correction(Bonds& b, const SurfaceFactors& s, bool has_dilatation_sum);

}  // namespace pd

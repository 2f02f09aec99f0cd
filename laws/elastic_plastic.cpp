// Mitchell's ordinary state-based elastic-perfectly-plastic law: J. A. Mitchell, "A
// nonlocal, ordinary, state-based plasticity model for peridynamics", Sandia report
// SAND2011-3166 (2011); the model Peridigm calls "Elastic Plastic".
//
// The elastic part is Silling's dilatation law (laws/silling.cpp): e = |Y| - |xi|,
// theta = (n/m) sum w a |xi| e V, the deviatoric extension e_d = e - theta |xi| / n
// (n = dim). The deviatoric extension splits into an elastic and a plastic part,
// e_d = e_d^e + e_p, and the bond's plastic extension e_p is the law's history:
//   t = (w a / m) n kappa theta |xi| + t_d,     t_d = alpha w a (e_d - e_p),   alpha = c G / m
// (kappa = K + G/3, c = 8 in plane strain; kappa = K, c = 15 in 3D), along Y/|Y|. Yield is
// on the norm of the deviatoric force state over the horizon, f(t_d) = ||t_d||^2 / 2 - psi0,
// ||t_d||^2 = sum t_d^2 V. The return map of a step is closed-form (Mitchell section 4):
// with the trial state t_tr = alpha w a (e_d - e_p,n) from the committed e_p,n,
//   s = sqrt(2 psi0 / max(||t_tr||^2, 2 psi0))   (1 when the trial state is elastic)
//   t_d = s t_tr,     e_p,n+1 = e_p,n + (1 - s) (e_d - e_p,n),
// so e_d - e_p,n+1 = s (e_d - e_p,n) and t_d = alpha w a (e_d - e_p,n+1) as it must. The
// force is written through s, an explicit function of the deformation and the committed
// history, so pdgen's tangent is the algorithmic tangent of the step (the derivative of the
// active branch of max, and of ||t_tr|| through the horizon sum: off-diagonal blocks).
//
// psi0. Mitchell gives psi0 = 25 sigma_y^2 / (8 pi delta^5) for w = 1 in 3D, from the
// continuum integral over a full sphere. Here psi0 is calibrated on the family itself:
// under a homogeneous deviatoric strain eps (e_d = |xi| n.eps.n) the isotropic average of
// (n.eps.n)^2 is (2/15) eps:eps in 3D and eps:eps / 4 in the plane, so
//   ||t_d||^2 = alpha^2 q k eps:eps,   q = sum w^2 a |xi|^2 V,   k = 2/15 (3D), 1/4 (2D),
// and von Mises yield (3/2 s:s = sigma_y^2, s = 2 G eps, so G^2 eps:eps = sigma_y^2 / 6) gives
//   psi0 = c^2 q sigma_y^2 / (90 m^2) (3D),   c^2 q sigma_y^2 / (48 m^2) (plane strain).
// With w = 1 over the continuum sphere (q = m = 4 pi delta^5 / 5) this is Mitchell's value;
// on a discrete or truncated family, and for any influence function, it keeps the yield
// stress of a homogeneous deviatoric state at sigma_y. Plane strain: the yield is on the
// in-plane deviatoric extension (Mitchell's 2D reading); it is von Mises for in-plane
// deviatoric states (pure shear), not for plane-strain states whose in-plane dilatation
// puts a deviator into the out-of-plane direction (docs/laws.md).
#include "mitchell_plastic.hpp"
#include "pdgen/dsl.hpp"

using namespace pdgen;

namespace {
Law elastic_plastic(const std::string& name, int dim, const std::string& summary) {
  Law law(name, dim, summary);
  const Expr K = law.param("K"), G = law.param("G");
  // The test value yields the automatic checks' random families (strain ~ 0.05, G ~ 0.4),
  // so their tangent checks exercise the plastic branch; tests/laws/test_history.cpp
  // covers the elastic and unloading branches.
  const Expr sigma_y = law.param("sigma_y", 0.01, ParamRange::positive);
  const MitchellElasticPart p = mitchell_elastic_part(law, dim, K, G);
  const Expr ep = law.bond_history("plastic_extension", 0.0);
  const Expr trial = p.stiffness * p.wa * (p.ed - ep);  // t_tr, the trial deviatoric force state
  const Expr trial_norm2 = law.sum("trial_deviatoric_norm2", trial * trial * law.V());
  const Expr psi0 = p.c * p.c / (dim == 2 ? 48.0 : 90.0) * p.q * sigma_y * sigma_y / (p.m * p.m);
  // Exactly 1 on the elastic branch (not 2 psi0 / 2 psi0 rounded), so that an elastic step
  // leaves e_p unchanged to the bit; the max keeps the unused branch finite at zero strain.
  const Expr scale = select(trial_norm2 - 2 * psi0, sqrt(2 * psi0 / max(trial_norm2, 2 * psi0)), Expr(1.0));
  law.force((p.dilatation_force + scale * trial) * law.Y() / p.l);
  law.update(ep, ep + (1 - scale) * (p.ed - ep));
  law.claim_angular_momentum_balance();  // ordinary: t is parallel to Y
  // The elastic response is Silling's (an unyielded body, e_p = 0): the same space.
  law.reproducing_terms(3, 4, 2);
  // Outputs, evaluated with the committed history: after a converged yielding step the
  // trial state of the same deformation lies on the yield surface (ratio 1 to rounding),
  // so "yielding" is 1 on or beyond the surface, within a relative 1e-8.
  law.output("yield_ratio", sqrt(trial_norm2 / (2 * psi0)));
  law.output("yielding", select(trial_norm2 - (1 - 1e-8) * 2 * psi0, Expr(1.0), Expr(0.0)));
  // The plastic extension's size at the particle: the rms plastic bond strain e_p / |xi|
  // over the family, weighted as m weights the bonds (0 in a virgin body).
  law.output("plastic_strain", sqrt(law.sum("plastic_moment", p.wa * ep * ep * law.V()) / p.m));
  return law;
}
}  // namespace

PDGEN_LAW(elastic_plastic_plane_strain) {
  return elastic_plastic("elastic_plastic_plane_strain", 2,
                         "Mitchell's ordinary state-based elastic-perfectly-plastic law (SAND2011-3166; "
                         "Peridigm's Elastic Plastic), plane strain; params K (3D bulk), G, sigma_y; history "
                         "plastic_extension per bond");
}

PDGEN_LAW(elastic_plastic_3d) {
  return elastic_plastic("elastic_plastic_3d", 3,
                         "Mitchell's ordinary state-based elastic-perfectly-plastic law (SAND2011-3166; "
                         "Peridigm's Elastic Plastic), 3D; params K, G, sigma_y; history plastic_extension "
                         "per bond");
}

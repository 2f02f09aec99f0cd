// Mitchell's ordinary state-based viscoelastic law, a standard linear solid per bond: J. A.
// Mitchell, "A non-local, ordinary-state-based viscoelasticity model for peridynamics",
// Sandia report SAND2011-8064 (2011); the model Peridigm calls "Viscoelastic".
//
// The dilatation part is the elastic one of Mitchell's laws (laws/mitchell_plastic.hpp).
// The deviatoric extension e_d splits into a spring of weight 1 - lambda_i in parallel
// with a Maxwell arm of weight lambda_i whose dashpot carries a back extension e_b:
//   t_d = (c G / m) w a ((1 - lambda_i) e_d + lambda_i (e_d - e_b)) = (c G / m) w a (e_d - lambda_i e_b),
//   d e_b / dt = (e_d - e_b) / tau_b.
// The time integration is the law paper's: over a step of length dt with e_d linear in time
// between its committed value e_d,n and the current e_d, the ODE is solved exactly,
//   e_b,n+1 = decay e_b,n + (1 - decay) e_d,n + beta (e_d - e_d,n),
//   decay = exp(-dt / tau_b),  beta = 1 - (tau_b / dt) (1 - decay),
// so a piecewise-linear strain history is integrated without time-discretisation error
// (tests/laws/test_viscoelastic.cpp checks a ramp and hold against the closed form). The
// force uses e_b,n+1, and the generated tangent is the algorithmic one: the deviatoric
// stiffness times 1 - lambda_i beta. dt -> 0 gives beta -> 0, the instantaneous (glassy)
// response of modulus G; a long hold relaxes it to (1 - lambda_i) G. Peridigm keeps the same two
// per-bond variables (e_b and the previous e_d); its tangent is by finite differences.
#include "mitchell_plastic.hpp"
#include "pdgen/dsl.hpp"

using namespace pdgen;

namespace {
Law viscoelastic(const std::string& name, int dim, const std::string& summary) {
  Law law(name, dim, summary);
  const Expr K = law.param("K"), G = law.param("G");
  const Expr lambda_i = law.param("lambda_i", 0.6, ParamRange::unit_interval);
  const Expr tau_b = law.param("tau_b", 0.7, ParamRange::positive);
  const MitchellElasticPart p = mitchell_elastic_part(law, dim, K, G);
  const Expr eb = law.bond_history("back_extension", 0.0);
  const Expr ed_n = law.bond_history("deviatoric_extension", 0.0);
  const Expr x = law.time_step() / tau_b;
  const Expr decay = exp(-x);
  // beta = 1 - (1 - exp(-x)) / x loses every digit to cancellation as x -> 0 and is 0/0 at
  // x = 0: below 1e-4 its series x/2 - x^2/6 + x^3/24 (next term x^4/120 < 1e-18) is used.
  const Expr beta = select(x - 1e-4, 1 - (1 - decay) / x, x / 2 - x * x / 6 + x * x * x / 24);
  const Expr eb_new = decay * eb + (1 - decay) * ed_n + beta * (p.ed - ed_n);
  const Expr deviatoric = p.stiffness * p.wa * (p.ed - lambda_i * eb_new);
  law.force((p.dilatation_force + deviatoric) * law.Y() / p.l);
  law.update(eb, eb_new);
  law.update(ed_n, p.ed);
  // Output, from the committed history: the size of the viscous arm's back extension at the
  // particle, the rms back strain e_b / |xi| over the family, weighted as m weights the bonds
  // (0 in a virgin body; it approaches the deviatoric strain as a held body relaxes).
  law.output("back_strain", sqrt(law.sum("back_moment", p.wa * eb * eb * law.V()) / p.m));
  law.claim_angular_momentum_balance();  // ordinary: t is parallel to Y
  law.reproducing_terms(3, 4, 2);        // Silling's law's space, as the plastic laws
  return law;
}
}  // namespace

PDGEN_LAW(viscoelastic_plane_strain) {
  return viscoelastic(
      "viscoelastic_plane_strain", 2,
      "Mitchell's ordinary state-based viscoelastic law, a standard linear solid per bond "
      "(SAND2011-8064; Peridigm's Viscoelastic), plane strain; params K (3D bulk), G, lambda_i, "
      "tau_b; history back_extension and deviatoric_extension per bond; reads the time step");
}

PDGEN_LAW(viscoelastic_3d) {
  return viscoelastic("viscoelastic_3d", 3,
                      "Mitchell's ordinary state-based viscoelastic law, a standard linear solid per bond "
                      "(SAND2011-8064; Peridigm's Viscoelastic), 3D; params K, G, lambda_i, tau_b; history "
                      "back_extension and deviatoric_extension per bond; reads the time step");
}

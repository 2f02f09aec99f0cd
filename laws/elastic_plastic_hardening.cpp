// Mitchell's ordinary state-based elastic-plastic law with linear isotropic hardening: J. A.
// Mitchell, "A nonlocal, ordinary, state-based plasticity model for peridynamics", Sandia
// report SAND2011-3166 (2011); the model Peridigm calls "Elastic Plastic Hardening".
//
// The elastic part, the deviatoric split and the yield calibration are those of the
// perfectly plastic law (laws/elastic_plastic.cpp, laws/mitchell_plastic.hpp): the trial
// deviatoric force state t_tr = alpha w a (e_d - e_p,n) from the committed plastic
// extension e_p,n, and its von Mises stress sigma_tr = ||t_tr|| / beta, where beta =
// sqrt(2 psi0) / sigma_y makes a homogeneous deviatoric state's sigma_tr the continuum's
// von Mises stress. The yield stress grows with a per-particle equivalent plastic strain
// lambda: sigma_y(lambda) = sigma_y + H lambda. The return is the continuum radial return
// (Simo and Hughes, Computational Inelasticity, section 3.3.1) on that scalar:
//   f = sigma_tr - sigma_y - H lambda_n;   elastic (f <= 0): s = 1, nothing changes;
//   plastic: d_lambda = f / (3 G + H),  lambda_n+1 = lambda_n + d_lambda,
//            s = (sigma_y + H lambda_n+1) / sigma_tr  (= 1 - 3 G d_lambda / sigma_tr),
//   t_d = s t_tr,   e_p,n+1 = e_p,n + (1 - s) (e_d - e_p,n).
// Under a homogeneous deviatoric strain the bond extensions are a linear image of the strain
// tensor, so this is the continuum return exactly and lambda is the equivalent plastic
// strain; H = 0 gives the perfectly plastic law (s = sigma_y / sigma_tr). Mitchell and
// Peridigm keep a per-point lambda too; here its increment is the consistency condition of
// the linear hardening law solved in closed form (no local iteration), so the generated
// tangent, through d_lambda's dependence on ||t_tr||, is the algorithmic tangent.
#include "mitchell_plastic.hpp"
#include "pdgen/dsl.hpp"

using namespace pdgen;

namespace {
Law elastic_plastic_hardening(const std::string& name, int dim, const std::string& summary) {
  Law law(name, dim, summary);
  const Expr K = law.param("K"), G = law.param("G");
  // Test values the automatic checks' random strains (~0.05, G ~ 0.4) exceed: plastic
  // branch with hardening.
  const Expr sigma_y = law.param("sigma_y", 0.01, ParamRange::positive);
  const Expr H = law.param("H", 0.05, ParamRange::non_negative);
  const MitchellElasticPart p = mitchell_elastic_part(law, dim, K, G);
  const Expr ep = law.bond_history("plastic_extension", 0.0);
  const Expr lambda = law.particle_history("equivalent_plastic_strain", 0.0);
  const Expr trial = p.stiffness * p.wa * (p.ed - ep);
  const Expr trial_norm2 = law.sum("trial_deviatoric_norm2", trial * trial * law.V());
  const Expr yield_n = sigma_y + H * lambda;  // the committed yield stress
  // Yield is decided on the squares, ||t_tr||^2 > beta^2 sigma_y,n^2, as in the perfectly
  // plastic law: without a square root the elastic side is exact (a floored sigma_tr equal
  // to sigma_y,n up to rounding would yield by 1e-16 and move the history off its bits).
  const Expr beta2 = p.von_mises_scale * p.von_mises_scale;
  const Expr yielding = trial_norm2 - beta2 * yield_n * yield_n;
  // The max keeps sigma_tr, and its derivative in the unused branch, finite at zero strain;
  // where the law yields it is the trial norm itself.
  const Expr sigma_tr = sqrt(max(trial_norm2, beta2 * yield_n * yield_n)) / p.von_mises_scale;
  const Expr d_lambda = select(yielding, (sigma_tr - yield_n) / (3 * G + H), Expr(0.0));
  // Exactly 1 on the elastic branch: an elastic step leaves the history unchanged to the bit.
  const Expr scale = select(yielding, (yield_n + H * d_lambda) / sigma_tr, Expr(1.0));
  law.force((p.dilatation_force + scale * trial) * law.Y() / p.l);
  law.update(ep, ep + (1 - scale) * (p.ed - ep));
  law.update(lambda, lambda + d_lambda);
  law.claim_angular_momentum_balance();  // ordinary: t is parallel to Y
  law.reproducing_terms(3, 4, 2);        // unyielded, Silling's law: the same space
  // Outputs with the committed history: 1 on or beyond the yield surface within 1e-8.
  law.output("yield_ratio", sqrt(trial_norm2) / (p.von_mises_scale * yield_n));
  law.output("yielding",
             select(sqrt(trial_norm2) / p.von_mises_scale - (1 - 1e-8) * yield_n, Expr(1.0), Expr(0.0)));
  law.output("equivalent_plastic_strain", lambda);
  law.output("yield_stress", yield_n);
  return law;
}
}  // namespace

PDGEN_LAW(elastic_plastic_hardening_plane_strain) {
  return elastic_plastic_hardening(
      "elastic_plastic_hardening_plane_strain", 2,
      "Mitchell's ordinary state-based elastic-plastic law with linear isotropic hardening (SAND2011-3166; "
      "Peridigm's Elastic Plastic Hardening), plane strain; params K (3D bulk), G, sigma_y, H; history "
      "plastic_extension per bond, equivalent_plastic_strain per particle");
}

PDGEN_LAW(elastic_plastic_hardening_3d) {
  return elastic_plastic_hardening(
      "elastic_plastic_hardening_3d", 3,
      "Mitchell's ordinary state-based elastic-plastic law with linear isotropic hardening (SAND2011-3166; "
      "Peridigm's Elastic Plastic Hardening), 3D; params K, G, sigma_y, H; history plastic_extension per "
      "bond, equivalent_plastic_strain per particle");
}

// Small-strain J2 plasticity with linear isotropic hardening in Silling's correspondence law
// (paper 000 section 2.4), stabilised by Silling's zero-energy-mode control (paper 003
// eqs. 13-15, as laws/correspondence.cpp): the F-based plasticity Peridigm offers as its
// correspondence plasticity models, whose tangent Peridigm forms by finite differences.
//
//   F = N K^-1,  eps = (F + F^T)/2 - I  (plane strain: eps_zz = 0), as laws/correspondence.cpp
//   e = dev(eps - eps_p,n)  (3 x 3; eps_p trace-free, the committed plastic strain)
//   s_tr = 2 G e,  q_tr = sqrt(3/2 s_tr : s_tr),  sigma_y,n = sigma_y + H lambda_n
//   yield if q_tr > sigma_y,n: d_lambda = (q_tr - sigma_y,n) / (3 G + H)   (radial return)
//   s = scale s_tr,  scale = (sigma_y,n + H d_lambda) / q_tr  (1 on the elastic branch)
//   eps_p,n+1 = eps_p,n + (1 - scale) e,  lambda_n+1 = lambda_n + d_lambda
//   sigma = K tr(eps) I + s,  t = w a sigma K^-1 xi + Silling's stabilisation term.
// (1 - scale) e = d_lambda (3/2) s_tr / q_tr: the flow is along the trial deviator. The
// return is closed form, so the generated tangent, through scale's dependence on q_tr and
// through F on every bond, is the algorithmic (consistent) tangent of the step.
//
// History per particle: the plastic strain's components (plane strain xx, yy, zz, xy: the
// out-of-plane component flows too, since the 3D deviator has one; 3D xx, yy, zz, xy, xz,
// yz) and the equivalent plastic strain lambda. The yield test compares squares (3/2 s:s
// against sigma_y,n^2), so an elastic step leaves the history unchanged to the bit.
// With sigma_y far above the stress the law is laws/correspondence.cpp's Silling-
// stabilised law (tests/laws/test_correspondence_plastic.cpp checks it).
#include <array>
#include <string>

#include "correspondence_kinematics.hpp"
#include "pdgen/dsl.hpp"

using namespace pdgen;

namespace {
Law correspondence_j2(const std::string& name, int dim, const std::string& summary) {
  Law law(name, dim, summary);
  const Expr Kb = law.param("K"), G = law.param("G");
  // The test values the automatic checks' random strains (~0.05, G ~ 0.4) exceed.
  const Expr sigma_y = law.param("sigma_y", 0.01, ParamRange::positive);
  const Expr H = law.param("H", 0.05, ParamRange::non_negative);
  const CorrespondenceKinematics kin = correspondence_kinematics(law, dim, Kb, G);
  const Mat& eps = kin.eps;

  // The committed plastic strain as a symmetric 3 x 3 tensor.
  const char* axis = "xyz";
  std::array<std::array<Expr, 3>, 3> ep;
  std::vector<std::pair<int, int>> stored;
  for (int i = 0; i < 3; ++i) stored.emplace_back(i, i);
  for (int i = 0; i < dim; ++i)
    for (int j = i + 1; j < dim; ++j) stored.emplace_back(i, j);
  std::vector<Expr> history;
  for (const auto& [i, j] : stored) {
    history.push_back(law.particle_history(std::string("plastic_strain_") + axis[i] + axis[j], 0.0));
    ep[i][j] = ep[j][i] = history.back();
  }
  if (dim == 2) ep[0][2] = ep[2][0] = ep[1][2] = ep[2][1] = Expr(0.0);
  const Expr lambda = law.particle_history("equivalent_plastic_strain", 0.0);

  // The trial deviator of the elastic strain (3 x 3; plane strain eps_zz = 0).
  const auto total = [&](int i, int j) { return i < dim && j < dim ? eps(i, j) : Expr(0.0); };
  const Expr tr = trace(eps);
  std::array<std::array<Expr, 3>, 3> e;
  Expr q2 = 0.0;  // 3/2 s_tr : s_tr
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      e[i][j] = total(i, j) - ep[i][j] - (i == j ? tr / 3 : Expr(0.0));
      q2 = q2 + 1.5 * (2 * G * e[i][j]) * (2 * G * e[i][j]);
    }
  const Expr yield_n = sigma_y + H * lambda;
  const Expr yielding = q2 - yield_n * yield_n;
  // The max keeps q_tr, and its derivative in the unused branch, finite at zero strain.
  const Expr q = sqrt(max(q2, yield_n * yield_n));
  const Expr d_lambda = select(yielding, (q - yield_n) / (3 * G + H), Expr(0.0));
  const Expr scale = select(yielding, (yield_n + H * d_lambda) / q, Expr(1.0));

  Mat sigma(dim);
  for (int i = 0; i < dim; ++i)
    for (int j = 0; j < dim; ++j) sigma(i, j) = (i == j ? Kb * tr : Expr(0.0)) + scale * 2 * G * e[i][j];
  // The stress on the bonds, and Silling's stabilisation (elastic) on their non-affine part.
  law.force(kin.wa * (sigma * (kin.Kinv * law.xi())) + silling_stabilisation(law, kin));

  for (std::size_t k = 0; k < stored.size(); ++k) {
    const auto [i, j] = stored[k];
    law.update(history[k], history[k] + (1 - scale) * e[i][j]);
  }
  law.update(lambda, lambda + d_lambda);
  // A homogeneous deformation of a body with uniform history has a uniform stress: the
  // correspondence law's space.
  law.reproducing_terms(1, 2, 0);
  // Outputs with the committed history: 1 on or beyond the yield surface within 1e-8.
  law.output("yield_ratio", sqrt(q2) / yield_n);
  law.output("yielding", select(sqrt(q2) - (1 - 1e-8) * yield_n, Expr(1.0), Expr(0.0)));
  law.output("equivalent_plastic_strain", lambda);
  law.output("yield_stress", yield_n);
  return law;
}
}  // namespace

PDGEN_LAW(correspondence_plastic_plane_strain) {
  return correspondence_j2(
      "correspondence_plastic_plane_strain", 2,
      "correspondence law with small-strain J2 plasticity, linear isotropic hardening and radial return, "
      "Silling-stabilised (paper 000 eqs. 18-21, paper 003 eqs. 13-15), plane strain; params K (3D bulk), G, "
      "sigma_y, H, stab; history plastic_strain_xx, _yy, _zz, _xy and equivalent_plastic_strain per "
      "particle");
}

PDGEN_LAW(correspondence_plastic_3d) {
  return correspondence_j2(
      "correspondence_plastic_3d", 3,
      "correspondence law with small-strain J2 plasticity, linear isotropic hardening and radial return, "
      "Silling-stabilised (paper 000 eqs. 18-21, paper 003 eqs. 13-15), 3D; params K, G, sigma_y, H, stab; "
      "history plastic_strain_xx, _yy, _zz, _xy, _xz, _yz and equivalent_plastic_strain per particle");
}

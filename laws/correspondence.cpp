// Silling's deformation-gradient (correspondence) law, paper 000 section 2.4:
//   K = sum w a xi (x) xi V          (shape tensor: a moment, eq. 18)
//   N = sum w a Y (x) xi V           (deformed shape tensor: a state, eq. 19)
//   F = N K^-1                       (per particle, eq. 20)
//   eps = (F + F^T)/2 - I,  sigma = lambda tr(eps) I + 2 G eps,  lambda = K_bulk - 2G/3
//   t = w a sigma K^-1 xi            (eq. 21)
// The paper prints eps = (F + F^T)/2; the identity must be subtracted for a linear
// strain (otherwise the undeformed body is stressed). In plane strain the 2D
// components obey the same law with the 3D lambda. The force is the exact derivative
// of W = lambda/2 tr(eps)^2 + G eps:eps through F (sigma is symmetric), so the law
// declares that energy. The linear strain is not objective: a rigid rotation stresses
// the body (tests/laws/test_correspondence.cpp documents it).
#include "pdgen/dsl.hpp"

using namespace pdgen;

namespace {
Law correspondence(const std::string& name, int dim, const std::string& summary) {
  Law law(name, dim, summary);
  const Expr Kb = law.param("K"), G = law.param("G");
  const Expr wa = law.w() * law.alpha();
  const Mat K = law.sum("shape", wa * law.V() * outer(law.xi(), law.xi()));
  const Mat N = law.sum("deformed_shape", wa * law.V() * outer(law.Y(), law.xi()));
  const Mat Kinv = inverse(K);
  const Mat F = N * Kinv;
  const Mat eps = Expr(0.5) * (F + transpose(F)) - identity(dim);
  const Expr lambda = Kb - 2 * G / 3;
  const Mat sigma = lambda * trace(eps) * identity(dim) + 2 * G * eps;
  law.force(wa * (sigma * (Kinv * law.xi())));
  law.energy(lambda / 2 * trace(eps) * trace(eps) + G * ddot(eps, eps));
  for (int i = 0; i < dim; ++i)
    for (int j = i; j < dim; ++j) law.output("strain_" + std::to_string(i) + std::to_string(j), eps(i, j));
  return law;
}
}  // namespace

PDGEN_LAW(correspondence_plane_strain) {
  return correspondence("correspondence_plane_strain", 2,
                        "deformation-gradient law, linear elastic, plane strain (paper 000 eqs. 18-21); params K (3D bulk), G");
}

PDGEN_LAW(correspondence_3d) {
  return correspondence("correspondence_3d", 3, "deformation-gradient law, linear elastic, 3D (paper 000 eqs. 18-21); params K, G");
}

// Oterkus's 3D law (laws/oterkus.cpp): on a regular interior family under a homogeneous
// deformation, the peridynamic stress nu = sum_k t_k (x) xi_k V_k (Silling's collapsed
// stress of a homogeneous deformation) is the classical one: 3 K s I under an isotropic
// stretch s, and G gamma on the sheared pair under a simple shear gamma; its dilatation is
// the volume strain 3 s. The plane-strain law is checked the same way (2 kappa2 s; G gamma).
// The residual of the family gives t_k: its entry for neighbour k is -t_k V_k V0, so nu is
// computed from the forces the generated kernel returns, not from the law's formula.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "verify/random_family.hpp"

namespace {
struct Moduli {
  double K, G;  // 3D bulk and shear; plane strain: kappa2 (2D bulk), G
};

pd::verify::TestFamily regular_family(const char* name, double ratio, Moduli m) {
  const auto* law = pd::abi::find_law(name);
  EXPECT_NE(law, nullptr) << name;
  pd::verify::FamilyOptions o;
  o.dim = law->dim;
  o.horizon_ratio = ratio;
  o.regular = true;
  pd::verify::TestFamily f = pd::verify::make_family(*law, o);
  for (double& v : f.V) v = f.V0;
  for (int p = 0; p < law->n_params; ++p) {
    const std::string n = law->param_names[p];
    f.params[p] = n == "G" ? m.G : m.K;  // K (3D) or kappa2 (2D)
  }
  f.update_moments(law->damaged);
  return f;
}

// nu_ij = sum_k t_k,i xi_k,j V_k for y = (I + H) x.
std::vector<double> stress(pd::verify::TestFamily& f, const double* H) {
  const int d = f.dim;
  std::vector<double> y(f.x.size());
  for (int p = 0; p <= f.bonds(); ++p)
    for (int r = 0; r < d; ++r) {
      y[p * d + r] = f.x[p * d + r];
      for (int c = 0; c < d; ++c) y[p * d + r] += H[r * 3 + c] * (f.x[p * d + c] - f.x[c]);
    }
  f.set_positions(y);
  const std::vector<double> r = f.forces(f.law->damaged);
  std::vector<double> nu(static_cast<std::size_t>(d * d), 0.0);
  for (int k = 0; k < f.bonds(); ++k)
    for (int i = 0; i < d; ++i)
      for (int j = 0; j < d; ++j) nu[i * d + j] += -r[(k + 1) * d + i] / f.V0 * f.xi[k * d + j];
  return nu;
}
}  // namespace

TEST(Oterkus3d, StressOfAnIsotropicStretchAndASimpleShearIsTheClassicalOne) {
  const double s = 1e-7;  // small: the law is linearised about the reference state
  for (const auto& [name, dim, ratio, bulk] :
       {std::tuple{"oterkus_3d", 3, 2.5, 3.0}, std::tuple{"oterkus_plane_strain", 2, 3.0, 2.0}}) {
    const Moduli m{1.7, 0.6};
    pd::verify::TestFamily f = regular_family(name, ratio, m);
    const double iso[9] = {s, 0, 0, 0, s, 0, 0, 0, dim == 3 ? s : 0};
    const std::vector<double> a = stress(f, iso);
    for (int i = 0; i < dim; ++i)
      for (int j = 0; j < dim; ++j)
        EXPECT_NEAR(a[i * dim + j], i == j ? bulk * m.K * s : 0.0, 1e-6 * m.K * s) << name;
    double theta = 0;
    f.law->damaged.outputs(f.view(), &theta);
    EXPECT_NEAR(theta, dim * s, 1e-6 * s) << name;
    const double shear[9] = {0, s / 2, 0, s / 2, 0, 0, 0, 0, 0};  // engineering shear strain s
    const std::vector<double> b = stress(f, shear);
    EXPECT_NEAR(b[0 * dim + 1], m.G * s, 1e-6 * m.G * s) << name;
    EXPECT_NEAR(b[1 * dim + 0], m.G * s, 1e-6 * m.G * s) << name;
    EXPECT_NEAR(b[0], 0.0, 1e-6 * m.G * s) << name;
  }
}

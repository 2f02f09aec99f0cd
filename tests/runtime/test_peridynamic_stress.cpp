// The peridynamic stress (paper 002 eqs. 2.12-2.13, runtime/post/peridynamic_stress.*) of
// a homogeneous deformation, at a particle deep inside a lattice (every family it touches
// is whole):
//   - it is the areal force density of eq. (2.12) summed literally over a column of
//     particles below a plane halfway between two layers (an independent construction:
//     pair forces from both families' residual kernels, bonds crossing the plane);
//   - for a law with an energy it is dW/dF of the family's energy kernel (finite
//     differences of W against F), the discrete first Piola-Kirchhoff stress;
//   - it is C : eps of the law's calibrated material within the horizon quadrature's
//     error, measured on the energy (W against eps : C : eps / 2) in the same family.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <string>
#include <vector>

#include "assembly/assembler.hpp"
#include "assembly/peridynamic_stress.hpp"
#include "discretize/discretization.hpp"
#include "discretize/partial_volume.hpp"
#include "material/elastic_constants.hpp"
#include "verify/test_values.hpp"  // a law's own parameters at its declared test values

namespace {

// A (2N+1)^d lattice of spacing 1 centred on the origin, delta = ratio, one law.
struct HomogeneousBody {
  const pd::abi::LawDescriptor& law;
  pd::Particles particles;
  pd::Bonds bonds;
  pd::IsotropicElastic material;
  std::unique_ptr<pd::FamilyAssembler> assembler;
  int centre = -1;

  HomogeneousBody(const pd::abi::LawDescriptor& l, double ratio, pd::Quadrature q, int reach)
      : law(l),
        material(pd::IsotropicElastic::from_E_nu(1.0, l.has_fixed_poisson_ratio ? l.poisson_ratio : 0.3)) {
    pd::Scene s;
    s.dim = l.dim, s.h = 1.0;
    const double n = reach + 0.5;
    s.lo = {-n, -n, l.dim == 3 ? -n : 0.0}, s.hi = {n, n, l.dim == 3 ? n : 0.0};
    s.materials.resize(1);
    particles = pd::discretize(s);
    bonds = pd::find_quadrature_bonds(particles, ratio, 1.0, q, pd::abi::find_influence("const")->weight);
    const auto params =
        pd::law_parameters(l, material, pd::PlaneAssumption::Strain, pd::verify::declared_test_values(l));
    pd::AssemblerOptions o;
    o.matrix = false;
    assembler = std::make_unique<pd::FamilyAssembler>(particles, bonds, l,
                                                      std::vector<std::vector<double>>{params}, o);
    for (int i = 0; i < particles.size(); ++i) {
      double r = 0;
      for (int c = 0; c < l.dim; ++c) r += std::abs(particles.x[i * l.dim + c]);
      if (r < 1e-9) centre = i;
    }
  }
  int dim() const { return law.dim; }
  std::vector<double> displacement(const Eigen::MatrixXd& grad) const {
    std::vector<double> u(particles.x.size());
    const int d = dim();
    for (int i = 0; i < particles.size(); ++i)
      for (int a = 0; a < d; ++a)
        for (int b = 0; b < d; ++b) u[i * d + a] += grad(a, b) * particles.x[i * d + b];
    return u;
  }
  Eigen::MatrixXd stress_at(const std::vector<double>& sigma, int i) const {
    const int d = dim();
    Eigen::MatrixXd s(d, d);
    for (int a = 0; a < d; ++a)
      for (int b = 0; b < d; ++b) s(a, b) = sigma[static_cast<std::size_t>(i) * d * d + a * d + b];
    return s;
  }
};

Eigen::MatrixXd strain(int d) {
  Eigen::MatrixXd e(d, d);
  if (d == 2)
    e << 1.0e-4, 0.4e-4, 0.4e-4, -0.3e-4;
  else
    e << 1.0e-4, 0.4e-4, -0.2e-4, 0.4e-4, -0.3e-4, 0.5e-4, -0.2e-4, 0.5e-4, 0.6e-4;
  return e;
}

Eigen::MatrixXd hooke(const pd::IsotropicElastic& m, const Eigen::MatrixXd& e) {
  return m.lambda * e.trace() * Eigen::MatrixXd::Identity(e.rows(), e.cols()) + 2 * m.G * e;
}

// Eq. (2.12) on the lattice: the plane x_b = -1/2 (between the centre's layer and the one
// below), the line L the column of particles x_hat_k = centre - k e_b, k = 1, 2, ... (each
// standing for a unit length of L), R+ the particles with x_b > -1/2. tau_a is the force
// per unit area on x_hat's side from R+: sum_k sum_{j in R+} f_a(x_hat_k, j) V_j with the
// pair force density f = t_xhat<j> - t_j<xhat> taken from both families' nodal forces.
Eigen::VectorXd areal_force_density(const HomogeneousBody& body, const std::vector<double>& u, int b,
                                    double delta) {
  const int d = body.dim();
  const auto& p = body.particles;
  const auto& B = body.bonds;
  pd::FamilyInputs in = body.assembler->inputs();
  pd::FamilyGather gather(in);
  std::vector<double> forces(static_cast<std::size_t>(gather.max_bonds() + 1) * d);
  auto index_of = [&](const std::vector<double>& x) {
    for (int i = 0; i < p.size(); ++i) {
      double r = 0;
      for (int c = 0; c < d; ++c) r += std::abs(p.x[i * d + c] - x[c]);
      if (r < 1e-9) return i;
    }
    return -1;
  };
  // Bond force V_q V_j t_q<j> of family q on neighbour j (0 when j is not in q's family).
  auto bond_force = [&](int q, int j) {
    Eigen::VectorXd F = Eigen::VectorXd::Zero(d);
    body.assembler->variant().residual(gather.gather(q, u.data()), forces.data());
    for (int e = B.offsets[q], k = 1; e < B.offsets[q + 1]; ++e, ++k)
      if (B.neighbor[e] == j)
        for (int c = 0; c < d; ++c) F[c] = -forces[k * d + c];
    return F;
  };
  Eigen::VectorXd tau = Eigen::VectorXd::Zero(d);
  for (int k = 1; k <= static_cast<int>(delta) + 1; ++k) {
    std::vector<double> xh(d, 0.0);
    xh[b] = -k;
    const int q = index_of(xh);
    for (int e = B.offsets[q]; e < B.offsets[q + 1]; ++e) {
      const int j = B.neighbor[e];
      if (p.x[j * d + b] < -0.5) continue;
      // f V_j = (F_qj - F_jq) / V_q (unit length of L, V_q = 1 on the unit lattice).
      tau += (bond_force(q, j) - bond_force(j, q)) / p.volume[q];
    }
  }
  return tau;
}

class PeridynamicStress : public testing::TestWithParam<const pd::abi::LawDescriptor*> {};
// The laws with an energy kernel (the checks that measure against W).
class PeridynamicStressOfEnergyLaws : public PeridynamicStress {};

}  // namespace

TEST_P(PeridynamicStress, EqualsTheArealForceDensityOfALatticePlane) {
  const auto& law = *GetParam();
  const double delta = law.dim == 2 ? 3.0 : 2.0;
  const HomogeneousBody body(law, delta, pd::Quadrature::PartialLinear, 3 * static_cast<int>(delta) + 2);
  const auto u = body.displacement(strain(law.dim));
  const Eigen::MatrixXd sigma =
      body.stress_at(pd::peridynamic_stress(*body.assembler, u.data()), body.centre);
  ASSERT_GT(sigma.norm(), 0.0);
  for (int b = 0; b < law.dim; ++b) {
    const Eigen::VectorXd tau = areal_force_density(body, u, b, delta);
    EXPECT_LT((tau - sigma.col(b)).norm(), 1e-12 * sigma.norm())
        << law.name << " n = e" << b << "\ntau " << tau.transpose() << "\nsigma n "
        << sigma.col(b).transpose();
  }
}

TEST_P(PeridynamicStressOfEnergyLaws, IsTheDerivativeOfTheFamilyEnergy) {
  const auto& law = *GetParam();
  const int d = law.dim;
  const double delta = d == 2 ? 3.0 : 2.0;
  const HomogeneousBody body(law, delta, pd::Quadrature::Volume, 2 * static_cast<int>(delta) + 2);
  Eigen::MatrixXd grad = strain(d) * 100;  // finite strain (1 %): P, not a linearisation
  grad(0, 1) += 0.01;                      // and a rotation-like skew part
  const auto u = body.displacement(grad);
  const Eigen::MatrixXd sigma =
      body.stress_at(pd::peridynamic_stress(*body.assembler, u.data()), body.centre);
  pd::FamilyGather gather(body.assembler->inputs());
  auto energy = [&](const Eigen::MatrixXd& g) {
    const auto v = body.displacement(g);
    return body.assembler->variant().energy(gather.gather(body.centre, v.data()));
  };
  const double eps = 1e-6;
  Eigen::MatrixXd dW(d, d);
  for (int a = 0; a < d; ++a)
    for (int b = 0; b < d; ++b) {
      Eigen::MatrixXd gp = grad, gm = grad;
      gp(a, b) += eps, gm(a, b) -= eps;
      dW(a, b) = (energy(gp) - energy(gm)) / (2 * eps);
    }
  EXPECT_LT((dW - sigma).norm(), 1e-6 * sigma.norm()) << law.name << "\ndW/dF\n"
                                                      << dW << "\nsigma\n"
                                                      << sigma;
}

// C : eps within the quadrature error of the same horizon sum, measured independently on
// the family's energy kernel: |W / (eps : C : eps / 2) - 1|. The stress may be off by that
// plus 1 % of |C : eps| (the lattice sum is not isotropic: W averages over directions).
// 2D with the exact cell-disc areas; 3D with the linear factors (the adaptive
// integration on every cut cell of 3000 families is too slow for the suite).
TEST_P(PeridynamicStressOfEnergyLaws, IsHookesLawWithinTheQuadratureError) {
  const auto& law = *GetParam();
  const int d = law.dim;
  const double delta =
      d == 2 ? 6.0 : 3.0;  // 2D: at 4.5 the conical law's lattice error is 2.0 % (energy 0.7 %)
  // The conical laws take their micromodulus c (1 - |xi|/delta) from |xi| inside the law, so
  // the cut cells beyond delta that the partial choices add enter with a negative modulus
  // (docs/paper002.md, "What the factors buy"): they keep the whole-volume rule here.
  const bool conical = std::string(law.name).find("conical") != std::string::npos;
  const pd::Quadrature q = conical  ? pd::Quadrature::Volume
                           : d == 2 ? pd::Quadrature::PartialExact
                                    : pd::Quadrature::PartialLinear;
  const HomogeneousBody body(law, delta, q, 2 * static_cast<int>(delta) + 2);
  const Eigen::MatrixXd e = strain(d);
  const auto u = body.displacement(e);
  const Eigen::MatrixXd sigma =
      body.stress_at(pd::peridynamic_stress(*body.assembler, u.data()), body.centre);
  const Eigen::MatrixXd expected = hooke(body.material, e);
  const double error = (sigma - expected).norm() / expected.norm();
  pd::FamilyGather gather(body.assembler->inputs());
  const double W = body.assembler->variant().energy(gather.gather(body.centre, u.data()));
  const double w_error = std::abs(W / (0.5 * (expected.array() * e.array()).sum()) - 1);
  std::printf("%s delta/h=%g %s: |sigma - C:eps| / |C:eps| = %.4f, energy error %.4f\n", law.name, delta,
              std::string(pd::name_of(q)).c_str(), error, w_error);
  EXPECT_LT(error, w_error + 0.01) << law.name << "\nsigma\n" << sigma << "\nC:eps\n" << expected;
}

std::vector<const pd::abi::LawDescriptor*> laws(bool with_energy_only) {
  std::vector<const pd::abi::LawDescriptor*> v;
  for (const auto& l : pd::abi::all_laws())
    if (!with_energy_only || l.damaged.energy != nullptr) v.push_back(&l);
  return v;
}
std::string law_name(const testing::TestParamInfo<const pd::abi::LawDescriptor*>& i) { return i.param->name; }
INSTANTIATE_TEST_SUITE_P(AllLaws, PeridynamicStress, testing::ValuesIn(laws(false)), law_name);
INSTANTIATE_TEST_SUITE_P(EnergyLaws, PeridynamicStressOfEnergyLaws, testing::ValuesIn(laws(true)), law_name);

// Each domain.quadrature choice reaches the kernels only through V[k]: the assembled
// stiffness must still be minus the derivative of the assembled forces, and the
// matrix-free product must equal the matrix, with the partial factors in place.
#include <gtest/gtest.h>

#include <cmath>

#include "assembler_fd.hpp"
#include "assembly/assembler.hpp"
#include "discretize/discretization.hpp"
#include "discretize/partial_volume.hpp"
#include "material/elastic_constants.hpp"
#include "verify/test_values.hpp"  // a law's own parameters at its declared test values

namespace {
struct Case {
  const pd::abi::LawDescriptor* law;
  pd::Quadrature quadrature;
};
std::vector<Case> cases() {
  std::vector<Case> v;
  for (const auto& l : pd::abi::all_laws())
    for (pd::Quadrature q : {pd::Quadrature::PartialLinear, pd::Quadrature::PartialExact})
      v.push_back({&l, q});
  return v;
}
std::string name(const testing::TestParamInfo<Case>& info) {
  return std::string(info.param.law->name) + "_" + std::string(pd::name_of(info.param.quadrature));
}
class QuadratureAssembly : public testing::TestWithParam<Case> {};
}  // namespace

TEST_P(QuadratureAssembly, StiffnessIsMinusDerivativeOfForcesAndProductEqualsMatrix) {
  const auto& law = *GetParam().law;
  pd::Scene s;
  s.dim = law.dim;
  s.h = 1.0;
  const int n = law.dim == 2 ? 7 : 4;
  s.lo = {0, 0, 0};
  s.hi = {double(n), double(n), law.dim == 3 ? double(n) : 0.0};
  s.materials.resize(1);
  const pd::Particles p = pd::discretize(s);
  const double delta = law.dim == 2 ? 2.3 : 1.6;
  const auto* influence = pd::abi::find_influence("linear");
  const pd::Bonds b = pd::find_quadrature_bonds(p, delta, s.h, GetParam().quadrature, influence->weight);
  // The choice is active: some bonds carry a strict fraction of their neighbour's cell.
  int fractional = 0;
  for (double f : b.volume_factor) fractional += f > 0 && f < 1;
  ASSERT_GT(fractional, 0);
  ASSERT_EQ(b.volume_factor.size(), b.neighbor.size());
  const auto params = pd::law_parameters(law, pd::IsotropicElastic::from_E_nu(1.0, 0.25),
                                         pd::PlaneAssumption::Strain, pd::verify::declared_test_values(law));
  const pd::FamilyAssembler a(p, b, law, {params}, {});
  const int dofs = static_cast<int>(p.x.size());
  std::vector<double> u(dofs), v(dofs);
  for (int i = 0; i < dofs; ++i) u[i] = 0.01 * std::sin(2.3 * p.x[i] + 0.9 * i), v[i] = std::cos(1.1 * i);
  const pd::test::TangentFdCheck fd = pd::test::tangent_fd_check(a, u);
  ASSERT_GT(fd.scale, 0.0);
  EXPECT_LT(fd.worst, 1e-6 * fd.scale);
  pd::test::expect_product_equals_matrix(a, u, v);
}

TEST(QuadratureAssembly, PartialFactorsChangeTheForces) {
  // The same grid and displacement under `volume` and `partial_exact`: the forces differ,
  // so the factor really reaches the kernels (a test of the tests above).
  const auto& law = *pd::abi::find_law("silling_plane_strain");
  pd::Scene s;
  s.dim = 2, s.h = 1.0, s.lo = {0, 0, 0}, s.hi = {6, 6, 0};
  s.materials.resize(1);
  const pd::Particles p = pd::discretize(s);
  const auto* influence = pd::abi::find_influence("const");
  const auto params =
      pd::law_parameters(law, pd::IsotropicElastic::from_E_nu(1.0, 0.25), pd::PlaneAssumption::Strain, {});
  std::vector<double> u(p.x.size()), f0(u.size()), f1(u.size());
  for (std::size_t i = 0; i < u.size(); ++i) u[i] = 0.01 * std::sin(1.7 * p.x[i] + i);
  const pd::Bonds b0 = pd::find_quadrature_bonds(p, 2.5, 1.0, pd::Quadrature::Volume, influence->weight);
  const pd::Bonds b1 =
      pd::find_quadrature_bonds(p, 2.5, 1.0, pd::Quadrature::PartialExact, influence->weight);
  pd::FamilyAssembler(p, b0, law, {params}, {}).internal_forces(u.data(), f0.data());
  pd::FamilyAssembler(p, b1, law, {params}, {}).internal_forces(u.data(), f1.data());
  double diff = 0, size = 0;
  for (std::size_t i = 0; i < u.size(); ++i)
    diff = std::max(diff, std::abs(f1[i] - f0[i])), size = std::max(size, std::abs(f0[i]));
  EXPECT_GT(diff, 1e-3 * size);
}

INSTANTIATE_TEST_SUITE_P(AllLaws, QuadratureAssembly, testing::ValuesIn(cases()), name);

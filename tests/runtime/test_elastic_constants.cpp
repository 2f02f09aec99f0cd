// Elastic constant conversions and the plane-stress equivalence.
#include <gtest/gtest.h>

#include "material/elastic_constants.hpp"

using pd::IsotropicElastic;

TEST(ElasticConstants, PairsAreConsistent) {
  const auto a = IsotropicElastic::from_E_nu(200.0, 0.3);
  const auto b = IsotropicElastic::from_K_G(a.K, a.G);
  EXPECT_NEAR(b.E, 200.0, 1e-12);
  EXPECT_NEAR(b.nu, 0.3, 1e-14);
  EXPECT_NEAR(a.lambda + 2 * a.G / 3, a.K, 1e-12);
  EXPECT_NEAR(a.G, 200.0 / 2.6, 1e-12);
}

TEST(ElasticConstants, PlaneStressEquivalentReproducesPlaneStressModuli) {
  // Plane stress: sigma = E/(1-nu^2) [[1, nu], [nu, 1]] eps. Plane strain of the
  // equivalent material: (lambda* + 2G*) and lambda* must equal E/(1-nu^2) and E nu/(1-nu^2).
  const auto m = IsotropicElastic::from_E_nu(70.0, 0.33);
  const auto s = m.plane_stress_equivalent();
  EXPECT_NEAR(s.lambda + 2 * s.G, m.E / (1 - m.nu * m.nu), 1e-10);
  EXPECT_NEAR(s.lambda, m.E * m.nu / (1 - m.nu * m.nu), 1e-10);
  EXPECT_NEAR(s.G, m.G, 1e-12);
}

TEST(ElasticConstants, InvalidValuesAreRejected) {
  EXPECT_THROW(IsotropicElastic::from_E_nu(1.0, 0.5), std::invalid_argument);
  EXPECT_THROW(IsotropicElastic::from_E_nu(-1.0, 0.2), std::invalid_argument);
  EXPECT_THROW(IsotropicElastic::from_K_G(1.0, 0.0), std::invalid_argument);
}

TEST(ElasticConstants, LawParametersByName) {
  const auto* law = pd::abi::find_law("silling_plane_strain");
  ASSERT_NE(law, nullptr);
  const auto m = IsotropicElastic::from_E_nu(1.0, 0.25);
  const auto p = pd::law_parameters(*law, m, pd::PlaneAssumption::Strain, {});
  ASSERT_EQ(p.size(), 2u);
  EXPECT_DOUBLE_EQ(p[0], m.K);
  EXPECT_DOUBLE_EQ(p[1], m.G);
  const auto ps = pd::law_parameters(*law, m, pd::PlaneAssumption::Stress, {});
  EXPECT_NE(ps[0], p[0]);
  EXPECT_DOUBLE_EQ(ps[1], p[1]);  // the shear modulus is unchanged
}

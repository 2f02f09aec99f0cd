// Bond-based laws fix the Poisson ratio at 1/4 (3D, plane strain), which plane stress
// reaches at nu = 1/3 through the equivalent material; another nu draws a warning.
#include <gtest/gtest.h>

#include "material/admissible_poisson.hpp"

using pd::PlaneAssumption;

TEST(AdmissiblePoisson, BondBasedLawsDeclareOneQuarter) {
  for (const auto& law : pd::abi::all_laws()) {
    const std::string n = law.name;
    EXPECT_EQ(law.has_fixed_poisson_ratio, n.rfind("bond_based_", 0) == 0) << n;
    if (law.has_fixed_poisson_ratio) {
      EXPECT_EQ(law.poisson_ratio, 0.25) << n;
    }
  }
}

TEST(AdmissiblePoisson, WarnsOnlyWhenTheMaterialDiffers) {
  const auto& bb2 = *pd::abi::find_law("bond_based_constant_2d");
  const auto& bb3 = *pd::abi::find_law("bond_based_conical_3d");
  const auto& silling = *pd::abi::find_law("silling_plane_strain");
  const auto quarter = pd::IsotropicElastic::from_E_nu(1.0, 0.25),
             third = pd::IsotropicElastic::from_E_nu(1.0, 1.0 / 3);
  const auto steel = pd::IsotropicElastic::from_E_nu(1.0, 0.3);
  EXPECT_FALSE(pd::poisson_ratio_warning(bb2, quarter, PlaneAssumption::Strain, "m"));
  EXPECT_FALSE(pd::poisson_ratio_warning(bb2, third, PlaneAssumption::Stress, "m"));
  EXPECT_FALSE(pd::poisson_ratio_warning(bb3, quarter, PlaneAssumption::None, "m"));
  EXPECT_FALSE(pd::poisson_ratio_warning(silling, steel, PlaneAssumption::Strain, "m"));  // K and G: any nu
  EXPECT_TRUE(
      pd::poisson_ratio_warning(bb2, quarter, PlaneAssumption::Stress, "m"));  // 1/4 in plane stress is 1/5
  EXPECT_TRUE(pd::poisson_ratio_warning(bb2, third, PlaneAssumption::Strain, "m"));
  const auto w = pd::poisson_ratio_warning(bb3, steel, PlaneAssumption::None, "rock");
  ASSERT_TRUE(w);
  EXPECT_NE(w->find("bond_based_conical_3d"), std::string::npos) << *w;
  EXPECT_NE(w->find("'rock' has nu = 0.3"), std::string::npos) << *w;
  EXPECT_NE(w->find("nu = 0.25"), std::string::npos) << *w;
  const auto w2 = pd::poisson_ratio_warning(bb2, steel, PlaneAssumption::Stress, "m");
  ASSERT_TRUE(w2);
  EXPECT_NE(w2->find("0.25 in plane strain, 0.3333 in plane stress"), std::string::npos) << *w2;
}

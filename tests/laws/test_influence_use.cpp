// LawDescriptor::ignores_influence is what the generator derives from the law's
// expressions (no path from w to the force). Checked here against the kernels themselves:
// a law that claims it ignores w gives the same forces bit for bit when every bond's
// weight changes, and one that reads w gives different forces. The runtime's warning
// that a scene's influence function is ignored (runtime/model/model.cpp) rests on it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "law_list.hpp"
#include "verify/random_family.hpp"

namespace {
class InfluenceUse : public testing::TestWithParam<const pd::abi::LawDescriptor*> {};
}  // namespace

TEST_P(InfluenceUse, TheDescriptorSaysWhetherTheForcesReadTheWeights) {
  const auto& law = *GetParam();
  pd::verify::FamilyOptions o;
  o.dim = law.dim;
  o.horizon_ratio = law.dim == 2 ? 3.0 : 2.0;
  pd::verify::TestFamily f = pd::verify::make_family(law, o);
  const auto before = f.forces(law.damaged);
  // Not a uniform scale: laws that divide by a weighted volume cancel one.
  for (int k = 0; k < f.bonds(); ++k) f.w[k] *= 1.0 + 0.5 * k / f.bonds();
  f.update_moments(law.damaged);
  const auto after = f.forces(law.damaged);
  double scale = 0, change = 0;
  for (std::size_t i = 0; i < before.size(); ++i) {
    scale = std::max(scale, std::fabs(before[i]));
    change = std::max(change, std::fabs(after[i] - before[i]));
  }
  ASSERT_GT(scale, 0.0);
  if (law.ignores_influence)
    EXPECT_EQ(change, 0.0) << law.name << " claims to ignore w, but its forces moved by " << change / scale;
  else
    EXPECT_GT(change, 1e-6 * scale) << law.name << " reads w, but its forces did not move";
}

INSTANTIATE_TEST_SUITE_P(AllLaws, InfluenceUse, testing::ValuesIn(pd::test::all_law_descriptors()),
                         pd::test::law_name);

TEST(InfluenceUse, BondBasedLawsPaper001sLpsAndTheContinuumOterkusIgnoreIt) {
  int ignoring = 0;
  for (const auto& law : pd::abi::all_laws()) {
    const std::string name = law.name;
    // oterkus_continuum_plane_strain: paper 003's continuum constants assume w = 1 (laws/oterkus.cpp).
    const bool expected = name.rfind("bond_based_", 0) == 0 || name.rfind("lps_paper_", 0) == 0 ||
                          name == "oterkus_continuum_plane_strain";
    EXPECT_EQ(law.ignores_influence, expected) << name;
    ignoring += law.ignores_influence;
  }
  EXPECT_GE(ignoring, 8);
}

// The automatic law checks themselves (verify/tangent_check, verify/balance): what
// `pd check-law` runs is what the suite runs, the angular-momentum check sees a torque,
// the lattice family catches a law that is infinite at r = delta, and laws declare test
// values for their own parameters.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "law_list.hpp"
#include "verify/balance.hpp"
#include "verify/tangent_check.hpp"
#include "verify/test_values.hpp"

using pd::verify::FamilyCheck;

namespace {
class CheckLaw : public testing::TestWithParam<const pd::abi::LawDescriptor*> {};

bool starts_with(const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; }
}  // namespace

// Every family `pd check-law` shows passes, with the tolerances it applies.
TEST_P(CheckLaw, EveryFamilyPasses) {
  const auto& law = *GetParam();
  for (const FamilyCheck& c : pd::verify::check_law(law, 1)) {
    EXPECT_TRUE(c.finite) << c.description;
    EXPECT_TRUE(pd::verify::passes(law, c))
        << c.description << ": tangent " << c.tangent.worst() << " jvp " << c.jvp_error << " momentum "
        << c.momentum_error << " angular " << c.angular_momentum_error;
  }
}

INSTANTIATE_TEST_SUITE_P(AllLaws, CheckLaw, testing::ValuesIn(pd::test::all_law_descriptors()),
                         pd::test::law_name);

// The claim is declared by the laws whose force state is parallel to the deformed bond
// (docs/laws.md); the linearised laws (correspondence, LPS) do not balance it, and the
// check measures that: it is not vacuous. A law added later (README's walkthrough) is held
// to its own claim: claimed, CheckLaw verifies it; not claimed, it must not balance.
TEST(AngularMomentum, ClaimedExactlyByBondBasedAndOrdinaryStateBasedLaws) {
  for (const auto& law : pd::abi::all_laws()) {
    const std::string n = law.name;
    const bool parallel =
        starts_with(n, "bond_based_") || starts_with(n, "silling_") || starts_with(n, "oterkus_");
    const bool linearised = starts_with(n, "correspondence_") || starts_with(n, "lps_");
    if (parallel) {
      EXPECT_TRUE(law.balances_angular_momentum) << n;
    }
    if (linearised) {
      EXPECT_FALSE(law.balances_angular_momentum) << n;
    }
    if (law.balances_angular_momentum) continue;
    double worst = 0;
    for (const FamilyCheck& c : pd::verify::check_law(law, 1))
      worst = std::max(worst, c.angular_momentum_error);
    EXPECT_GT(worst, 1e-6) << n << " balances angular momentum: it could claim it";
  }
}

// Forces perpendicular to the bonds with zero sum: momentum balanced, angular momentum not.
TEST(AngularMomentum, CheckSeesATorqueFromForcesPerpendicularToTheBonds) {
  const auto* law = pd::abi::find_law("bond_based_constant_2d");
  ASSERT_NE(law, nullptr);
  pd::verify::FamilyOptions o;
  pd::verify::TestFamily f = pd::verify::make_family(*law, o);
  std::vector<double> forces(static_cast<std::size_t>(f.dofs()), 0.0);
  for (int k = 0; k < f.bonds(); ++k) {
    forces[(k + 1) * 2 + 0] = -f.Y[k * 2 + 1];
    forces[(k + 1) * 2 + 1] = f.Y[k * 2 + 0];
    forces[0] -= forces[(k + 1) * 2 + 0];
    forces[1] -= forces[(k + 1) * 2 + 1];
  }
  EXPECT_LE(pd::verify::momentum_error(f, forces), 1e-15);
  EXPECT_NEAR(pd::verify::angular_momentum_error(f, forces), 1.0,
              1e-12);  // every bond's torque |Y|^2 adds up
}

namespace {
// bond_based_constant_2d with every bond force scaled by delta / (delta - |xi|): finite
// on any family whose bonds are all shorter than delta, infinite at r = delta.
void singular_residual(const pd::abi::Family& fam, double* forces) {
  pd::abi::find_law("bond_based_constant_2d")->damaged.residual(fam, forces);
  forces[0] = forces[1] = 0;
  for (int k = 0; k < fam.n_bonds; ++k) {
    const double r = std::hypot(fam.xi[2 * k], fam.xi[2 * k + 1]);
    for (int c = 0; c < 2; ++c) {
      forces[(k + 1) * 2 + c] *= fam.delta / (fam.delta - r);
      forces[c] -= forces[(k + 1) * 2 + c];
    }
  }
}
}  // namespace

TEST(CheckLawFamilies, ALawInfiniteAtTheHorizonFailsOnlyOnTheLatticeFamily) {
  pd::abi::LawDescriptor bad = *pd::abi::find_law("bond_based_constant_2d");
  bad.damaged.residual = &singular_residual;
  bool lattice_seen = false;
  for (const FamilyCheck& c : pd::verify::check_law(bad, 1)) {
    const bool lattice = c.description == "lattice, r = delta";
    lattice_seen = lattice_seen || lattice;
    EXPECT_EQ(c.finite, !lattice) << c.description;
    if (lattice) {
      EXPECT_FALSE(pd::verify::passes(bad, c));
    }
  }
  EXPECT_TRUE(lattice_seen);
}

TEST(TestValues, LawsDeclareValuesForTheirOwnParameters) {
  const auto* silling = pd::abi::find_law("correspondence_silling_plane_strain");
  const auto* littlewood = pd::abi::find_law("correspondence_littlewood_3d");
  ASSERT_NE(silling, nullptr);
  ASSERT_NE(littlewood, nullptr);
  EXPECT_EQ(pd::verify::declared_test_values(*silling), (std::map<std::string, double>{{"stab", 1.0}}));
  EXPECT_EQ(pd::verify::declared_test_values(*littlewood),
            (std::map<std::string, double>{{"hourglass", 1.0}}));
  EXPECT_TRUE(pd::verify::declared_test_values(*pd::abi::find_law("silling_3d")).empty());  // K, G: elastic
}

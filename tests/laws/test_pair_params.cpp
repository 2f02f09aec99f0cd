// Pair-averaged material parameters (Law::pair_param, Family::nbr_params): a law that
// declares them reads the neighbours' parameters, one that does not ignores them, a null
// pointer and the center's own values give the same forces bit for bit, and LPS's bond
// force takes the harmonic mean of eq. (2.4) of paper 001 bond by bond. The tangent and
// JVP with a material jump are checked for every law by CheckLaw (verify/tangent_check).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "law_list.hpp"
#include "verify/random_family.hpp"

namespace {
class PairParams : public testing::TestWithParam<const pd::abi::LawDescriptor*> {};

pd::verify::TestFamily jump_family(const pd::abi::LawDescriptor& law) {
  pd::verify::FamilyOptions o;
  o.dim = law.dim;
  o.horizon_ratio = law.dim == 2 ? 3.0 : 2.0;
  o.material_jump = true;
  o.seed = 7;
  return pd::verify::make_family(law, o);
}

double max_difference(const std::vector<double>& a, const std::vector<double>& b) {
  double m = 0;
  for (std::size_t i = 0; i < a.size(); ++i) m = std::max(m, std::fabs(a[i] - b[i]));
  return m;
}
}  // namespace

// Neighbours with the center's parameters: the same forces as no neighbour parameters.
TEST_P(PairParams, TheCentersOwnValuesGiveTheForcesOfANullPointer) {
  const auto& law = *GetParam();
  auto f = jump_family(law);
  for (int k = 0; k < f.bonds(); ++k)
    for (int p = 0; p < law.n_params; ++p)
      f.nbr_params[static_cast<std::size_t>(k * law.n_params + p)] = f.params[p];
  const auto with = f.forces(law.damaged);
  f.nbr_params.clear();
  EXPECT_EQ(with, f.forces(law.damaged));
}

// The jump changes the forces exactly for the laws that declare pair parameters.
TEST_P(PairParams, OnlyALawWithPairParametersSeesTheNeighbours) {
  const auto& law = *GetParam();
  auto f = jump_family(law);
  ASSERT_FALSE(f.nbr_params.empty());
  const auto with = f.forces(law.damaged);
  f.nbr_params.clear();
  const auto without = f.forces(law.damaged);
  if (law.uses_pair_params)
    EXPECT_GT(max_difference(with, without),
              1e-3 * max_difference(without, std::vector<double>(without.size(), 0.0)))
        << law.name;
  else
    EXPECT_EQ(with, without) << law.name;
}

INSTANTIATE_TEST_SUITE_P(AllLaws, PairParams, testing::ValuesIn(pd::test::all_law_descriptors()),
                         pd::test::law_name);

// LPS's force on bond k with neighbour parameters equals the force of a homogeneous family
// whose parameters are the harmonic means 2 p_0 p_k / (p_0 + p_k) of bond k's pair (the
// dilatation and m do not depend on the parameters): eq. (2.4) applied bond by bond.
TEST(PairParams, LpsBondForceUsesTheHarmonicMeanOfEachPair) {
  for (const char* name : {"lps_plane_strain", "lps_corrected_plane_strain", "lps_3d"}) {
    const auto* law = pd::abi::find_law(name);
    ASSERT_NE(law, nullptr) << name;
    ASSERT_TRUE(law->uses_pair_params) << name;
    auto f = jump_family(*law);
    const int d = f.dim, np = law->n_params;
    const auto jump = f.forces(law->damaged);
    int across = 0;
    for (int k = 0; k < f.bonds(); ++k) {
      pd::verify::TestFamily g = f;
      g.nbr_params.clear();
      for (int p = 0; p < np; ++p) {
        const double a = f.params[p], b = f.nbr_params[static_cast<std::size_t>(k * np + p)];
        g.params[p] = 2 * a * b / (a + b);
        across += p == 0 && a != b;
      }
      const auto hom = g.forces(law->damaged);
      // Bond k's force is the nodal force on its neighbour, local particle k + 1.
      for (int c = 0; c < d; ++c)
        EXPECT_NEAR(jump[(k + 1) * d + c], hom[(k + 1) * d + c],
                    1e-13 * (std::fabs(hom[(k + 1) * d + c]) + 1e-300))
            << name << " bond " << k;
    }
    EXPECT_GT(across, 3) << name << ": the family must have bonds across the interface";
  }
}

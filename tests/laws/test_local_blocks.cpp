// runtime/local_matrix.hpp's pair blocks (laws without states) against the dense local
// matrix, and the finite check on the tangent factors against the matrix it stands for.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "verify/random_family.hpp"

namespace {
pd::verify::TestFamily family(const pd::abi::LawDescriptor& law, bool broken) {
  pd::verify::FamilyOptions o;
  o.dim = law.dim;
  o.horizon_ratio = law.dim == 2 ? 3.0 : 2.0;
  o.broken_bonds = broken;
  o.truncation = pd::verify::Truncation::Edge;
  return pd::verify::make_family(law, o);
}
}  // namespace

// Every law without states: its dense matrix is the pair blocks, in their four places,
// and zero elsewhere (the neighbour-neighbour blocks a pairwise law never couples).
TEST(PairBlocks, AreTheDenseMatrixOfEveryLawWithoutStates) {
  int laws = 0;
  for (const auto& law : pd::abi::all_laws()) {
    if (law.n_states != 0) continue;
    ++laws;
    const pd::verify::TestFamily f = family(law, true);
    const int d = f.dim, L = f.bonds(), n = f.dofs(), dd = d * d;
    const auto M = f.tangent_matrix(law.damaged);
    pd::TangentScratch ts;
    const auto fac = ts.view(d, 0, L);
    law.damaged.tangent(f.view(), nullptr, fac);
    std::vector<double> B(static_cast<std::size_t>((L + 1) * dd));
    pd::form_pair_blocks(d, f.view(), fac, B.data());
    const double tol = 1e-13 * std::abs(B[0]);
    for (int a = 0; a <= L; ++a)
      for (int b = 0; b <= L; ++b)
        for (int r = 0; r < d; ++r)
          for (int q = 0; q < d; ++q) {
            double expected = 0.0;
            if (a == 0 && b == 0)
              expected = B[r * d + q];
            else if (a == 0 || b == 0)
              expected = B[(a + b) * dd + r * d + q];
            else if (a == b)
              expected = -B[a * dd + r * d + q];
            ASSERT_NEAR(M[static_cast<std::size_t>((a * d + r) * n + b * d + q)], expected, tol)
                << law.name << " block (" << a << ", " << b << ")";
          }
  }
  EXPECT_GE(laws, 2) << "the bond-based laws have no states";
}

// The check says finite exactly when the formed matrix is, on real factors, on a NaN
// or an infinity in any one factor, and on factors finite alone whose products overflow.
TEST(FactorsFinite, AgreesWithTheFormedMatrix) {
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  for (const char* name : {"silling_plane_strain", "correspondence_3d", "bond_based_constant_2d"}) {
    const auto* law = pd::abi::find_law(name);
    ASSERT_NE(law, nullptr) << name;
    const pd::verify::TestFamily f = family(*law, false);
    const int d = f.dim, S = law->n_states, L = f.bonds();
    pd::TangentScratch ts;
    const auto fac = ts.view(d, S, L);
    auto all_finite = [&] {
      std::vector<double> M(static_cast<std::size_t>(f.dofs() * f.dofs()));
      pd::form_local_matrix(law->intact, d, S, f.view(), fac, M.data());
      for (double v : M)
        if (!std::isfinite(v)) return false;
      return true;
    };
    law->intact.tangent(f.view(), nullptr, fac);
    EXPECT_TRUE(pd::factors_finite(d, S, f.view(), fac)) << name;
    EXPECT_TRUE(all_finite()) << name;
    std::vector<double*> entries{&fac.direct[d * d * (L / 2) + 1]};
    if (S > 0) entries.push_back(&fac.left[S * d * (L - 1)]), entries.push_back(&fac.right[S * d * (L / 3)]);
    for (double* e : entries)
      for (double bad : {nan, inf, -inf}) {
        const double keep = *e;
        *e = bad;
        EXPECT_FALSE(pd::factors_finite(d, S, f.view(), fac)) << name << " with " << bad;
        *e = keep;
      }
    if (S > 0) {
      // Finite factors whose product overflows: left and right of one state at 1e200.
      for (int k = 0; k < L; ++k)
        for (int a = 0; a < S * d; ++a) fac.left[k * S * d + a] *= 1e200, fac.right[k * S * d + a] *= 1e200;
      EXPECT_FALSE(all_finite()) << name << ": the test must make the matrix overflow";
      EXPECT_FALSE(pd::factors_finite(d, S, f.view(), fac)) << name;
    }
  }
}

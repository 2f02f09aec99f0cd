// The generated form kernels (KernelVariant::form, generator/emit/form_kernel.cpp) against
// the generic forming of runtime/local_matrix.hpp: the same local matrix, entry for entry,
// for every law and variant on interior, truncated and damaged families, with every entry
// written (the output starts as NaN). Skipping a structurally zero factor drops only
// products with zero, so the two agree exactly, not to a tolerance.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "law_list.hpp"
#include "verify/random_family.hpp"

namespace {
using pd::verify::Truncation;

class FormKernel : public testing::TestWithParam<const pd::abi::LawDescriptor*> {};

void expect_same_matrix(const pd::abi::LawDescriptor& law, const pd::abi::KernelVariant& v,
                        const char* variant, Truncation t, bool broken) {
  pd::verify::FamilyOptions o;
  o.dim = law.dim;
  o.horizon_ratio = law.dim == 2 ? 3.0 : 2.0;
  o.truncation = t;
  o.broken_bonds = broken;
  pd::verify::TestFamily f = pd::verify::make_family(law, o);
  f.update_moments(v);
  ASSERT_NE(v.form, nullptr) << law.name << " " << variant;
  pd::TangentScratch ts;
  const auto fac = ts.view(f.dim, law.n_states, f.bonds());
  v.tangent(f.view(), nullptr, fac);
  const std::size_t n = static_cast<std::size_t>(f.dofs());
  std::vector<double> generic(n * n, std::numeric_limits<double>::quiet_NaN()), generated = generic;
  pd::form_local_matrix(f.dim, law.n_states, f.view(), fac, generic.data());
  v.form(f.view(), fac, generated.data());
  double largest = 0.0;
  for (std::size_t i = 0; i < generic.size(); ++i) {
    ASSERT_EQ(generated[i], generic[i])
        << law.name << " " << variant << " entry (" << i / n << ", " << i % n << ")";
    largest = std::max(largest, std::abs(generic[i]));
  }
  EXPECT_GT(largest, 0.0) << "a zero matrix would compare equal whatever the kernel does";
}
}  // namespace

TEST_P(FormKernel, GivesTheGenericFormingsMatrixEntryForEntry) {
  const auto& law = *GetParam();
  for (Truncation t : {Truncation::Interior, Truncation::Edge, Truncation::Corner})
    for (bool broken : {false, true}) {
      expect_same_matrix(law, law.damaged, "damaged", t, broken);
      if (!broken) expect_same_matrix(law, law.intact, "intact", t, broken);
    }
}

// The correspondence laws' right factors dN_ij/dY_k = w V xi_j e_i have one nonzero
// component each and their direct factor none. The generated forming must not read
// those entries at all (that is where its saving comes from): with them overwritten by
// NaN it gives the same finite matrix, where the generic forming turns NaN.
TEST(FormKernelStructure, CorrespondenceNeverReadsItsStructurallyZeroFactors) {
  for (const char* name : {"correspondence_plane_strain", "correspondence_3d"}) {
    const auto* law = pd::abi::find_law(name);
    ASSERT_NE(law, nullptr) << name;
    pd::verify::FamilyOptions o;
    o.dim = law->dim;
    o.horizon_ratio = law->dim == 2 ? 3.0 : 2.0;
    pd::verify::TestFamily f = pd::verify::make_family(*law, o);
    const int d = law->dim, S = law->n_states, L = f.bonds();
    pd::TangentScratch ts;
    const auto fac = ts.view(d, S, L);
    law->intact.tangent(f.view(), nullptr, fac);
    const std::size_t n = static_cast<std::size_t>(f.dofs());
    std::vector<double> reference(n * n), M(n * n), generic(n * n);
    law->intact.form(f.view(), fac, reference.data());
    int poisoned = 0;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (int k = 0; k < L; ++k) {
      for (int a = 0; a < S * d; ++a)
        if (fac.right[k * S * d + a] == 0.0) fac.right[k * S * d + a] = nan, ++poisoned;
      for (int a = 0; a < d * d; ++a) fac.direct[k * d * d + a] = nan, ++poisoned;
    }
    EXPECT_EQ(poisoned, L * (S * d - S) + L * d * d)
        << name << ": (d-1) of every d right components are zero";
    law->intact.form(f.view(), fac, M.data());
    for (std::size_t i = 0; i < M.size(); ++i) ASSERT_EQ(M[i], reference[i]) << name << " entry " << i;
    pd::form_local_matrix(d, S, f.view(), fac, generic.data());
    EXPECT_TRUE(std::isnan(generic[n + 1])) << "the generic forming reads every entry";
  }
}

INSTANTIATE_TEST_SUITE_P(AllLaws, FormKernel, testing::ValuesIn(pd::test::all_law_descriptors()),
                         pd::test::law_name);

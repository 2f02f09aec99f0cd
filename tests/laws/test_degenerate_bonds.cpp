// A deformed bond of zero or nearly zero length must not put NaN or Inf into the
// residual, the tangent or the tangent-vector product of any law (issue: hard cases).
#include <gtest/gtest.h>

#include <cmath>

#include "law_list.hpp"
#include "verify/random_family.hpp"

using pd::verify::FamilyOptions;
using pd::verify::make_family;
using pd::verify::TestFamily;

namespace {
class DegenerateBond : public testing::TestWithParam<const pd::abi::LawDescriptor*> {};

void expect_finite(const std::vector<double>& v, const char* what, double gap) {
  for (std::size_t i = 0; i < v.size(); ++i)
    ASSERT_TRUE(std::isfinite(v[i])) << what << "[" << i << "], gap " << gap;
}
}  // namespace

TEST_P(DegenerateBond, CollapsedBondGivesFiniteResidualTangentAndJvp) {
  const auto& law = *GetParam();
  FamilyOptions o;
  o.dim = law.dim;
  o.horizon_ratio = law.dim == 2 ? 3.0 : 2.0;
  for (double gap : {0.0, 1e-300, 1e-12}) {
    TestFamily f = make_family(law, o);
    // Move neighbour 1 onto the center (plus `gap` along the first axis).
    std::vector<double> y = f.y;
    for (int c = 0; c < f.dim; ++c) y[f.dim + c] = y[c] + (c == 0 ? gap : 0.0);
    f.set_positions(y);
    expect_finite(f.forces(law.damaged), "residual", gap);
    expect_finite(f.forces(law.intact), "intact residual", gap);
    expect_finite(f.tangent_matrix(law.damaged), "tangent", gap);
    std::vector<double> dy(static_cast<std::size_t>(f.dofs()), 0.3), df(dy.size());
    law.damaged.jvp(f.view(), dy.data(), df.data());
    expect_finite(df, "jvp", gap);
  }
}

INSTANTIATE_TEST_SUITE_P(AllLaws, DegenerateBond, testing::ValuesIn(pd::test::all_law_descriptors()),
                         pd::test::law_name);

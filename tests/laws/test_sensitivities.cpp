// Every generated law: the parameter-sensitivity kernel (d nodal forces / d material
// parameter, kernel_abi.hpp SensitivityKernel) against central differences of the generated
// residual in each parameter, on interior, truncated and damaged families, at a small and at
// a large strain (a law with memory yields there), with the committed history held fixed
// (the virgin one and one after a committed step);
// and the intact variant against the damaged one with every bond intact.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "law_list.hpp"
#include "verify/random_family.hpp"

using pd::verify::FamilyOptions;
using pd::verify::TestFamily;
using pd::verify::Truncation;

namespace {
std::vector<double> sensitivities(const TestFamily& f, const pd::abi::KernelVariant& v) {
  std::vector<double> dfdp(static_cast<std::size_t>(f.law->n_params * f.dofs()), -7.0);
  v.sensitivity(f.view(), dfdp.data());
  return dfdp;
}

// Central differences of the residual in each parameter, the moments recomputed at every
// value (the kernel's contract: the family's forces as a function of its parameters).
std::vector<double> fd_sensitivities(TestFamily f, const pd::abi::KernelVariant& v) {
  const int n = f.dofs();
  std::vector<double> out(static_cast<std::size_t>(f.law->n_params * n));
  for (int i = 0; i < f.law->n_params; ++i) {
    const double p = f.params[i], h = 1e-6 * std::max(std::fabs(p), 1e-3);
    f.params[i] = p + h;
    f.update_moments(v);
    const auto fp = f.forces(v);
    f.params[i] = p - h;
    f.update_moments(v);
    const auto fm = f.forces(v);
    f.params[i] = p;
    f.update_moments(v);
    for (int a = 0; a < n; ++a) out[i * n + a] = (fp[a] - fm[a]) / (2 * h);
  }
  return out;
}

class LawSensitivity : public testing::TestWithParam<const pd::abi::LawDescriptor*> {
 protected:
  TestFamily family(unsigned seed, Truncation truncation = Truncation::Interior, bool broken = false,
                    double strain = 0.05) const {
    FamilyOptions o;
    o.dim = GetParam()->dim;
    o.truncation = truncation;
    o.broken_bonds = broken;
    o.horizon_ratio = o.dim == 2 ? 3.0 : 2.0;
    o.strain = strain;
    o.seed = seed;
    return make_family(*GetParam(), o);
  }
};

// Column by column: each parameter's derivative within 1e-6 of the largest entry of the
// column (and of the forces' own scale over the parameter, for a column that is zero).
void expect_columns_match(const TestFamily& f, const std::vector<double>& got, const std::vector<double>& fd,
                          const std::string& what) {
  const int n = f.dofs();
  double force_scale = 0;
  for (double v : f.forces(f.law->damaged)) force_scale = std::max(force_scale, std::fabs(v));
  for (int i = 0; i < f.law->n_params; ++i) {
    double scale = force_scale / std::max(std::fabs(f.params[i]), 1e-3), err = 0;
    for (int a = 0; a < n; ++a) scale = std::max(scale, std::fabs(fd[i * n + a]));
    for (int a = 0; a < n; ++a) err = std::max(err, std::fabs(got[i * n + a] - fd[i * n + a]));
    EXPECT_LE(err, 1e-6 * scale) << what << ": parameter " << f.law->param_names[i];
  }
}
}  // namespace

TEST_P(LawSensitivity, EveryParameterMatchesCentralDifferences) {
  ASSERT_NE(GetParam()->damaged.sensitivity, nullptr);
  ASSERT_NE(GetParam()->intact.sensitivity, nullptr);
  unsigned seed = 1;
  for (Truncation t : {Truncation::Interior, Truncation::Corner})
    for (bool broken : {false, true})
      for (double strain : {0.05, 0.4}) {
        const TestFamily f = family(seed++, t, broken, strain);
        expect_columns_match(f, sensitivities(f, f.law->damaged), fd_sensitivities(f, f.law->damaged),
                             (t == Truncation::Interior ? "interior, " : "corner, ") +
                                 std::string(broken ? "broken bonds, " : "intact, ") + "strain " +
                                 std::to_string(strain));
      }
  if (!pd::abi::has_history(*GetParam())) return;
  // A law with memory: at a committed history that is not the virgin one -- a step to the
  // family's deformation committed, then a smaller deformation (unloading).
  TestFamily f = family(20, Truncation::Interior, false, 0.4);
  f.commit_update(f.law->damaged);
  std::vector<double> y = f.x;  // the center kept in place: the forces are translation invariant
  for (std::size_t a = static_cast<std::size_t>(f.dim); a < y.size(); ++a) {
    const std::size_t c = a % static_cast<std::size_t>(f.dim);
    const double y_now = f.x[c] + f.Y[a - static_cast<std::size_t>(f.dim)];
    y[a] += 0.3 * (y_now - f.x[a]);
  }
  f.set_positions(y);
  expect_columns_match(f, sensitivities(f, f.law->damaged), fd_sensitivities(f, f.law->damaged),
                       "after a committed step");
}

TEST_P(LawSensitivity, IntactVariantEqualsDamagedWithAllBondsIntact) {
  TestFamily f = family(21, Truncation::Corner, true);
  std::fill(f.alpha.begin(), f.alpha.end(), 1.0);
  f.update_moments(f.law->damaged);
  const auto damaged = sensitivities(f, f.law->damaged), intact = sensitivities(f, f.law->intact);
  double scale = 1;
  for (double v : damaged) scale = std::max(scale, std::fabs(v));
  for (std::size_t i = 0; i < damaged.size(); ++i) EXPECT_NEAR(intact[i], damaged[i], 1e-12 * scale) << i;
}

INSTANTIATE_TEST_SUITE_P(AllLaws, LawSensitivity, testing::ValuesIn(pd::test::all_law_descriptors()),
                         pd::test::law_name);

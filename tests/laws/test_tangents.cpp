// Every generated law: the factored tangent against central finite differences of the
// generated residual, block kind by block kind, on interior, truncated and damaged
// families; the tangent-vector product; momentum balance; translation invariance;
// energy consistency; the intact variant's moments, forces, tangent factors, dense tangent
// and JVP against the damaged variant's with every bond intact, and against differences.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "verify/random_family.hpp"
#include "verify/tangent_check.hpp"

using pd::verify::FamilyOptions;
using pd::verify::make_family;
using pd::verify::TestFamily;
using pd::verify::Truncation;

namespace {
struct Case {
  const pd::abi::LawDescriptor* law;
  Truncation truncation;
  bool broken;
};

std::string case_name(const testing::TestParamInfo<Case>& info) {
  const char* t[] = {"interior", "edge", "corner"};
  return std::string(info.param.law->name) + "_" + t[static_cast<int>(info.param.truncation)] +
         (info.param.broken ? "_broken" : "_intact");
}

std::vector<Case> all_cases() {
  std::vector<Case> cases;
  for (const auto& law : pd::abi::all_laws())
    for (Truncation t : {Truncation::Interior, Truncation::Edge, Truncation::Corner})
      for (bool broken : {false, true}) cases.push_back({&law, t, broken});
  return cases;
}

class LawTangent : public testing::TestWithParam<Case> {
 protected:
  TestFamily family(unsigned seed) const {
    FamilyOptions o;
    o.dim = GetParam().law->dim;
    o.truncation = GetParam().truncation;
    o.broken_bonds = GetParam().broken;
    o.horizon_ratio = o.dim == 2 ? 3.0 : 2.0;
    o.seed = seed;
    return make_family(*GetParam().law, o);
  }
};

// Every block kind of the tangent M within 1e-6 of the differences Mfd.
void expect_blocks_match(const TestFamily& f, const std::vector<double>& M, const std::vector<double>& Mfd,
                         unsigned seed) {
  const pd::verify::BlockErrors e = pd::verify::block_errors(f, M, Mfd);
  EXPECT_LE(e.center, 1e-6) << "seed " << seed;
  EXPECT_LE(e.on_diagonal, 1e-6) << "seed " << seed;
  EXPECT_LE(e.off_diagonal, 1e-6) << "seed " << seed;
  EXPECT_LE(e.center_coupling, 1e-6) << "seed " << seed;
}

}  // namespace

TEST_P(LawTangent, EveryBlockKindMatchesCentralDifferences) {
  for (unsigned seed : {1u, 2u, 3u}) {
    TestFamily f = family(seed);
    ASSERT_GT(f.bonds(), 3);
    const auto M = f.tangent_matrix(f.law->damaged);
    const auto Mfd = f.fd_matrix(f.law->damaged, 1e-6 * f.delta);
    expect_blocks_match(f, M, Mfd, seed);
  }
}

TEST_P(LawTangent, TangentKernelAlsoWritesTheResidual) {
  TestFamily f = family(4);
  pd::TangentScratch scratch;
  std::vector<double> forces(static_cast<std::size_t>(f.dofs()), -7.0);
  f.law->damaged.tangent(f.view(), forces.data(), scratch.view(f.dim, f.law->n_states, f.bonds()));
  const auto expected = f.forces(f.law->damaged);
  for (int i = 0; i < f.dofs(); ++i) EXPECT_DOUBLE_EQ(forces[i], expected[i]);
}

TEST_P(LawTangent, TangentVectorProductEqualsTangentTimesVector) {
  TestFamily f = family(5);
  const int n = f.dofs();
  std::vector<double> dy(static_cast<std::size_t>(n)), df(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) dy[i] = std::sin(1.3 * i + 0.4);
  f.law->damaged.jvp(f.view(), dy.data(), df.data());
  const auto M = f.tangent_matrix(f.law->damaged);
  double scale = 0;
  for (int i = 0; i < n; ++i) {
    double v = 0;
    for (int j = 0; j < n; ++j) v += M[i * n + j] * dy[j];
    scale = std::max(scale, std::fabs(v));
    EXPECT_NEAR(df[i], v, 1e-10 * (1 + scale)) << "dof " << i;
  }
}

TEST_P(LawTangent, ForcesOfAFamilySumToZero) {
  TestFamily f = family(6);
  const auto forces = f.forces(f.law->damaged);
  for (int c = 0; c < f.dim; ++c) {
    double s = 0, scale = 0;
    for (int a = 0; a <= f.bonds(); ++a)
      s += forces[a * f.dim + c], scale += std::fabs(forces[a * f.dim + c]);
    EXPECT_LE(std::fabs(s), 1e-12 * scale) << "component " << c;
  }
}

TEST_P(LawTangent, RigidTranslationGivesZeroForce) {
  TestFamily f = family(7);
  std::vector<double> y = f.x;
  for (std::size_t i = 0; i < y.size(); ++i) y[i] += (i % f.dim == 0 ? 0.37 : -1.21);
  f.set_positions(y);
  for (double v : f.forces(f.law->damaged)) EXPECT_NEAR(v, 0.0, 1e-12);
}

TEST_P(LawTangent, IntactVariantEqualsDamagedWithAllBondsIntact) {
  // The intact variant is only valid when no bond is broken: mend them all.
  TestFamily f = family(9);
  std::fill(f.alpha.begin(), f.alpha.end(), 1.0);
  f.update_moments(f.law->damaged);
  const auto damaged = f.forces(f.law->damaged);
  std::vector<double> m_intact(static_cast<std::size_t>(f.law->n_moments) + 1);
  f.law->intact.moments(f.view(), m_intact.data());
  for (int i = 0; i < f.law->n_moments; ++i)
    EXPECT_NEAR(m_intact[i], f.moments[i], 1e-13 * std::fabs(f.moments[i]));
  const auto intact = f.forces(f.law->intact);
  for (int i = 0; i < f.dofs(); ++i) EXPECT_NEAR(intact[i], damaged[i], 1e-13 * (1 + std::fabs(damaged[i])));
}

// Every scene without a broken bond runs on the intact variant, so its tangent is checked
// as the damaged variant's is: factors, dense form (the law's own form kernel and the
// generic forming) and JVP against the damaged variant at alpha = 1, and the dense
// form against central differences of the intact residual.
namespace {
double max_abs(const std::vector<double>& v) {
  double m = 0;
  for (double x : v) m = std::max(m, std::fabs(x));
  return m;
}

void expect_close(const std::vector<double>& got, const std::vector<double>& want, double rel,
                  const char* what) {
  ASSERT_EQ(got.size(), want.size()) << what;
  const double scale = 1 + max_abs(want);
  for (std::size_t i = 0; i < got.size(); ++i)
    EXPECT_NEAR(got[i], want[i], rel * scale) << what << " entry " << i;
}
}  // namespace

TEST_P(LawTangent, IntactTangentFactorsEqualTheDamagedOnesWithAllBondsIntact) {
  TestFamily f = family(12);
  std::fill(f.alpha.begin(), f.alpha.end(), 1.0);
  f.update_moments(f.law->damaged);
  pd::TangentScratch intact, damaged;
  std::vector<double> forces(static_cast<std::size_t>(f.dofs()), -7.0);
  f.law->intact.tangent(f.view(), forces.data(), intact.view(f.dim, f.law->n_states, f.bonds()));
  f.law->damaged.tangent(f.view(), nullptr, damaged.view(f.dim, f.law->n_states, f.bonds()));
  expect_close(intact.direct, damaged.direct, 1e-13, "direct factor");
  expect_close(intact.left, damaged.left, 1e-13, "left factor");
  expect_close(intact.right, damaged.right, 1e-13, "right factor");
  expect_close(forces, f.forces(f.law->damaged), 1e-13, "forces written by the intact tangent kernel");
}

TEST_P(LawTangent, IntactDenseTangentMatchesDamagedAndCentralDifferences) {
  for (unsigned seed : {13u, 14u}) {
    TestFamily f = family(seed);
    std::fill(f.alpha.begin(), f.alpha.end(), 1.0);
    f.update_moments(f.law->damaged);
    const auto M = f.tangent_matrix(f.law->intact);
    expect_close(M, f.tangent_matrix(f.law->damaged), 1e-12, "intact vs damaged dense tangent");
    expect_close(M, f.tangent_matrix(f.law->intact, /*generic=*/true), 1e-12,
                 "intact form kernel vs generic forming");
    const auto Mfd = f.fd_matrix(f.law->intact, 1e-6 * f.delta);
    expect_blocks_match(f, M, Mfd, seed);
  }
}

TEST_P(LawTangent, IntactTangentVectorProductEqualsTangentTimesVector) {
  TestFamily f = family(15);
  std::fill(f.alpha.begin(), f.alpha.end(), 1.0);
  f.update_moments(f.law->damaged);
  const int n = f.dofs();
  std::vector<double> dy(static_cast<std::size_t>(n)), intact(dy.size()), damaged(dy.size());
  for (int i = 0; i < n; ++i) dy[i] = std::cos(0.7 * i + 0.2);
  f.law->intact.jvp(f.view(), dy.data(), intact.data());
  f.law->damaged.jvp(f.view(), dy.data(), damaged.data());
  expect_close(intact, damaged, 1e-12, "intact vs damaged JVP");
  const auto M = f.tangent_matrix(f.law->intact);
  std::vector<double> Mdy(dy.size(), 0.0);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) Mdy[i] += M[i * n + j] * dy[j];
  expect_close(intact, Mdy, 1e-10, "intact JVP vs intact tangent times vector");
}

// The assembler skips a family whose bonds are all broken (has_intact_bond): sound only
// if every law weights a bond's force by its alpha, so a broken bond carries no force.
TEST_P(LawTangent, BrokenBondsCarryNoForce) {
  TestFamily f = family(11);
  for (int k = 0; k < f.bonds(); k += 3) f.alpha[k] = 0.0;  // besides any the case broke
  f.update_moments(f.law->damaged);
  const auto forces = f.forces(f.law->damaged);
  int broken = 0;
  for (int k = 0; k < f.bonds(); ++k) {
    if (f.alpha[k] != 0.0) continue;
    ++broken;
    for (int c = 0; c < f.dim; ++c) EXPECT_EQ(forces[(k + 1) * f.dim + c], 0.0) << "bond " << k;
  }
  EXPECT_GT(broken, 0);
}

INSTANTIATE_TEST_SUITE_P(AllLaws, LawTangent, testing::ValuesIn(all_cases()), case_name);

// Laws that declare a strain-energy density.
class LawEnergy : public LawTangent {};

TEST_P(LawEnergy, ForcesAreMinusTheGradientOfTheEnergy) {
  TestFamily f = family(8);
  const auto forces = f.forces(f.law->damaged);
  const double step = 1e-6 * f.delta;
  double scale = 0;
  for (double v : forces) scale = std::max(scale, std::fabs(v));
  std::vector<double> y0 = f.y;
  for (int j = 0; j < f.dofs(); ++j) {
    std::vector<double> p = y0;
    p[j] += step;
    f.set_positions(p);
    const double ep = f.V0 * f.law->damaged.energy(f.view());
    p[j] -= 2 * step;
    f.set_positions(p);
    const double em = f.V0 * f.law->damaged.energy(f.view());
    EXPECT_NEAR(forces[j], -(ep - em) / (2 * step), 1e-6 * scale) << "dof " << j;
  }
}

std::vector<Case> energy_cases() {
  std::vector<Case> cases;
  for (const Case& c : all_cases())
    if (c.law->damaged.energy != nullptr) cases.push_back(c);
  return cases;
}

INSTANTIATE_TEST_SUITE_P(LawsWithEnergy, LawEnergy, testing::ValuesIn(energy_cases()), case_name);

// Patch test for every law and influence function: under a homogeneous linear
// deformation of a uniform grid, the particles far enough from the boundary that every
// family they touch is complete (distance > 2 delta) feel no net force. Also: the
// corrected LPS dilatation is exact for linear fields even on truncated and damaged families.
#include <gtest/gtest.h>

#include <cmath>

#include "assembly/assembler.hpp"
#include "discretize/discretization.hpp"
#include "material/elastic_constants.hpp"
#include "verify/random_family.hpp"
#include "verify/test_values.hpp"

namespace {
struct Case {
  const pd::abi::LawDescriptor* law;
  const pd::abi::InfluenceDescriptor* influence;
};
std::vector<Case> cases() {
  std::vector<Case> v;
  for (const auto& l : pd::abi::all_laws())
    for (const auto& i : pd::abi::all_influences()) v.push_back({&l, &i});
  return v;
}
std::string name(const testing::TestParamInfo<Case>& info) {
  return std::string(info.param.law->name) + "_" + info.param.influence->name;
}
class Patch : public testing::TestWithParam<Case> {};
}  // namespace

TEST_P(Patch, InteriorParticlesOfAHomogeneouslyStrainedGridFeelNoNetForce) {
  const auto& law = *GetParam().law;
  pd::Scene s;
  s.dim = law.dim;
  s.h = 1.0;
  const double ratio = law.dim == 2 ? 3.0 : 2.0, delta = ratio * s.h;
  const int n = law.dim == 2 ? 16 : 11;
  s.lo = {0, 0, 0};
  s.hi = {double(n), double(n), law.dim == 3 ? double(n) : 0.0};
  s.materials.resize(1);
  const pd::Particles p = pd::discretize(s);
  const pd::Bonds b = pd::find_bonds(p, delta, GetParam().influence->weight);
  const auto m = pd::IsotropicElastic::from_E_nu(1.0, 0.25);
  // Parameters that are not elastic constants take the values the law declares for its
  // tests: a law with its own parameter needs no edit here.
  const auto params =
      pd::law_parameters(law, m, pd::PlaneAssumption::Strain, pd::verify::declared_test_values(law));
  pd::AssemblerOptions options;
  options.intact = true;
  options.matrix = false;
  const pd::FamilyAssembler a(p, b, law, {params}, options);
  const double H[9] = {1e-3, 4e-4, -2e-4, -3e-4, 2e-3, 1e-4, 5e-4, -1e-4, -1e-3};
  std::vector<double> u(p.x.size());
  const int d = law.dim;
  for (int i = 0; i < p.size(); ++i)
    for (int r = 0; r < d; ++r) {
      u[i * d + r] = 0;
      for (int c = 0; c < d; ++c) u[i * d + r] += H[r * 3 + c] * p.x[i * d + c];
    }
  std::vector<double> f(u.size());
  a.internal_forces(u.data(), f.data());
  double boundary = 0, interior = 0;
  int n_interior = 0;
  for (int i = 0; i < p.size(); ++i) {
    bool inside = true;
    for (int c = 0; c < d; ++c)
      inside = inside && p.x[i * d + c] > 2 * delta + 0.5 && p.x[i * d + c] < n - 2 * delta - 0.5;
    for (int c = 0; c < d; ++c)
      (inside ? interior : boundary) = std::max(inside ? interior : boundary, std::fabs(f[i * d + c]));
    n_interior += inside;
  }
  ASSERT_GT(n_interior, 0);
  ASSERT_GT(boundary, 0.0);
  EXPECT_LE(interior, 1e-9 * boundary) << "interior " << interior << " boundary " << boundary;
}

INSTANTIATE_TEST_SUITE_P(AllLawsAllInfluences, Patch, testing::ValuesIn(cases()), name);

TEST(CorrectedDilatation, ExactForLinearFieldsOnTruncatedAndDamagedFamilies) {
  for (const char* lname : {"lps_corrected_plane_strain", "lps_corrected_3d",
                            "lps_paper_corrected_plane_strain", "lps_paper_corrected_3d"}) {
    const auto* law = pd::abi::find_law(lname);
    ASSERT_NE(law, nullptr);
    for (auto t :
         {pd::verify::Truncation::Interior, pd::verify::Truncation::Edge, pd::verify::Truncation::Corner}) {
      pd::verify::FamilyOptions o;
      o.dim = law->dim;
      o.truncation = t;
      o.broken_bonds = true;
      o.horizon_ratio = law->dim == 2 ? 3.0 : 2.0;
      pd::verify::TestFamily f = pd::verify::make_family(*law, o);
      const double H[9] = {1e-3, 4e-4, -2e-4, -3e-4, 2e-3, 1e-4, 5e-4, -1e-4, -1e-3};
      std::vector<double> y(f.x.size());
      for (int q = 0; q <= f.bonds(); ++q)
        for (int r = 0; r < f.dim; ++r) {
          y[q * f.dim + r] = f.x[q * f.dim + r];
          for (int c = 0; c < f.dim; ++c) y[q * f.dim + r] += H[r * 3 + c] * f.x[q * f.dim + c];
        }
      f.set_positions(y);
      double theta = 0;
      law->damaged.outputs(f.view(), &theta);
      const double trace = law->dim == 2 ? 3e-3 : 2e-3;
      EXPECT_NEAR(theta, trace, 1e-12) << lname << " truncation " << static_cast<int>(t);
    }
  }
}

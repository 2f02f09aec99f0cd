// domain.surface_correction: read, refused where it cannot apply, and applied by
// the model's first phase (DiscretizedBody) to the bonds the assembler sees.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "assembly/surface_correction.hpp"
#include "input/scene.hpp"
#include "input/yaml_keys.hpp"
#include "model/model.hpp"

namespace {
std::string plate(const std::string& domain_extra, const std::string& law = "oterkus_plane_strain") {
  return "dimension: 2\ndomain:\n  box: {min: [0, 0], max: [8, 8]}\n  spacing: 1\n" + domain_extra +
         "horizon: {ratio: 3}\nlaw: " + law + "\nmaterials:\n  - {name: m, E: 1, nu: 0.2, plane: strain}\n";
}
std::string error_of(const std::string& yaml) {
  try {
    pd::parse_scene(yaml, "s.yaml");
  } catch (const pd::SceneError& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST(SurfaceCorrectionScene, ReadsTheKeyAndRefusesWhatItCannotCorrect) {
  EXPECT_FALSE(pd::parse_scene(plate(""), "s.yaml").surface_correction);
  const pd::Scene terms = pd::parse_scene(plate("  surface_correction: terms\n"), "s.yaml");
  EXPECT_TRUE(terms.surface_correction);
  EXPECT_EQ(terms.surface_match, pd::SurfaceMatch::Terms);
  EXPECT_EQ(pd::parse_scene(plate("  surface_correction: responses\n"), "s.yaml").surface_match,
            pd::SurfaceMatch::Responses);
  EXPECT_EQ(pd::parse_scene(plate("  surface_correction: directions\n"), "s.yaml").surface_match,
            pd::SurfaceMatch::Directions);
  EXPECT_NE(error_of(plate("  surface_correction: yes\n"))
                .find("s.yaml:5: domain.surface_correction: surface_correction is none"),
            std::string::npos)
      << error_of(plate("  surface_correction: yes\n"));
  EXPECT_NE(error_of(plate("  compensation: true\n  surface_correction: terms\n")).find("choose one"),
            std::string::npos);
  EXPECT_NE(error_of(plate("  quadrature: obq\n  surface_correction: terms\n")).find("obq"),
            std::string::npos);
  EXPECT_NE(error_of(plate("  surface_correction: terms\n  gauss_points: {per_axis: 2}\n"))
                .find("surface_correction"),
            std::string::npos);
}

TEST(SurfaceCorrectionScene, TheBodyPutsTheBondMeansOnTheBonds) {
  const pd::DiscretizedBody off(pd::parse_scene(plate(""), "s.yaml"));
  EXPECT_TRUE(off.bonds.surface_force.empty());
  EXPECT_TRUE(off.bonds.surface_dilatation.empty());
  const pd::DiscretizedBody on(pd::parse_scene(plate("  surface_correction: terms\n"), "s.yaml"));
  ASSERT_EQ(on.bonds.surface_force.size(), on.bonds.neighbor.size());
  ASSERT_EQ(on.bonds.surface_dilatation.size(), on.bonds.neighbor.size());
  const auto [lo, hi] = std::minmax_element(on.bonds.surface_force.begin(), on.bonds.surface_force.end());
  EXPECT_LT(*lo, 0.95);  // Oterkus's cut families are too stiff in shear (docs/paper003.md)
  EXPECT_GT(*hi, 0.0);
  // A bond keeps one factor in both of its families.
  for (int i = 0; i < on.particles.size(); ++i)
    for (int e = on.bonds.offsets[i]; e < on.bonds.offsets[i + 1]; ++e) {
      const int j = on.bonds.neighbor[e];
      for (int f = on.bonds.offsets[j]; f < on.bonds.offsets[j + 1]; ++f)
        if (on.bonds.neighbor[f] == i) {
          ASSERT_DOUBLE_EQ(on.bonds.surface_force[f], on.bonds.surface_force[e]);
        }
    }
  // ... and that factor is the mean of its two ends' (paper 003 eq. 19): the particles'
  // factors computed here from the uncorrected body, with the inputs the model gives.
  const pd::SurfaceCorrectionInputs in{
      off.law, &off.params, 3.0, 1.0, pd::Quadrature::Volume, off.influence->weight, pd::SurfaceMatch::Terms};
  const pd::SurfaceFactors ends = pd::surface_correction_factors(off.particles, off.bonds, in);
  int whole = 0;
  for (int i = 0; i < on.particles.size(); ++i)
    for (int e = on.bonds.offsets[i]; e < on.bonds.offsets[i + 1]; ++e) {
      const auto j = static_cast<std::size_t>(on.bonds.neighbor[e]), k = static_cast<std::size_t>(i);
      ASSERT_NEAR(on.bonds.surface_force[e], 0.5 * (ends.force[k] + ends.force[j]), 1e-15);
      ASSERT_NEAR(on.bonds.surface_dilatation[e], 0.5 * (ends.dilatation[k] + ends.dilatation[j]), 1e-15);
      // Two ends whose families the surface did not cut (cell centres 3.5 and 4.5 on the 8 x 8
      // plate at delta 3) keep the bond as it is: the factors of a whole family are 1.
      const double* p = on.particles.position(i);
      const double* q = on.particles.position(on.bonds.neighbor[e]);
      if (std::min({p[0], p[1], q[0], q[1]}) >= 3 && std::max({p[0], p[1], q[0], q[1]}) <= 5) {
        EXPECT_NEAR(on.bonds.surface_force[e], 1.0, 1e-12);
        EXPECT_NEAR(on.bonds.surface_dilatation[e], 1.0, 1e-12);
        ++whole;
      }
    }
  EXPECT_EQ(whole, 4 * 3);  // the 2 x 2 whole families and their bonds to each other
  // A law without a dilatation sum gets the force factor only.
  const pd::DiscretizedBody bb(
      pd::parse_scene(plate("  surface_correction: terms\n", "bond_based_constant_2d"), "s.yaml"));
  EXPECT_TRUE(bb.bonds.surface_dilatation.empty());
  EXPECT_FALSE(bb.bonds.surface_force.empty());
}

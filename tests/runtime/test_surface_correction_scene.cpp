// domain.surface_correction: read, refused where it cannot apply, and applied by
// the model's first phase (DiscretizedBody) to the bonds the assembler sees.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

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
  EXPECT_FALSE(terms.surface_match_responses);
  EXPECT_TRUE(pd::parse_scene(plate("  surface_correction: responses\n"), "s.yaml").surface_match_responses);
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
  // A law without a dilatation sum gets the force factor only.
  const pd::DiscretizedBody bb(
      pd::parse_scene(plate("  surface_correction: terms\n", "bond_based_constant_2d"), "s.yaml"));
  EXPECT_TRUE(bb.bonds.surface_dilatation.empty());
  EXPECT_FALSE(bb.bonds.surface_force.empty());
}

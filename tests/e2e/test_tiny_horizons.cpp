// Singular influence functions and tiny horizons (delta/h from 1 to 1.5): families
// without weight or with a singular shape tensor stop the run before the solve, naming
// the particles; every other combination solves, and no NaN ever reaches the solver.
#include <gtest/gtest.h>

#include <cmath>
#include <regex>

#include "discretize/family_quality.hpp"
#include "input/scene.hpp"
#include "kernel_abi.hpp"
#include "run/simulation.hpp"

namespace {
std::string scene_text(const std::string& law, const std::string& influence, double ratio,
                       const std::string& box = "[1, 1]") {
  return "dimension: 2\ndomain:\n  box: {min: [0, 0], max: " + box +
         "}\n  spacing: 0.1\nhorizon: {ratio: " + std::to_string(ratio) + "}\nlaw: " + law +
         "\ninfluence: " + influence +
         "\nmaterials: [{E: 1, nu: 0.25}]\nboundary:\n  - region: {side: bottom}\n    fixed: [x, y]\n"
         "  - region: {side: top}\n    displacement: {x: 0.002, y: 0.01}\n";
}

// "" when the scene solves; otherwise the message and where it came from.
std::string failure(const std::string& text, bool& at_setup) {
  at_setup = false;
  std::unique_ptr<pd::Simulation> sim;
  try {
    sim = std::make_unique<pd::Simulation>(pd::parse_scene(text, "t.yaml"), [](const std::string&) {});
  } catch (const std::exception& e) {
    at_setup = true;
    return e.what();
  }
  try {
    sim->run(false);
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST(TinyHorizons, ContinuumWeightedVolumeByHand) {
  const double d = 0.7, pi = M_PI;
  EXPECT_NEAR(pd::continuum_weighted_volume(pd::abi::find_influence("const")->weight, d, 2),
              pi * std::pow(d, 4) / 2, 1e-6);
  EXPECT_NEAR(pd::continuum_weighted_volume(pd::abi::find_influence("linear")->weight, d, 2),
              pi * std::pow(d, 4) / 10, 1e-6);
  EXPECT_NEAR(pd::continuum_weighted_volume(pd::abi::find_influence("rational_a0_n2")->weight, d, 2),
              pi * d * d, 1e-6);
  EXPECT_NEAR(pd::continuum_weighted_volume(pd::abi::find_influence("const")->weight, d, 3),
              4 * pi * std::pow(d, 5) / 5, 1e-6);
}

TEST(TinyHorizons, WeightlessAndStrainBlindFamiliesAreReportedBeforeTheSolveAndNoNaNReachesIt) {
  // Influence functions with a factor (1 - r/delta)^a, a > 0, vanish on the horizon; at
  // delta = h the only bonds lie there, so every family is weightless. Below
  // delta/h = sqrt(2) a square lattice gives each particle only its 4 axial bonds: laws
  // whose forces follow bond stretches (Silling, LPS) then have no shear stiffness at all,
  // while the correspondence law (F = N K^-1) still has. Everything else must solve.
  for (const char* law : {"silling_plane_strain", "correspondence_plane_strain", "lps_plane_strain"})
    for (const char* influence :
         {"const", "inv", "rational_a0_n2", "rational_a1_n2", "rational_a2_n2", "cubic", "linear"})
      for (double ratio : {1.0, 1.1, 1.25, 1.5}) {
        bool at_setup = false;
        const std::string msg = failure(scene_text(law, influence, ratio), at_setup);
        const std::string inf(influence);
        const bool vanishes_on_horizon = inf != "const" && inf != "inv" && inf != "rational_a0_n2";
        const bool stretch_law = std::string(law) != "correspondence_plane_strain";
        const std::string what =
            std::string(law) + " " + influence + " delta/h " + std::to_string(ratio) + ": " + msg;
        EXPECT_EQ(msg.find("finite"), std::string::npos)
            << what;  // no NaN/Inf from assembly, moments or Newton
        if (ratio == 1.0 && vanishes_on_horizon) {
          EXPECT_TRUE(at_setup) << what;
          EXPECT_TRUE(std::regex_search(
              msg, std::regex(R"(^100 particle\(s\) have \(almost\) no weighted volume.*influence )" + inf +
                              R"( at delta/h = 1 .*particle 0 at \(0\.05, 0\.05\))")))
              << what;
        } else if (ratio < std::sqrt(2.0) && stretch_law) {
          EXPECT_TRUE(at_setup) << what;
          EXPECT_TRUE(std::regex_search(
              msg, std::regex("^100 of 100 families give law " + std::string(law) +
                              R"( no stiffness against some homogeneous strain \(influence )" + inf +
                              R"(.*particle 0 at \(0\.05, 0\.05\))")))
              << what;
        } else {
          EXPECT_EQ(msg, "") << what;
        }
      }
}

TEST(TinyHorizons, CollinearFamiliesAreReportedAsSingularShapeTensors) {
  // A body one particle thick: every bond is horizontal, so no family resolves y.
  bool at_setup = false;
  const std::string msg =
      failure(scene_text("correspondence_plane_strain", "cubic", 3.0, "[1, 0.1]"), at_setup);
  EXPECT_TRUE(at_setup) << msg;
  EXPECT_TRUE(std::regex_search(
      msg,
      std::regex(
          R"(^10 particle\(s\) have a near-singular shape tensor .*particle 0 at \(0\.05, 0\.05\) condition number inf, 3 intact bond\(s\).*and 5 more)")))
      << msg;
}

// Rigid rotations up to 90 degrees (issue: numerical stability). The outer collar of a
// square, two horizons thick, follows a rotation (or rotation + 10% stretch) about the
// centre, along a path of rotations (DofMap::set_load_path); every family that touches a
// free particle is complete, so for an objective law the homogeneous motion is the exact
// solution. Objective laws: Newton converges to it, and the rigid rotation leaves no
// internal force anywhere. The laws built on a linear strain (LPS, correspondence and
// its stabilised forms) are not objective: the exact rotation needs reaction forces.
#include <gtest/gtest.h>

#include <cmath>

#include "fields/analytic.hpp"
#include "input/scene.hpp"
#include "run/simulation.hpp"

namespace {
std::string scene_text(const std::string& law, double angle, double stretch) {
  const std::string field = "{solution: rotation, angle: " + std::to_string(angle) +
                            ", stretch: " + std::to_string(stretch) + ", x0: 0.5, y0: 0.5}";
  // h = 1/18, delta = 3h = 1/6: the collar is two horizons thick.
  return "dimension: 2\ndomain:\n  box: {min: [0, 0], max: [1, 1]}\n  count: 18\nhorizon: {ratio: 3}\nlaw: " +
         law +
         "\ninfluence: cubic\nmaterials: [{E: 1, nu: 0.25, parameters: {stab: 1, hourglass: 1}}]\nboundary:\n"
         "  - region: {outside: {min: [0.3333333, 0.3333333], max: [0.6666667, 0.6666667]}}\n    field: " +
         field + "\nreference: " + field + "\nsolver: {load_steps: 3, tolerance: 1e-12}\n";
}

double max_abs(const std::vector<double>& v) {
  double m = 0;
  for (double x : v) m = std::max(m, std::fabs(x));
  return m;
}

// Largest internal nodal force of the law at the analytic field of `scene`'s reference.
double force_at(const pd::Simulation& sim, const pd::FieldSpec& field) {
  const pd::AnalyticField f(field, sim.scene().materials[0].elastic);
  const pd::Particles& p = sim.particles();
  std::vector<double> u(static_cast<std::size_t>(p.size()) * 2), force(u.size());
  for (int i = 0; i < p.size(); ++i) {
    const auto ui = f.displacement(p.position(i));
    u[2 * i] = ui[0], u[2 * i + 1] = ui[1];
  }
  sim.assembler().internal_forces(u.data(), force.data());
  return max_abs(force);
}

// The force scale: the largest internal force under a 1% isotropic stretch.
double stretch_scale(const pd::Simulation& sim) {
  return force_at(sim,
                  pd::FieldSpec{"rotation", {{"angle", 0.0}, {"stretch", 0.01}, {"x0", 0.5}, {"y0", 0.5}}});
}
}  // namespace

TEST(Rotations, ObjectiveLawsFollowRotationsUpTo90DegreesWithoutInternalForce) {
  for (const char* law : {"silling_plane_strain", "oterkus_plane_strain", "bond_based_conical_2d"})
    for (const auto& [angle, stretch] :
         {std::pair{30.0, 0.0}, std::pair{60.0, 0.0}, std::pair{90.0, 0.0}, std::pair{90.0, 0.1}}) {
      const std::string what =
          std::string(law) + " angle " + std::to_string(angle) + " stretch " + std::to_string(stretch);
      pd::Simulation sim(pd::parse_scene(scene_text(law, angle, stretch), "rotation.yaml"),
                         [](const std::string&) {});
      pd::RunSummary r;
      try {
        r = sim.run(false);
      } catch (const std::exception& e) {
        ADD_FAILURE() << what << ": " << e.what();
        continue;
      }
      ASSERT_TRUE(r.newton.converged) << what << ": " << r.newton.message;
      EXPECT_LT(r.field_error, 1e-20) << what;  // sum |u - u_exact|^2 / sum |u_exact|^2
      if (stretch == 0.0) {
        std::vector<double> force(sim.displacement().size());
        sim.assembler().internal_forces(sim.displacement().data(), force.data());
        EXPECT_LT(max_abs(force), 1e-9 * stretch_scale(sim)) << what;
      }
    }
}

TEST(Rotations, LinearStrainLawsAreNotObjective) {
  for (const char* law : {"lps_plane_strain", "lps_corrected_plane_strain", "correspondence_plane_strain",
                          "correspondence_silling_plane_strain", "correspondence_littlewood_plane_strain"}) {
    pd::Simulation sim(pd::parse_scene(scene_text(law, 30, 0), "rotation.yaml"), [](const std::string&) {});
    // A 30-degree rotation reads as a contraction of 1 - cos 30 = 13%: forces about 13
    // times those of the 1% stretch, where an objective law has none.
    EXPECT_GT(force_at(sim, *sim.scene().reference), 1.0 * stretch_scale(sim)) << law;
  }
  // The same measure for an objective law, as a control.
  pd::Simulation sim(pd::parse_scene(scene_text("silling_plane_strain", 30, 0), "rotation.yaml"),
                     [](const std::string&) {});
  EXPECT_LT(force_at(sim, *sim.scene().reference), 1e-9 * stretch_scale(sim));
}

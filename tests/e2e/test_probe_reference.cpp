// A probe's reference is taken where paper 000 measures (eq. 36: the analytic displacement
// at y = H for the top probe), whatever rows the particles sit on: on a cell-centred
// lattice the top row is at H - h/2, and `reference_at: particles` is the mean there.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "input/scene.hpp"
#include "run/simulation.hpp"

namespace {
// scenes/uniaxial.yaml: E = 1000 GPa, nu = 0, T = -0.001 GPa on a 10 mm block, so the
// analytic u_y = T y / E (plane strain, nu = 0) is -1e-6 y.
constexpr double kSlope = -0.001 / 1000;

pd::ProbeResult top_probe(const std::string& placement, const std::string& reference_at) {
  pd::Scene s = pd::read_scene(std::string(PD_SOURCE_DIR) + "/scenes/uniaxial.yaml");
  s.placement = *pd::parse_name<pd::Placement>(placement);
  s.h = 10.0 / 20;
  s.law = "correspondence_plane_strain";
  s.horizon_ratio = 1.5;
  // The probe is the middle of the top side (`within`): the outermost row on either lattice.
  pd::Probe& p = s.probes.at(0);
  if (reference_at == "particles") p.reference_at = pd::Probe::ReferenceAt::particles;
  if (reference_at == "point") {
    p.reference_at = pd::Probe::ReferenceAt::point;
    p.reference_point = {5, 8, 0};
  }
  pd::Simulation sim(s, [](const std::string&) {});
  const pd::RunSummary r = sim.run(false);
  EXPECT_TRUE(r.newton.converged);
  return r.probes.at(0);
}
}  // namespace

TEST(ProbeReference, DefaultIsTheAnalyticValueAtTheRegionPoint) {
  for (const char* placement : {"cell", "node"}) {
    const pd::ProbeResult r = top_probe(placement, "region");
    EXPECT_NEAR(r.reference, kSlope * 10, 1e-15) << placement;
    EXPECT_NEAR(r.error, std::fabs(r.value - kSlope * 10), 1e-18) << placement;
  }
}

TEST(ProbeReference, ParticlesAndAnExplicitPointAreTheirOwnReferences) {
  // Cell placement: the top row at y = H - h/2 = 9.75.
  EXPECT_NEAR(top_probe("cell", "particles").reference, kSlope * 9.75, 1e-15);
  EXPECT_NEAR(top_probe("node", "particles").reference, kSlope * 10, 1e-15);
  EXPECT_NEAR(top_probe("cell", "point").reference, kSlope * 8, 1e-15);
}

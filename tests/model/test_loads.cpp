// Nodal forces of the loads: tractions (paper 000 eq. 34), body forces, and the crack
// pressure on the bonds across the crack faces (eqs. 23, 30), read from the effects at
// zero displacement and unit load factor.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "discretize/discretization.hpp"
#include "effects/loads.hpp"

namespace {

double unit(double, double) { return 1.0; }

pd::Scene box_scene(int dim, double h, double perturbation) {
  pd::Scene s;
  s.file = "test.yaml";
  s.dim = dim;
  s.lo = {0, 0, 0};
  s.hi = {2, 1, 0.5};
  s.h = h;
  s.perturbation = perturbation;
  s.seed = 8;
  s.materials.resize(1);
  return s;
}

pd::BoundaryCondition load(pd::BoundaryCondition::Kind kind, const std::string& side, pd::Point values) {
  pd::BoundaryCondition bc;
  bc.kind = kind;
  bc.region.kind = side.empty() ? pd::Region::Kind::All : pd::Region::Kind::Side;
  if (!side.empty()) bc.region.side = *pd::parse_name<pd::Region::Side>(side);
  bc.values = values;
  bc.where = "test.yaml:1: boundary[0]";
  return bc;
}

std::vector<double> forces(const pd::Effect& e, int n_dofs) {
  std::vector<double> u(n_dofs, 0.0), r(n_dofs, 0.0);
  e.add_forces(u.data(), 1.0, r.data());
  return r;
}

}  // namespace

TEST(Loads, TractionNodalForcesSumToTractionTimesEdge) {
  for (double perturbation : {0.0, 0.4}) {
    pd::Scene s = box_scene(2, 0.1, perturbation);
    s.boundary.push_back(load(pd::BoundaryCondition::Kind::Traction, "top", {0.3, -2.0, 0}));
    const pd::Particles p = pd::discretize(s);
    const auto effect = pd::make_external_loads(s, p);
    ASSERT_NE(effect, nullptr);
    const auto f = forces(*effect, p.size() * 2);
    double fx = 0, fy = 0;
    int loaded = 0;
    for (int i = 0; i < p.size(); ++i) {
      fx += f[2 * i];
      fy += f[2 * i + 1];
      if (f[2 * i + 1] != 0.0) {
        ++loaded;
        // Eq. 34: each of the N_edge particles of the top row gets T W / N_edge.
        EXPECT_NEAR(f[2 * i + 1], -2.0 * 2.0 / 20, 1e-14);
        EXPECT_GT(p.position(i)[1], 1.0 - s.h);
      }
    }
    EXPECT_EQ(loaded, 20) << "the whole top row, perturbation " << perturbation;
    EXPECT_NEAR(fx, 0.3 * 2.0, 1e-12);  // traction x edge length W = 2
    EXPECT_NEAR(fy, -2.0 * 2.0, 1e-12);
  }
}

TEST(Loads, TractionOnA3DFaceAndABoxRegion) {
  pd::Scene s = box_scene(3, 0.1, 0.2);
  s.boundary.push_back(load(pd::BoundaryCondition::Kind::Traction, "right", {1.5, 0, 0}));
  pd::BoundaryCondition box = load(pd::BoundaryCondition::Kind::Traction, "", {0, 0, -1.0});
  box.region.kind = pd::Region::Kind::Box;
  box.region.min = {0.5, 0.5, 0.4};
  box.region.max = {1.0, 1.0, 0.5};
  box.face_measure = 0.25;  // the patch 0.5 x 0.5 of the front face
  s.boundary.push_back(box);
  const pd::Particles p = pd::discretize(s);
  const auto f = forces(*pd::make_external_loads(s, p), p.size() * 3);
  double sum[3] = {0, 0, 0};
  for (int i = 0; i < p.size(); ++i)
    for (int c = 0; c < 3; ++c) sum[c] += f[3 * i + c];
  EXPECT_NEAR(sum[0], 1.5 * 1.0 * 0.5, 1e-12);  // right face: H x D = 1 x 0.5
  EXPECT_NEAR(sum[1], 0.0, 1e-15);
  EXPECT_NEAR(sum[2], -1.0 * 0.25, 1e-12);
}

TEST(Loads, BodyForceIsForcePerVolume) {
  pd::Scene s = box_scene(2, 0.05, 0.3);
  s.boundary.push_back(load(pd::BoundaryCondition::Kind::BodyForce, "", {0, -9.81, 0}));
  const pd::Particles p = pd::discretize(s);
  const auto f = forces(*pd::make_external_loads(s, p), p.size() * 2);
  double fy = 0;
  for (int i = 0; i < p.size(); ++i) fy += f[2 * i + 1];
  EXPECT_NEAR(fy, -9.81 * 2.0, 1e-10);
}

TEST(Loads, NoLoadsNoEffect) {
  const pd::Scene s = box_scene(2, 0.1, 0.0);
  EXPECT_EQ(pd::make_external_loads(s, pd::discretize(s)), nullptr);
}

TEST(Loads, CrackPressureEqualsPressureTimesCrackLength) {
  // The paper-000 set-up: crack between two rows (y = 0.5 with h = 0.05), tips at
  // multiples of h. Eq. (30) read as t V_A = (p/2) (y_B - y_A)/|y_B - y_A|^2 per state, so
  // each nearest-neighbour pair across the crack pushes its particles apart with p V/|xi|
  // = p h: the pressure on the face length h each particle covers.
  pd::Scene s = box_scene(2, 0.05, 0.0);
  s.hi = {2, 1, 0};
  pd::Crack crack;
  crack.points = {pd::Point{0.5, 0.5, 0}, pd::Point{1.5, 0.5, 0}};
  crack.pressure = 0.2;
  s.cracks.push_back(crack);
  const pd::Particles p = pd::discretize(s);
  pd::Bonds b = pd::find_bonds(p, 3 * s.h, unit);
  pd::cut_bonds(s.cracks, p, b);
  const auto effect = pd::make_crack_pressure(s, p, b);
  ASSERT_NE(effect, nullptr);
  const auto f = forces(*effect, p.size() * 2);
  double up = 0, down = 0, fx = 0;
  int loaded = 0;
  for (int i = 0; i < p.size(); ++i) {
    const double y = p.position(i)[1], x = p.position(i)[0];
    fx += f[2 * i];
    (y > 0.5 ? up : down) += f[2 * i + 1];
    if (f[2 * i + 1] != 0.0) {
      ++loaded;
      EXPECT_NEAR(std::fabs(y - 0.5), 0.5 * s.h, 1e-12) << "only the rows facing the crack";
      EXPECT_GT(x, 0.5);
      EXPECT_LT(x, 1.5);
      EXPECT_NEAR(f[2 * i + 1], (y > 0.5 ? 1 : -1) * 0.2 * s.h, 1e-14) << "pushes the faces apart";
    }
  }
  EXPECT_EQ(loaded, 2 * 20);
  EXPECT_NEAR(up, 0.2 * 1.0, 1e-12);  // p x crack length
  EXPECT_NEAR(down, -0.2 * 1.0, 1e-12);
  EXPECT_NEAR(fx, 0.0, 1e-14);
}

TEST(Loads, UnpressurisedCracksHaveNoPressureEffect) {
  pd::Scene s = box_scene(2, 0.1, 0.0);
  pd::Crack crack;
  crack.points = {pd::Point{0.5, 0.5, 0}, pd::Point{1.5, 0.5, 0}};
  s.cracks.push_back(crack);
  const pd::Particles p = pd::discretize(s);
  pd::Bonds b = pd::find_bonds(p, 3 * s.h, unit);
  EXPECT_EQ(pd::make_crack_pressure(s, p, b), nullptr);
}

// Crack pressure on a perturbed cloud: the total normal load on each crack face is
// p x crack length, whatever the perturbation (on the paper's lattice it is by construction).
#include <gtest/gtest.h>

#include <cmath>

#include "assemble/sparsity.hpp"
#include "discretize/discretization.hpp"
#include "run/effects.hpp"

TEST(CrackPressure, TotalNormalLoadOnEachFaceIsPressureTimesLength) {
  for (double amplitude : {0.0, 0.2, 0.4}) {
    pd::Scene s;
    s.dim = 2;
    s.lo = {-1, -1, 0};
    s.hi = {1, 1, 0};
    s.h = 0.05;
    s.perturbation = amplitude;
    s.seed = 11;
    s.materials.resize(1);
    pd::Crack c;
    c.points = {pd::Point{-0.4, 0, 0}, pd::Point{0.4, 0, 0}};
    c.pressure = 0.1;
    s.cracks = {c};
    const pd::Particles p = pd::discretize(s);
    pd::Bonds b = pd::find_bonds(p, 3 * s.h, [](double, double) { return 1.0; });
    pd::cut_bonds(s.cracks, p, b);
    const pd::Sparsity sp(b, 2);
    const auto effect = pd::make_crack_pressure(s, p, b, sp);
    ASSERT_NE(effect, nullptr);
    std::vector<double> u(p.x.size(), 0.0), r(p.x.size(), 0.0);
    effect->add_forces(u, 1.0, r);
    double up = 0, down = 0, sum_x = 0;
    for (int i = 0; i < p.size(); ++i) {
      (p.x[2 * i + 1] > 0 ? up : down) += r[2 * i + 1];
      sum_x += r[2 * i];
    }
    EXPECT_NEAR(up, 0.1 * 0.8, 1e-12) << "amplitude " << amplitude;
    EXPECT_NEAR(down, -0.1 * 0.8, 1e-12) << "amplitude " << amplitude;
    EXPECT_NEAR(sum_x, 0.0, 1e-12);
  }
}

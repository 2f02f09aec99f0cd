// Shared set-up of the OBQ tests: paper 001's perturbed point cloud (§4: lattice of
// spacing h, each point moved by a uniform variable of magnitude 0.2 h, delta = 3.5 h)
// with OBQ weights on the families whose ball lies inside the cloud.
#pragma once

#include <vector>

#include "assembly/collocation.hpp"
#include "discretize/discretization.hpp"
#include "discretize/obq_weights.hpp"
#include "kernel_abi.hpp"
#include "unit_box_cloud.hpp"

namespace obq_test {

struct Cloud {
  pd::Particles particles;
  pd::Bonds bonds;
  double h = 0, delta = 0;
  std::vector<char> full_ball;  // the family's ball lies inside the unit box
};

// The unit square (dim 2) or cube (dim 3).
inline Cloud unit_box_cloud(int dim, double h, double horizon_ratio = 3.5, double perturbation = 0.2,
                            int seed = 11) {
  Cloud c;
  c.h = h;
  c.delta = horizon_ratio * h;
  c.particles = pd_test::unit_box_particles(dim, h, perturbation, static_cast<unsigned>(seed));
  c.bonds = pd::find_bonds(c.particles, c.delta, pd::abi::find_influence("inv")->weight);
  c.full_ball.resize(c.particles.size());
  for (int p = 0; p < c.particles.size(); ++p) {
    const double* x = c.particles.position(p);
    c.full_ball[p] = true;
    for (int k = 0; k < dim; ++k) c.full_ball[p] = c.full_ball[p] && x[k] >= c.delta && x[k] <= 1 - c.delta;
  }
  return c;
}
inline Cloud unit_square_cloud(double h) { return unit_box_cloud(2, h); }

// Collocation with paper 001's space on the full-ball families, volumes elsewhere.
inline pd::Collocation paper001_collocation(const Cloud& c) {
  return pd::make_collocation(c.particles, c.bonds,
                              pd::obq_weights(c.particles, c.bonds, pd::paper001_space(2), c.full_ball));
}

}  // namespace obq_test

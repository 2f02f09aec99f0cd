// Test support: the particles of the unit square (dim 2) or cube (dim 3), lattice spacing h,
// each point moved by up to perturbation x h per axis (domain.perturbation, seeded).
#pragma once

#include "discretize/discretization.hpp"
#include "input/scene.hpp"

namespace pd_test {

inline pd::Particles unit_box_particles(int dim, double h, double perturbation, unsigned seed) {
  pd::Scene s;
  s.dim = dim;
  s.lo = {0, 0, 0};
  s.hi = {1, 1, 1};
  s.h = h;
  s.perturbation = perturbation;
  s.seed = seed;
  s.materials.resize(1);
  return pd::discretize(s);
}

}  // namespace pd_test

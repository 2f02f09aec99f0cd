// Dirichlet conditions of a scene, and the checks that the body is held: every
// cluster of particles joined by intact bonds must have its rigid-body modes removed.
#pragma once

#include "input/scene.hpp"
#include "particles.hpp"
#include "solve/dof_map.hpp"

namespace pd {

// The constrained dofs (fixed, prescribed and analytic-field conditions) with their
// values at full load. Throws SceneError naming the condition whose region is empty.
DofMap scene_constraints(const Scene& scene, const Particles& particles);

// Throws std::runtime_error naming the particles of a cluster (or the whole body) whose
// rigid translation or rotation the constraints leave free: dead loads cannot balance a
// free rigid mode, and the message beats a singular factorisation.
void check_held(const Particles& particles, const Bonds& bonds, const DofMap& dofs);

}  // namespace pd

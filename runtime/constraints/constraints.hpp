// Dirichlet conditions of a scene, and the checks that the body is held: every
// cluster of particles joined by intact bonds must have its rigid-body modes removed.
#pragma once

#include <vector>

#include "constraints/dof_map.hpp"
#include "input/scene.hpp"
#include "particles.hpp"

namespace pd {

// One constrained dof: the condition (index into scene.boundary) that sets it last, its
// kind, and its value at full load (velocity conditions: the velocity).
struct PrescribedDof {
  int dof;
  BoundaryCondition::Kind kind;
  double value;
  int condition;
};

// Every dof a fixed, displacement, field or velocity condition constrains, in the order
// the conditions first reach them. Two conditions may constrain the same component only
// when they agree (same value, both velocities or both displacements, same time
// function); otherwise SceneError names both (file:line: boundary[i]), the particle and
// the values. Throws SceneError naming the condition whose region is empty.
std::vector<PrescribedDof> prescribed_dofs(const Scene& scene, const Particles& particles);

// The constrained dofs (fixed, prescribed and analytic-field conditions) with their
// values at full load, as the static solver's DofMap. Throws SceneError naming the condition whose region is
// empty.
DofMap scene_constraints(const Scene& scene, const Particles& particles);

// Throws std::runtime_error naming the particles of a cluster (or the whole body) whose
// rigid translation or rotation the constraints leave free: dead loads cannot balance a
// free rigid mode, and the message beats a singular factorisation.
void check_held(const Particles& particles, const Bonds& bonds, const DofMap& dofs);
// The same before a static solve, where a body the scene leaves free is bad input: throws
// SceneError (exit 2), naming the missing `boundary` section when the scene has none.
void check_scene_holds_body(const Scene& scene, const Particles& particles, const Bonds& bonds,
                            const DofMap& dofs);

}  // namespace pd

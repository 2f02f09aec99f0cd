// Fictitious boundary layers (paper 003 section 3.3, eqs. 29-35; Madenci & Oterkus's book):
// particles outside the body whose displacements follow their mirror images inside it, so
// that a boundary particle's family is full and the condition is carried by the layer's
// displacements rather than by holding the body's own particles. The layer's particles
// are given (a scene region outside the body); this file builds the linear map from the
// body's displacements to theirs as multipoint constraints (TiedDof) for the DofMap
// (constraints/dof_map.hpp).
#pragma once

#include <array>
#include <functional>
#include <span>
#include <vector>

#include "discretize/tied_dof.hpp"
#include "particles.hpp"

namespace pd {

// The body's boundary plane: a point on it and the unit normal pointing out of the body,
// into the layer. A layer particle at x_f mirrors onto x = x_f - 2 ((x_f - p) . n) n, whose
// projection on the plane is x* = x_f - ((x_f - p) . n) n.
struct MirrorFace {
  std::array<double, 3> point{}, normal{};
};

struct LayerCondition {
  enum class Kind { displacement, traction } kind = Kind::displacement;
  MirrorFace face;
  // displacement (eqs. 29-31): the components held at U*(x*) follow u_f = 2 U*(x*) - u(x)
  // (odd mirror); the others follow u_f = u(x) (even mirror: a plane of symmetry, a roller).
  std::array<bool, 3> prescribed{};
  // U* at a point of the face, at full load (a load factor scales it). Linear in x for
  // the mirror to reproduce a homogeneous strain exactly.
  std::function<std::array<double, 3>(const double* x_star)> value;
  // traction (eqs. 32-35, 2D only): the traction vector sigma . n on the face, at full
  // load, and the 2D elastic constants (plane stress or plane strain): sigma_nn = M
  // eps_nn + lambda eps_tt, sigma_nt = 2 mu eps_nt.
  std::array<double, 3> traction{};
  double M = 0, lambda = 0, mu = 0;
};

// The ties of the layer's particles (`layer`, any order): one per component. `target` marks
// the particles a mirror image or a neighbour may be (not in this layer; a particle of
// another layer -- a corner -- is resolved by compose_ties). The traction variant
// extrapolates from the mirror image x along the normal with the normal gradient that
// eqs. 32-35 give: u_f = u(x) + d [ n eps_nn + t du_t/dn ], d = (x_f - x) . n, with the
// tangential derivatives from x's lattice neighbours x +- h t (h = V^(1/dim) of x; one-sided
// where one is missing). Both variants reproduce a linear displacement field exactly.
// Throws std::invalid_argument naming the particle when a mirror image or a neighbour is
// a target particle (a lattice not symmetric about the face), or the face lies inside
// the body.
std::vector<TiedDof> fictitious_layer_ties(const Particles& particles, std::span<const int> layer,
                                           std::span<const char> target, const LayerCondition& condition);

// Substitutes tied masters by their own ties until every master is untied (a corner
// particle of one layer mirrors into another layer, whose particle mirrors into the body:
// for linear ties the composition is again linear and reproduces a linear field). Throws
// std::invalid_argument on a cycle.
void compose_ties(std::vector<TiedDof>& ties, int n_dofs);

}  // namespace pd

namespace pd {

struct Scene;

// The ties of every `method: fictitious_layer` condition of the scene (none: empty).
// Throws SceneError naming the condition (file:line: boundary[i]) when its region is
// empty, overlaps another layer, or a particle has no mirror image.
std::vector<TiedDof> scene_layer_ties(const Scene& scene, const Particles& particles);

}  // namespace pd

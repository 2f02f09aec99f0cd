// The model a run solves: the law and influence, the particles, the bonds (cut by the
// pre-cracks), the per-material law parameters, the family checks and the dof map (the
// Dirichlet conditions, with their load path and motion in time), built once from
// a const Scene by build_model; the assembler is added by the driver once the solver
// plan has said whether it needs a matrix (attach_assembler), then the effects
// (attach_effects), which read the assembler. The static and dynamic drivers both start from it.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "assembly/assembler.hpp"
#include "assembly/collocation.hpp"
#include "assembly/force_operator.hpp"
#include "constraints/dof_map.hpp"
#include "discretize/family_quality.hpp"
#include "discretize/gauss_points.hpp"
#include "effects/effect.hpp"
#include "input/scene.hpp"
#include "kernel_abi.hpp"
#include "particles.hpp"

namespace pd {

class CriticalStretchDamage;
class Inertia;
class ViscousDamping;

struct Model {
  const abi::LawDescriptor* law = nullptr;
  const abi::InfluenceDescriptor* influence = nullptr;
  Particles particles;
  Bonds bonds;
  std::vector<std::vector<double>> params;  // per material, in law.param_names order
  FamilyQualityReport quality;
  double build_seconds = 0;  // build_model's time (the run's setup time starts with it)
  // The constrained dofs and their values at full load (constraints/constraints.hpp), with the
  // load path of a rotation and each dof's function of time (DofMap::apply_motion).
  DofMap dofs;
  long long bond_count = 0;           // each bond once (not per direction)
  int cut_by_cracks = 0;              // bonds the scene's pre-cracks cut, each once
  std::vector<std::string> warnings;  // the scene's and the set-up's (a crack that crosses no bond)
  // domain.quadrature: obq — the per-bond weights and collocation assembly (eq. 2.13 of
  // paper 001), and the log line that says how many families kept the volume rule.
  std::unique_ptr<Collocation> collocation;
  std::string collocation_description;
  // domain.gauss_points (paper 002 §3.3): the points, their MLS shape functions and the
  // Gauss families the assembler integrates over instead of the bonds.
  std::unique_ptr<GaussPoints> gauss_points;
  std::unique_ptr<ForceOperator> assembler;  // attach_assembler (declared after what it reads)
  AssemblerOptions assembler_options;        // the options it was built with
  // Static matrix-free runs with the short-horizon preconditioner (attach_short_horizon):
  // the same law on delta = ratio h, whose factorised stiffness preconditions the solve.
  Bonds short_bonds;
  std::unique_ptr<ForceOperator> approximation;
  // attach_effects: every effect the scene calls for, in the order the run log lists
  // them (loads, crack pressure, body forces, pre-cracks, damage evolution; a dynamic
  // run's inertia and viscous damping last). Declared last: they read the assemblers and bonds above.
  std::vector<std::unique_ptr<Effect>> effects;
  const CriticalStretchDamage* damage = nullptr;  // the damage effect's rule (null without `damage`)
  const Inertia* inertia = nullptr;  // dynamic runs: rho V (explicit) or the fictitious density (relaxation)
  const ViscousDamping* damping = nullptr;  // explicit dynamics with dynamics.damping > 0
};

// Throws std::invalid_argument on an unknown law or influence, std::runtime_error
// naming a particle without neighbours and SceneError naming a condition whose region is empty.
Model build_model(const Scene& scene);

// The assembler over the model's particles and bonds: the intact kernels (alpha folded
// to 1) unless a bond is cut or can break (`damage`), with a matrix pattern only when
// `matrix`. Returns the options it used.
AssemblerOptions attach_assembler(Model& model, const Scene& scene, bool matrix, int threads = 0);

// The short-horizon approximation (bonds within short_delta, negligible ones dropped,
// cut by the same cracks) for the matrix-free path's preconditioner. On a body of blocks
// each particle's own min(delta_i, preconditioner_ratio h_i) instead of short_delta.
void attach_short_horizon(Model& model, const Scene& scene, double short_delta);

// The scene's effects (model/model_effects.cpp), after attach_assembler (and
// attach_short_horizon when used). A dynamic scene's loads carry their time functions;
// its inertia (and damping) come last, from the stiffness row sums at the reference
// configuration (a temporary assembler with a matrix).
void attach_effects(Model& model, const Scene& scene);

}  // namespace pd

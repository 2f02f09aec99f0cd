// The model a run solves, built complete in two phases by one constructor and not
// added to afterwards:
//  1. DiscretizedBody: the law and influence, the particles, the bonds (cut by the
//     pre-cracks), the per-material law parameters, the family checks, the quadrature
//     (OBQ collocation or Gauss points) and the dof map (the Dirichlet conditions, with
//     their load path and motion in time) -- everything a solver plan reads;
//  2. Model: what the plan chose (ModelPlan) -- the assembler (with a matrix or
//     matrix-free), the short-horizon approximation for the preconditioner -- and then the
//     scene's effects, which read the assemblers and bonds.
// The drivers pass the planner (run/static_run.hpp: build_static_model; a dynamic run's
// plan is fixed: build_dynamic_model) and only read and step the result; the run's state that changes (u, v,
// the bonds' damage through the damage effect) is the run's.
#pragma once

#include <functional>
#include <memory>
#include <optional>
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

// Phase 1: the discretized body and its quadrature, from the scene alone.
struct DiscretizedBody {
  // Throws std::invalid_argument on an unknown law or influence, std::runtime_error
  // naming a particle without neighbours and SceneError naming a condition whose region is empty.
  explicit DiscretizedBody(const Scene& scene);

  const abi::LawDescriptor* law = nullptr;
  const abi::InfluenceDescriptor* influence = nullptr;
  Particles particles;
  Bonds bonds;
  std::vector<std::vector<double>> params;  // per material, in law.param_names order
  FamilyQualityReport quality;
  double build_seconds = 0;  // the model's build time, both phases (the run's setup time starts with it)
  // The constrained dofs and their values at full load (constraints/constraints.hpp), with the
  // load path of a rotation and each dof's function of time (DofMap::apply_motion).
  DofMap dofs;
  long long bond_count = 0;           // each bond once (not per direction)
  int cut_by_cracks = 0;              // bonds the scene's pre-cracks cut, each once
  std::vector<std::string> warnings;  // the scene's and the set-up's (a crack that crosses no bond)
  // domain.quadrature: obq -- the per-bond weights and collocation assembly (eq. 2.13 of
  // paper 001), and the log line that says how many families kept the volume rule.
  std::unique_ptr<Collocation> collocation;
  std::string collocation_description;
  // domain.gauss_points (paper 002 §3.3): the points, their MLS shape functions and the
  // Gauss families the assembler integrates over instead of the bonds.
  std::unique_ptr<GaussPoints> gauss_points;
};

// What a solver plan asks of phase 2.
struct ModelPlan {
  bool matrix = false;  // the assembler keeps a sparsity pattern (factorisation, PETSc's matrix)
  int threads = 0;      // the assembler's OpenMP threads (0: OpenMP's default)
  // The short-horizon approximation for the matrix-free path's preconditioner: the bonds
  // within this horizon (negligible ones dropped, cut by the same cracks); on a body of
  // blocks each particle's own min(delta_i, preconditioner_ratio h_i). With OBQ collocation
  // the approximation is the collocation tangent itself.
  std::optional<double> short_delta;
};

// Phase 2 on top of phase 1. Neither copied nor moved: the effects and assemblers hold
// references into the body (a prvalue, as build_model returns, is built in place).
struct Model : DiscretizedBody {
  using Planner = std::function<ModelPlan(const DiscretizedBody&)>;
  // Builds the body, asks `planner` what it needs, then builds that and the scene's effects.
  Model(const Scene& scene, const Planner& planner);
  Model(const Scene& scene, const ModelPlan& plan)
      : Model(scene, Planner([plan](const auto&) { return plan; })) {}
  Model(const Model&) = delete;
  Model& operator=(const Model&) = delete;

  // A law with memory: the committed per-bond history, [bonds * law.n_history] in bond order,
  // every bond at the law's initial values until commit_history; the assembler reads it
  // (AssemblerOptions::history). Empty for a law without history.
  std::vector<double> bond_history;
  // Likewise per particle, [particles * law.n_particle_history] (AssemblerOptions::particle_history).
  std::vector<double> particle_history;
  // The duration of the current step, which a rate-dependent law reads
  // (LawDescriptor::uses_time_step, AssemblerOptions::time_step): the driver sets it for
  // each step (explicit dynamics: dt; the static driver: each increment's share of
  // solver.duration). 0 until then, the instantaneous response, and again after the last
  // commit: the committed state read at a zero duration gives the converged forces, which
  // the outputs report (at the step's duration the law would relax one step more).
  double step_duration = 0.0;
  bool has_history() const { return !bond_history.empty() || !particle_history.empty(); }
  // Commits a converged step: the history becomes the law's update at displacement u
  // (FamilyAssembler::updated_history). Call only with a converged solution: a failed or
  // trial state must never reach the history. No-op for a law without history.
  void commit_history(const double* u);

  std::unique_ptr<ForceOperator> assembler;  // the intact kernels unless a bond is cut or can break
  AssemblerOptions assembler_options;        // the options it was built with
  // ModelPlan::short_delta: the same law on a shorter horizon, whose factorised stiffness
  // preconditions the matrix-free solve (empty bonds and null without it).
  Bonds short_bonds;
  std::unique_ptr<ForceOperator> approximation;
  // Every effect the scene calls for, in the order the run log lists them (loads, crack
  // pressure, body forces, pre-cracks, damage evolution; a dynamic run's inertia and
  // viscous damping last; model/model_effects.cpp). Declared last: they read the assemblers and bonds above.
  std::vector<std::unique_ptr<Effect>> effects;
  const CriticalStretchDamage* damage = nullptr;  // the damage effect's rule (null without `damage`)
  const Inertia* inertia = nullptr;  // dynamic runs: rho V (explicit) or the fictitious density (relaxation)
  const ViscousDamping* damping = nullptr;  // explicit dynamics with dynamics.damping > 0

 private:
  void build_assembler(const Scene& scene, const ModelPlan& plan);
  void build_short_horizon(const Scene& scene, double short_delta);
  void build_effects(const Scene& scene);  // model/model_effects.cpp
};

// The model with a fixed plan (the tests' and tools' shorthand; the drivers plan).
inline Model build_model(const Scene& scene, const ModelPlan& plan = {}) { return Model(scene, plan); }
}  // namespace pd

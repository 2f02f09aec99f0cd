// The optional `dynamics` and `damage` sections of a scene (docs/scene_format.md):
// plain data with the documented defaults, read by read_dynamics / read_damage.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "input/enum_names.hpp"
#include "input/region.hpp"

namespace pd {

struct YamlAt;

// Initial displacement and velocity of the particles of a region, optionally shaped by
// a Gaussian profile exp(-((x_axis - center) / width)^2 / 2) along one axis, plus a
// displacement field linear in position, u += gradient (x - origin): a homogeneous strain
// state such as paper 003's uniaxial-strain start (section 5.1).
struct InitialCondition {
  Region region;
  Point displacement{}, velocity{};
  bool has_gradient = false;
  std::array<Point, 3> gradient{};  // gradient[i][j] = du_i/dx_j
  Point origin{};
  bool gaussian = false;
  int axis = 0;
  double center = 0, width = 0;
  std::string where;  // "file:line: dynamics.initial[i]"
};

// explicit (velocity Verlet) | relaxation (adaptive dynamic relaxation)
enum class DynamicsMethod { explicit_verlet, relaxation };
template <>
struct enum_names<DynamicsMethod> {
  static constexpr std::array<EnumName<DynamicsMethod>, 2> table{
      {{DynamicsMethod::explicit_verlet, "explicit"}, {DynamicsMethod::relaxation, "relaxation"}}};
};

struct DynamicsSpec {
  DynamicsMethod method = DynamicsMethod::explicit_verlet;
  int steps = 0;                // explicit: time steps (required); relaxation: the iteration limit
  double dt = 0;                // explicit: a fixed step; 0: the estimate times safety_factor
  double safety_factor = 0.8;   // fraction of the estimated stable step
  double damping = 0;           // explicit: mass-proportional viscous damping c (a = f/m - c v)
  double tolerance = 1e-8;      // relaxation: |r_free| <= tolerance * reference force
  int output_every = 0;         // time-series row every N steps (0: steps / 100, at least 1)
  int snapshot_every = 0;       // .vtu snapshot every N steps, with a .pvd collection (0: none)
  int checkpoint_every = 0;     // checkpoint every N steps (0: none)
  double progress_seconds = 2;  // progress line at most this often (0: none)
  int threads = 0;              // OpenMP threads of the force loop (0: OpenMP's default)
  std::string restart;          // a checkpoint to resume from ("" : start at t = 0)
  std::vector<InitialCondition> initial;
};

struct DamageSpec {
  double critical_stretch = 0;     // given directly, or ...
  double fracture_energy = 0;      // ... G0, converted with the PMB formula of the dimension
  bool tension_only = true;        // bonds break in tension only (s > s0); false: |s| > s0
  int max_resolves = 50;           // implicit runs: re-solves of one load step after bonds broke
  std::string max_resolves_where;  // "file:line: damage.max_resolves" when given
  std::string where;               // "file:line: damage"
};

DynamicsSpec read_dynamics(const YamlAt& at, int dim);
DamageSpec read_damage(const YamlAt& at);

}  // namespace pd

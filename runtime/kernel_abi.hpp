// The kernel ABI: the only contract between generated law kernels and the runtime.
//
// A law is evaluated one *family* at a time: the center particle (local index 0)
// and its L neighbours (local indices 1..L). Bond k (0-based, k < L) joins the
// center to local particle k+1.
//
// Sign and volume convention (see docs/conventions.md): the family of particle B
// adds V_B V_A t_B<A> to the nodal force of B and subtracts it from A, so forces
// are nodal forces (not densities) and momentum is conserved bond by bond.
// The tangent is the exact derivative of those nodal forces with respect to the
// deformed positions y of the family's particles: d f / d y.  (The stiffness
// matrix a solver wants is its negative.)
#pragma once

#include <cstddef>
#include <span>
#include <string_view>

namespace pd::abi {

// Inputs of one family. Arrays are bond-major: component c of bond k of a vector
// quantity is at [k*dim + c].
struct Family {
  int n_bonds = 0;                // L
  const double* xi = nullptr;     // [L*dim] reference bonds  x_k - x_0
  const double* Y = nullptr;      // [L*dim] deformed bonds   y_k - y_0
  const double* w = nullptr;      // [L] influence weights
  const double* alpha = nullptr;  // [L] bond factors, 1 intact, 0 broken (unused by the intact variant)
  const double* V = nullptr;      // [L] neighbour volumes
  double V0 = 0.0;                // center volume
  double delta = 0.0;             // horizon of the center particle
  // The duration of the current step (physical time), read by a rate-dependent law's force and
  // update (LawDescriptor::uses_time_step): the time step of explicit dynamics, or a static
  // increment's share of solver.duration (NewtonSettings::duration). 0 for a law that does not
  // read it.
  double time_step = 0.0;
  const double* params = nullptr;  // [n_params] material parameters, in LawDescriptor::param_names order
  // [L*n_params] the neighbours' material parameters, bond-major (bond k's at [k*n_params]),
  // read by a law with pair parameters (LawDescriptor::uses_pair_params). Null: every
  // neighbour has the center's (a body of one material); always valid.
  const double* nbr_params = nullptr;
  const double* moments = nullptr;  // [n_moments] output of the moments kernel (setup)
  // [L * LawDescriptor::scratch_per_bond] working memory the kernels may overwrite (per-bond
  // values one loop computes and a later loop reads); the caller owns it, one per thread.
  // May be null when the law's scratch_per_bond is 0.
  double* scratch = nullptr;
  // Surface correction (paper 003 eq. 19; assembly/surface_correction.hpp), per bond,
  // null meaning 1 for every bond. force_factor multiplies the bond's force state (and
  // so its tangent and JVP); dilatation_factor multiplies the bond's term in the law's
  // dilatation sum (laws that declare one: LawDescriptor::has_dilatation_sum).
  const double* dilatation_factor = nullptr;  // [L]
  const double* force_factor = nullptr;       // [L]
  // History (a law with memory, LawDescriptor::n_history > 0): the committed per-bond
  // internal variables at the start of the step, [L*n_history] bond-major (bond k's at
  // [k*n_history]). The kernels read them and never write them: the residual, tangent and
  // JVP are those of the incremental problem with this history held fixed, and the update
  // kernel writes the values at the end of the step into a separate array, which the
  // runtime commits only once the step has converged. Null: every bond at the law's
  // initial values (LawDescriptor::history_initial), a virgin body.
  const double* history = nullptr;
  // The center particle's committed internal variables (LawDescriptor::n_particle_history >
  // 0), [n_particle_history]: read-only, as `history`. Null: the law's initial values
  // (LawDescriptor::particle_history_initial).
  const double* particle_history = nullptr;
};

// Factored tangent of one family. With T_ik = d t_i / d Y_k (bond i's force state
// against bond k's deformed vector):
//     T_ik = delta_ik * direct_i + sum_s left_i[s] (outer) right_k[s]
// direct_i = partial t_i / partial Y_i (states held fixed), left_i[s] = partial t_i /
// partial S_s, right_k[s] = total d S_s / d Y_k (through earlier states too).
// The center block follows from translation invariance: d/dy_0 = -sum_k d/dY_k.
struct TangentFactors {
  double* direct = nullptr;  // [L*dim*dim] row-major per bond
  double* left = nullptr;    // [L*n_states*dim]
  double* right = nullptr;   // [L*n_states*dim]
};

// Setup: horizon sums that do not depend on the deformation (weighted volume,
// shape tensor, ...). Recompute when alpha changes.
using MomentsKernel = void (*)(const Family&, double* moments);
// Nodal forces of the family, [(L+1)*dim], overwritten.
using ResidualKernel = void (*)(const Family&, double* forces);
// Tangent factors; also writes the nodal forces when `forces` is not null.
using TangentKernel = void (*)(const Family&, double* forces, const TangentFactors& factors);
// Directional derivative of the nodal forces along a local increment dy of the
// positions of particles 0..L: df = (d f / d y) dy. Cost linear in L.
using JvpKernel = void (*)(const Family&, const double* dy, double* df);
// The derivative of the nodal forces with respect to each material parameter, dense:
// dfdp [n_params * (L+1)*dim], parameter-major (parameter i's nodal vector, laid out as
// `forces`, at [i*(L+1)*dim]), overwritten. The parameter is varied for the whole family
// at once (the center's value and every neighbour's, so a pair mean of equal values moves
// with it), the deformation and the committed history held fixed: for a law with memory
// it is the sensitivity of the incremental residual. A body of one material (or a law
// without pair parameters, whose family reads only its center's values) gets the exact
// d(forces)/d(material parameter) by summing these over the families of that material.
using SensitivityKernel = void (*)(const Family&, double* dfdp);
// The family's dense local matrix M = d f / d y, (L+1)*dim square, row-major, from the
// factors of the tangent kernel: the formula of runtime/local_matrix.hpp, emitted per law
// with the factor entries that are structurally zero for that law left out of every sum
// (correspondence's right factors dN_ij/dY have one nonzero component, its direct factor
// none). Writes every entry. Null for a hand-written law: use pd::form_local_matrix.
using FormKernel = void (*)(const Family&, const TangentFactors& factors, double* M);
// Strain-energy density W of the center particle; the family's energy is V0*W
// and forces = -d(V0 W)/dy. Null when the law has no energy.
using EnergyKernel = double (*)(const Family&);
// Per-particle derived quantities for output (dilatation, strain, ...).
using OutputsKernel = void (*)(const Family&, double* outputs);
// The history at the end of the step from the committed values (Family::history,
// Family::particle_history) and the current deformation: the law's update (plastic return
// map, viscous update). Writes history_out [L*n_history] bond-major and
// particle_history_out [n_particle_history] (each may be null when its count is 0). Null
// when the law has no history.
using UpdateKernel = void (*)(const Family&, double* history_out, double* particle_history_out);

struct OpCounts {
  int adds = 0, muls = 0, divs = 0, calls = 0;  // calls: sqrt, pow, exp, log, ...
};

struct KernelVariant {
  MomentsKernel moments = nullptr;
  ResidualKernel residual = nullptr;
  TangentKernel tangent = nullptr;
  JvpKernel jvp = nullptr;
  SensitivityKernel sensitivity = nullptr;      // may be null (hand-written laws)
  FormKernel form = nullptr;                    // may be null (hand-written laws)
  EnergyKernel energy = nullptr;                // may be null
  OutputsKernel outputs = nullptr;              // may be null when n_outputs == 0
  UpdateKernel update = nullptr;                // null when the law has no history
  OpCounts residual_ops, tangent_ops, jvp_ops;  // per bond-loop body, as emitted
  OpCounts sensitivity_ops;
};

// The bond monomials xi^b / |xi|^inverse_r_power with lowest_degree <= |b| <= highest_degree
// (pd::monomials, runtime/discretize/reproducing_space.hpp): one group of a law's
// reproducing space, LawDescriptor::reproducing_groups.
struct MonomialGroup {
  int lowest_degree = 0;
  int highest_degree = 0;
  int inverse_r_power = 0;
};

// One term c (r/delta)^k of a radial profile (LawDescriptor::kernel_terms).
struct RadialTerm {
  double coefficient = 1.0;
  int power = 0;
};

// The values a material parameter may take (pdgen ParamRange, in the same order).
enum class ParamRange : int { any = 0, positive = 1, non_negative = 2, unit_interval = 3 };

struct LawDescriptor {
  const char* name = "";
  const char* summary = "";
  int dim = 0;
  int n_params = 0;
  const char* const* param_names = nullptr;
  // [n_params] the value the automatic law tests give each parameter; NaN where the
  // law declares none (elastic names are derived from the material instead).
  const double* param_test_values = nullptr;
  // [n_params] the range each parameter's value must lie in; the scene reader refuses a
  // material outside it. Null: every parameter may take any value.
  const ParamRange* param_ranges = nullptr;
  int n_moments = 0;
  int n_states = 0;  // scalar state components (the s index of TangentFactors)
  int n_outputs = 0;
  const char* const* output_names = nullptr;
  // Per-bond internal variables (Family::history, UpdateKernel): their names and the values
  // a virgin bond has; 0: an elastic law, a function of the current deformation alone.
  int n_history = 0;
  const char* const* history_names = nullptr;
  const double* history_initial = nullptr;
  // Per-particle internal variables (Family::particle_history), likewise; 0: none.
  int n_particle_history = 0;
  const char* const* particle_history_names = nullptr;
  const double* particle_history_initial = nullptr;
  int scratch_per_bond = 0;  // doubles per bond of Family::scratch any kernel of the law uses
  // The law claims sum_k Y_k x t_k = 0 (angular momentum balance) for every deformation.
  bool balances_angular_momentum = false;
  // Some bond quantity is a pair mean of a material parameter (Family::nbr_params). With
  // parameters that differ across a family the tangent is in general not symmetric
  // (a bond's coefficient multiplies a state of one of its two families only).
  bool uses_pair_params = false;
  // The Poisson ratio the law has whatever its parameters (bond-based: 1/4), in its 3D
  // or plane-strain form; false: any ratio the material gives.
  bool has_fixed_poisson_ratio = false;
  double poisson_ratio = 0.0;
  // The law marks a dilatation sum (pdgen Law::dilatation_sum) that reads
  // Family::dilatation_factor; false: only Family::force_factor acts.
  bool has_dilatation_sum = false;
  // The law reads Family::time_step (pdgen Law::time_step): its answer depends on how long a
  // step lasts, so it runs only where the scene gives physical time (explicit dynamics).
  bool uses_time_step = false;
  // The force never reads Family::w (bond-based laws, a kernel built into the law): the
  // scene's influence function does not change the law's forces.
  bool ignores_influence = false;
  // The law's reproducing space (domain.obq_space: law; runtime/discretize/law_space.hpp):
  // the groups of bond monomials that its horizon sums integrate under a homogeneous
  // deformation, each times the radial weight the sums carry. Declared in the law's source
  // (pdgen Law::reproducing_terms, docs/laws.md) and copied here in declaration order;
  // 0 groups: the law declares none, and obq_space: law refuses it.
  int n_reproducing_groups = 0;
  const MonomialGroup* reproducing_groups = nullptr;
  // The radial weight of those sums when the law ignores the influence (a kernel built into
  // the law: bond-based micromoduli, paper 001's K = 1/r): sum c (r/delta)^k over
  // kernel_terms, up to a constant factor, and a phrase for it. Declared by pdgen
  // Law::built_in_kernel; null kernel_description: none declared. A law that reads the
  // influence (ignores_influence false) has none: its sums carry the scene's w.
  int n_kernel_terms = 0;
  const RadialTerm* kernel_terms = nullptr;
  const char* kernel_description = nullptr;
  KernelVariant damaged;  // reads alpha per bond
  KernelVariant intact;   // alpha folded to 1: use when no bond of the body is broken
};

// The pair means a law's pair parameters use (paper 001 eq. 2.4 and the arithmetic one).
// Equal values give that value exactly, so a body of one material is unchanged to the bit.
// A law with memory: it carries per-bond or per-particle internal variables.
inline bool has_history(const LawDescriptor& d) { return d.n_history > 0 || d.n_particle_history > 0; }

inline double harmonic_mean(double a, double b) { return a == b ? a : 2.0 * a * b / (a + b); }
inline double arithmetic_mean(double a, double b) { return a == b ? a : 0.5 * (a + b); }

// Influence function w(r, delta), generated from laws/influence.cpp.
struct InfluenceDescriptor {
  const char* name = "";
  const char* formula = "";
  double (*weight)(double r, double delta) = nullptr;
};

// The tables, generated into law_table.cpp.
std::span<const LawDescriptor> all_laws();
std::span<const InfluenceDescriptor> all_influences();
const LawDescriptor* find_law(std::string_view name);
const InfluenceDescriptor* find_influence(std::string_view name);

}  // namespace pd::abi

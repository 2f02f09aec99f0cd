// The law model: what a constitutive law declares for one family.
//
// A law is written for the center particle 0 and its L bonds (L known only at run
// time). Expressions are built from per-bond inputs (xi, Y, w, alpha, V), per-particle
// inputs (V0, delta, named parameters) and horizon sums. A sum whose body depends on
// Y (directly or through an earlier sum) is a *state*; otherwise it is a *moment*,
// computed once at setup. The force state is a per-bond vector.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "pdgen/tensor.hpp"

namespace pdgen {

// One scalar horizon sum S = sum over bonds of `body`.
struct SumDef {
  std::string name;  // C identifier, unique in the law
  Expr symbol;       // the per-particle symbol standing for S
  Expr body;         // per-bond expression
  bool is_state = false;
  int level = 0;  // 1 + the highest level among the sums its body uses
};

struct OutputDef {
  std::string name;
  Expr value;  // per-particle expression
};

// An internal variable (Law::bond_history, Law::particle_history): `committed` is the value
// at the start of the step, an input the kernels read (Family::history per bond,
// Family::particle_history for the center particle); `updated` is its value after the step,
// a function of the committed values and the current deformation, which the update kernel
// writes and the runtime commits once a step has converged.
struct HistoryDef {
  std::string name;  // C identifier, unique in the law (bond and particle variables together)
  double initial = 0.0;
  Expr committed;  // input symbol: per bond, or per particle (the family's center)
  Expr updated;    // same kind of expression (the committed value until Law::update sets it)
  bool has_update = false;
};

// The values a material parameter may take (Law::param). The runtime refuses a scene whose
// material gives one outside them, naming the key, before anything runs (a yield stress of
// 0 would divide by zero in the return map; a negative relaxation time grows without bound).
enum class ParamRange {
  any,
  positive,       // > 0: a yield stress, a relaxation time
  non_negative,   // >= 0: a hardening modulus
  unit_interval,  // in [0, 1]: a viscous weight
};

// How a bond's pair parameter p_ij is formed from its two particles' values; each
// satisfies p(z, z) = p(z) (paper 001 after eq. 2.3).
enum class PairMean {
  harmonic,    // 2 / p_ij = 1 / p_i + 1 / p_j (paper 001 eq. 2.4)
  arithmetic,  // p_ij = (p_i + p_j) / 2
};

// A per-bond parameter: the mean of the center's and the neighbour's value of the
// material parameter `param` (an index into Law::param_names()).
struct PairParamDef {
  Expr symbol;  // a per-bond input symbol
  int param = 0;
  PairMean mean = PairMean::harmonic;
};

// Bond monomials xi^b / |xi|^inverse_r_power, lowest_degree <= |b| <= highest_degree: a
// group of a law's reproducing space (Law::reproducing_terms).
struct MonomialGroupDef {
  int lowest_degree = 0, highest_degree = 0, inverse_r_power = 0;
};

// One term c (r/delta)^k of a built-in radial kernel (Law::built_in_kernel).
struct RadialTermDef {
  double coefficient = 1.0;
  int power = 0;
};

class Law {
 public:
  Law(std::string name, int dim, std::string summary);

  const std::string& name() const { return name_; }
  const std::string& summary() const { return summary_; }
  int dim() const { return dim_; }

  // Inputs. A parameter named like an elastic constant (E, nu, K, G, mu, lambda,
  // kappa2) is derived from the scene's material; any other needs a value in the
  // material's parameters, and `test_value` is the value the automatic law tests
  // (patch test, check-law) give it.
  Expr param(const std::string& name);
  Expr param(const std::string& name, double test_value);
  // ... whose values are restricted to `range` (the test value must lie in it).
  Expr param(const std::string& name, double test_value, ParamRange range);
  // The bond's pair value of parameter `name` (declared as by param(name) if it is not
  // yet): the mean of the center's and the neighbour's value (Family::nbr_params), so a
  // bond across a material interface sees one value from both of its families. Where the
  // runtime gives no neighbour parameters (a body of one material) it is the center's.
  Expr pair_param(const std::string& name, PairMean mean);
  const Vec& xi() const { return xi_; }
  const Vec& Y() const { return Y_; }
  Expr w() const { return w_; }
  Expr alpha() const { return alpha_; }
  Expr V() const { return V_; }
  Expr V0() const { return V0_; }
  Expr delta() const { return delta_; }
  // The duration of the current step (Family::time_step): the time a rate-dependent law's
  // update integrates over (a viscous back-extension). A law that reads it is marked
  // LawDescriptor::uses_time_step, and the runtime refuses it in a scene that gives no time.
  Expr time_step() {
    reads_time_step_ = true;
    return time_step_;
  }
  Expr time_step_symbol() const { return time_step_; }
  bool reads_time_step() const { return reads_time_step_; }
  // Surface correction (paper 003 eq. 19, runtime/assembly/surface_correction.hpp):
  // per-bond factors the runtime passes in abi::Family (null: 1). The force factor
  // multiplies every bond's force state (the builders apply it; a law does not use it).
  // The dilatation factor multiplies the bond's term in the sum declared by
  // dilatation_sum: a law that has a dilatation marks it that way.
  Expr dilatation_factor() const { return dilatation_factor_; }
  Expr force_factor() const { return force_factor_; }
  // |Y| regularised as sqrt(Y.Y + (1e-8 |xi|)^2): equal to |Y| to rounding for every
  // bond longer than about 1e-8 |xi|, and finite, with a finite derivative, when a
  // deformed bond collapses to zero length (where Y/|Y| would be 0/0). Use it rather
  // than norm(Y()) wherever the law divides by the deformed length.
  Expr deformed_length() const;

  // History (laws with memory). A per-bond internal variable with its initial value; the
  // returned expression is its committed value at the start of the step. The law writes
  // the force from the committed values and the current deformation (the return map of a
  // plastic law, a time-discrete viscous update), and `update` gives the variable's value
  // at the end of the step. The kernels' tangent is then the algorithmic (consistent)
  // tangent of the incremental problem: the committed values are inputs, held fixed.
  Expr bond_history(const std::string& name, double initial);
  // A per-particle internal variable (an equivalent plastic strain, a hardening variable):
  // one value for the family's center. Its update is a per-particle expression: per-bond
  // quantities reach it only through horizon sums.
  Expr particle_history(const std::string& name, double initial);
  void update(Expr committed, Expr updated);
  const std::vector<HistoryDef>& history() const { return history_; }  // per bond
  const std::vector<HistoryDef>& particle_history() const { return particle_history_; }
  bool has_history() const { return !history_.empty() || !particle_history_.empty(); }

  // Horizon sums. Names must be C identifiers; vector and matrix sums get one
  // scalar sum per component, named name_i or name_i_j.
  Expr sum(const std::string& name, Expr body);
  Vec sum(const std::string& name, const Vec& body);
  Mat sum(const std::string& name, const Mat& body);
  // The law's dilatation: a horizon sum whose every term is scaled by the bond's
  // dilatation_factor() (the surface correction of the dilatation term; 1 unless the
  // scene asks for domain.surface_correction). At most one per law; it is also the law's
  // output "dilatation", which the surface correction reads.
  Expr dilatation_sum(const std::string& name, Expr body);
  bool has_dilatation_sum() const { return has_dilatation_sum_; }
  // Whether the force reads w (directly or through a horizon sum). Bond-based laws and
  // laws with a kernel built in (paper 001's lps_paper_*) do not: the scene's influence
  // function then leaves their forces unchanged, and the runtime says so.
  bool reads_influence() const;

  void force(const Vec& t);
  bool has_force() const { return force_.dim() == dim_; }
  void energy(Expr W) {
    energy_ = W;
    has_energy_ = true;
  }
  void output(const std::string& name, Expr value) { outputs_.push_back({name, value}); }
  // Claims: checked by the automatic law tests and `pd check-law`.
  // The force state conserves angular momentum: sum_k Y_k x t_k = 0 for every
  // deformation (true when every t_k is parallel to Y_k: bond-based and ordinary
  // state-based laws).
  void claim_angular_momentum_balance() { balances_angular_momentum_ = true; }
  // The law's response has this Poisson ratio whatever the parameters (bond-based
  // laws: 1/4 in 3D and plane strain; plane stress maps to 1/3 through the equivalent
  // material). The runtime warns when a scene's material differs.
  void fixed_poisson_ratio(double nu);
  // The law's reproducing space for OBQ weights (domain.obq_space: law, runtime/discretize/
  // law_space.hpp): its horizon sums, linearised for a homogeneous deformation u = eps x,
  // and the sums of its force state t and of t (x) xi (force and stress of the family),
  // integrate the radial weight times xi^b / |xi|^inverse_r_power with lowest_degree <= |b|
  // <= highest_degree. Called once per group; the order is the space's. Declared, not
  // derived: the space rests on the linearisation and on cancellations the expression graph
  // does not show (docs/laws.md). The radial weight is derived: the scene's influence when
  // the force reads w, else the built_in_kernel the law declares.
  void reproducing_terms(int lowest_degree, int highest_degree, int inverse_r_power);
  // The radial weight a law that never reads w has built in (bond-based micromodulus c(r),
  // paper 001's K = 1/r): c(r) proportional to sum c_k (r/delta)^k, described in a phrase
  // ("micromodulus 1 - r/delta"). Only for a law whose force does not read w (pdgen refuses
  // it otherwise) and needed by one that declares reproducing_terms.
  void built_in_kernel(std::string description, std::vector<RadialTermDef> profile);

  // Read by the kernel builders.
  const std::vector<std::string>& param_names() const { return param_names_; }
  const std::vector<Expr>& params() const { return params_; }
  const std::vector<double>& param_test_values() const { return param_test_values_; }  // NaN: none declared
  const std::vector<ParamRange>& param_ranges() const { return param_ranges_; }
  const std::vector<PairParamDef>& pair_params() const { return pair_params_; }
  bool balances_angular_momentum() const { return balances_angular_momentum_; }
  bool has_fixed_poisson_ratio() const { return has_fixed_poisson_ratio_; }
  double poisson_ratio() const { return poisson_ratio_; }
  const std::vector<MonomialGroupDef>& reproducing_groups() const { return reproducing_groups_; }
  bool has_built_in_kernel() const { return has_built_in_kernel_; }
  const std::string& kernel_description() const { return kernel_description_; }
  const std::vector<RadialTermDef>& kernel_profile() const { return kernel_profile_; }
  const std::vector<SumDef>& sums() const { return sums_; }
  const Vec& force_state() const { return force_; }
  bool has_energy() const { return has_energy_; }
  Expr energy_density() const { return energy_; }
  const std::vector<OutputDef>& outputs() const { return outputs_; }
  // The law with alpha replaced by 1 everywhere: the intact-bond variant.
  Law with_alpha_folded() const;

 private:
  void check_new_history(const std::string& name, double initial) const;

  std::string name_, summary_;
  int dim_;
  Vec xi_, Y_;
  Expr w_, alpha_, V_, V0_, delta_, time_step_, dilatation_factor_, force_factor_;
  bool reads_time_step_ = false;
  bool has_dilatation_sum_ = false;
  std::vector<std::string> param_names_;
  std::vector<Expr> params_;
  std::vector<double> param_test_values_;
  std::vector<ParamRange> param_ranges_;
  std::vector<PairParamDef> pair_params_;
  bool balances_angular_momentum_ = false;
  bool has_fixed_poisson_ratio_ = false;
  double poisson_ratio_ = 0.0;
  std::vector<MonomialGroupDef> reproducing_groups_;
  bool has_built_in_kernel_ = false;
  std::string kernel_description_;
  std::vector<RadialTermDef> kernel_profile_;
  std::vector<SumDef> sums_;
  Vec force_;
  Expr energy_;
  bool has_energy_ = false;
  std::vector<OutputDef> outputs_;
  std::vector<HistoryDef> history_;
  std::vector<HistoryDef> particle_history_;
};

// An influence function w(r, delta).
struct InfluenceDef {
  std::string file_stem, name, formula;
  std::function<Expr(Expr r, Expr delta)> weight;
};

// Registration, used through the macros below: each law file registers its laws
// under its file stem, which names the generated file pair.
struct LawEntry {
  std::string file_stem;
  std::string source;  // the law file's path as compiled (__FILE__), for error messages
  std::function<Law()> build;
};
std::vector<LawEntry>& law_registry();
// The name given to the most recently constructed Law: names the law in the error
// of a builder that throws before returning it (pdgen's messages).
std::string& law_under_construction();
std::vector<InfluenceDef>& influence_registry();
std::string file_stem(const char* path);

struct LawRegistrar {
  LawRegistrar(const char* file, std::function<Law()> build) {
    law_registry().push_back({file_stem(file), file, std::move(build)});
  }
};
struct InfluenceRegistrar {
  InfluenceRegistrar(const char* file, std::string name, std::string formula,
                     std::function<Expr(Expr, Expr)> w) {
    influence_registry().push_back({file_stem(file), std::move(name), std::move(formula), std::move(w)});
  }
};

}  // namespace pdgen

#define PDGEN_CONCAT2(a, b) a##b
#define PDGEN_CONCAT(a, b) PDGEN_CONCAT2(a, b)
// PDGEN_LAW(fn) { Law law(...); ...; return law; } registers a law builder.
#define PDGEN_LAW(fn)                                                             \
  static ::pdgen::Law fn();                                                       \
  static const ::pdgen::LawRegistrar PDGEN_CONCAT(fn, _registrar){__FILE__, &fn}; \
  static ::pdgen::Law fn()
// PDGEN_INFLUENCE(name, "formula") { return expression of r and delta; }
#define PDGEN_INFLUENCE(name, formula)                                                       \
  static ::pdgen::Expr PDGEN_CONCAT(influence_, name)(::pdgen::Expr r, ::pdgen::Expr delta); \
  static const ::pdgen::InfluenceRegistrar PDGEN_CONCAT(name, _influence_registrar){         \
      __FILE__, #name, formula, &PDGEN_CONCAT(influence_, name)};                            \
  static ::pdgen::Expr PDGEN_CONCAT(influence_, name)([[maybe_unused]] ::pdgen::Expr r,      \
                                                      [[maybe_unused]] ::pdgen::Expr delta)

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
  int level = 0;     // 1 + the highest level among the sums its body uses
};

struct OutputDef {
  std::string name;
  Expr value;  // per-particle expression
};

class Law {
 public:
  Law(std::string name, int dim, std::string summary);

  const std::string& name() const { return name_; }
  const std::string& summary() const { return summary_; }
  int dim() const { return dim_; }

  // Inputs.
  Expr param(const std::string& name);
  const Vec& xi() const { return xi_; }
  const Vec& Y() const { return Y_; }
  Expr w() const { return w_; }
  Expr alpha() const { return alpha_; }
  Expr V() const { return V_; }
  Expr V0() const { return V0_; }
  Expr delta() const { return delta_; }
  // |Y| regularised as sqrt(Y.Y + (1e-8 |xi|)^2): equal to |Y| to rounding for every
  // bond longer than about 1e-8 |xi|, and finite, with a finite derivative, when a
  // deformed bond collapses to zero length (where Y/|Y| would be 0/0). Use it rather
  // than norm(Y()) wherever the law divides by the deformed length.
  Expr deformed_length() const;

  // Horizon sums. Names must be C identifiers; vector and matrix sums get one
  // scalar sum per component, named name_i or name_i_j.
  Expr sum(const std::string& name, Expr body);
  Vec sum(const std::string& name, const Vec& body);
  Mat sum(const std::string& name, const Mat& body);

  void force(const Vec& t);
  bool has_force() const { return force_.dim() == dim_; }
  void energy(Expr W) { energy_ = W; has_energy_ = true; }
  void output(const std::string& name, Expr value) { outputs_.push_back({name, value}); }

  // Read by the kernel builders.
  const std::vector<std::string>& param_names() const { return param_names_; }
  const std::vector<Expr>& params() const { return params_; }
  const std::vector<SumDef>& sums() const { return sums_; }
  const Vec& force_state() const { return force_; }
  bool has_energy() const { return has_energy_; }
  Expr energy_density() const { return energy_; }
  const std::vector<OutputDef>& outputs() const { return outputs_; }
  bool is_bond_input(int symbol) const;
  // The law with alpha replaced by 1 everywhere: the intact-bond variant.
  Law with_alpha_folded() const;

 private:
  std::string name_, summary_;
  int dim_;
  Vec xi_, Y_;
  Expr w_, alpha_, V_, V0_, delta_;
  std::vector<std::string> param_names_;
  std::vector<Expr> params_;
  std::vector<SumDef> sums_;
  Vec force_;
  Expr energy_;
  bool has_energy_ = false;
  std::vector<OutputDef> outputs_;
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
  InfluenceRegistrar(const char* file, std::string name, std::string formula, std::function<Expr(Expr, Expr)> w) {
    influence_registry().push_back({file_stem(file), std::move(name), std::move(formula), std::move(w)});
  }
};

}  // namespace pdgen

#define PDGEN_CONCAT2(a, b) a##b
#define PDGEN_CONCAT(a, b) PDGEN_CONCAT2(a, b)
// PDGEN_LAW(fn) { Law law(...); ...; return law; } registers a law builder.
#define PDGEN_LAW(fn)                                                                 \
  static ::pdgen::Law fn();                                                           \
  static const ::pdgen::LawRegistrar PDGEN_CONCAT(fn, _registrar){__FILE__, &fn};     \
  static ::pdgen::Law fn()
// PDGEN_INFLUENCE(name, "formula") { return expression of r and delta; }
#define PDGEN_INFLUENCE(name, formula)                                                          \
  static ::pdgen::Expr PDGEN_CONCAT(influence_, name)(::pdgen::Expr r, ::pdgen::Expr delta);   \
  static const ::pdgen::InfluenceRegistrar PDGEN_CONCAT(name, _influence_registrar){            \
      __FILE__, #name, formula, &PDGEN_CONCAT(influence_, name)};                                         \
  static ::pdgen::Expr PDGEN_CONCAT(influence_, name)([[maybe_unused]] ::pdgen::Expr r,         \
                                                      [[maybe_unused]] ::pdgen::Expr delta)

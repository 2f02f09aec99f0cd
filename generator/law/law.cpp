// The law model: inputs, parameters, horizon sums (moment/state classification), force state.
#include "pdgen/law.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "pdgen/diff.hpp"

namespace pdgen {

namespace {
void check_identifier(const std::string& s) {
  const bool ok = !s.empty() && (std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_') &&
                  std::all_of(s.begin(), s.end(),
                              [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; });
  if (!ok) throw std::invalid_argument("law: '" + s + "' is not a C identifier");
}
Vec bond_vector(const std::string& name, int dim) {
  Vec v(dim);
  for (int i = 0; i < dim; ++i) v[i] = symbol(name + "_" + std::to_string(i), SymbolKind::BondInput);
  return v;
}
}  // namespace

std::string& law_under_construction() {
  static std::string name;
  return name;
}

Law::Law(std::string name, int dim, std::string summary)
    : name_(std::move(name)), summary_(std::move(summary)), dim_(dim) {
  law_under_construction() = name_;
  check_identifier(name_);
  if (dim != 2 && dim != 3) throw std::invalid_argument("law " + name_ + ": dimension must be 2 or 3");
  xi_ = bond_vector("xi", dim);
  Y_ = bond_vector("Y", dim);
  w_ = symbol("w", SymbolKind::BondInput);
  alpha_ = symbol("alpha", SymbolKind::BondInput);
  V_ = symbol("V", SymbolKind::BondInput);
  V0_ = symbol("V0", SymbolKind::ParticleInput);
  delta_ = symbol("delta", SymbolKind::ParticleInput);
  time_step_ = symbol("time_step", SymbolKind::ParticleInput);
  dilatation_factor_ = symbol("dilatation_factor", SymbolKind::BondInput);
  force_factor_ = symbol("force_factor", SymbolKind::BondInput);
}

Expr Law::param(const std::string& name) {
  check_identifier(name);
  for (std::size_t i = 0; i < param_names_.size(); ++i)
    if (param_names_[i] == name) return params_[i];
  param_names_.push_back(name);
  params_.push_back(symbol(name, SymbolKind::Param));
  param_test_values_.push_back(std::numeric_limits<double>::quiet_NaN());
  param_ranges_.push_back(ParamRange::any);
  return params_.back();
}

Expr Law::param(const std::string& name, double test_value) {
  if (!std::isfinite(test_value))
    throw std::invalid_argument("law " + name_ + ": test value of parameter '" + name + "' must be finite");
  const Expr p = param(name);
  for (std::size_t i = 0; i < param_names_.size(); ++i)
    if (param_names_[i] == name) param_test_values_[i] = test_value;
  return p;
}

Expr Law::param(const std::string& name, double test_value, ParamRange range) {
  const bool inside = range == ParamRange::any || (range == ParamRange::positive && test_value > 0) ||
                      (range == ParamRange::non_negative && test_value >= 0) ||
                      (range == ParamRange::unit_interval && test_value >= 0 && test_value <= 1);
  if (!inside)
    throw std::invalid_argument("law " + name_ + ": the test value of parameter '" + name +
                                "' lies outside the range the law declares for it");
  const Expr p = param(name, test_value);
  for (std::size_t i = 0; i < param_names_.size(); ++i)
    if (param_names_[i] == name) param_ranges_[i] = range;
  return p;
}

Expr Law::pair_param(const std::string& name, PairMean mean) {
  param(name);
  const auto index =
      static_cast<int>(std::find(param_names_.begin(), param_names_.end(), name) - param_names_.begin());
  for (const PairParamDef& d : pair_params_) {
    if (d.param != index) continue;
    if (d.mean != mean)
      throw std::invalid_argument("law " + name_ + ": pair parameter '" + name +
                                  "' declared with two different means");
    return d.symbol;
  }
  pair_params_.push_back({symbol("pair_" + name, SymbolKind::BondInput), index, mean});
  return pair_params_.back().symbol;
}

void Law::fixed_poisson_ratio(double nu) {
  if (!(nu > -1.0 && nu < 0.5))
    throw std::invalid_argument("law " + name_ + ": a Poisson ratio lies in (-1, 0.5)");
  has_fixed_poisson_ratio_ = true;
  poisson_ratio_ = nu;
}

void Law::reproducing_terms(int lowest_degree, int highest_degree, int inverse_r_power) {
  if (lowest_degree < 0 || highest_degree < lowest_degree)
    throw std::invalid_argument("law " + name_ + ": reproducing_terms needs 0 <= lowest <= highest degree");
  reproducing_groups_.push_back({lowest_degree, highest_degree, inverse_r_power});
}

void Law::built_in_kernel(std::string description, std::vector<RadialTermDef> profile) {
  if (has_built_in_kernel_) throw std::invalid_argument("law " + name_ + ": built_in_kernel declared twice");
  if (description.empty() || profile.empty())
    throw std::invalid_argument("law " + name_ + ": built_in_kernel needs a description and a profile");
  for (const RadialTermDef& t : profile)
    if (!std::isfinite(t.coefficient))
      throw std::invalid_argument("law " + name_ + ": built_in_kernel coefficients must be finite");
  has_built_in_kernel_ = true;
  kernel_description_ = std::move(description);
  kernel_profile_ = std::move(profile);
}

void Law::check_new_history(const std::string& name, double initial) const {
  check_identifier(name);
  if (!std::isfinite(initial))
    throw std::invalid_argument("law " + name_ + ": initial value of history '" + name + "' must be finite");
  for (const std::vector<HistoryDef>* list : {&history_, &particle_history_})
    for (const HistoryDef& h : *list)
      if (h.name == name)
        throw std::invalid_argument("law " + name_ + ": history '" + name + "' declared twice");
}

Expr Law::bond_history(const std::string& name, double initial) {
  check_new_history(name, initial);
  const Expr committed = symbol("history_" + name, SymbolKind::BondInput);
  history_.push_back({name, initial, committed, committed, false});
  return committed;
}

Expr Law::particle_history(const std::string& name, double initial) {
  check_new_history(name, initial);
  const Expr committed = symbol("particle_history_" + name, SymbolKind::ParticleInput);
  particle_history_.push_back({name, initial, committed, committed, false});
  return committed;
}

void Law::update(Expr committed, Expr updated) {
  for (std::vector<HistoryDef>* list : {&history_, &particle_history_})
    for (HistoryDef& h : *list) {
      if (h.committed != committed) continue;
      if (h.has_update)
        throw std::invalid_argument("law " + name_ + ": history '" + h.name + "' updated twice");
      h.updated = updated;
      h.has_update = true;
      return;
    }
  throw std::invalid_argument("law " + name_ + ": update of an expression that is not a declared history");
}

Expr Law::deformed_length() const { return sqrt(dot(Y_, Y_) + 1e-16 * dot(xi_, xi_)); }

Expr Law::sum(const std::string& name, Expr body) {
  check_identifier(name);
  for (const SumDef& d : sums_)
    if (d.name == name) throw std::invalid_argument("law " + name_ + ": sum '" + name + "' declared twice");
  SumDef def{name, symbol(name, SymbolKind::Sum), body, false, 0};
  std::vector<int> y_symbols;
  for (int c = 0; c < dim_; ++c) y_symbols.push_back(symbol_index(Y_[c]));
  for (const HistoryDef& h : history_) y_symbols.push_back(symbol_index(h.committed));
  for (const HistoryDef& h : particle_history_) y_symbols.push_back(symbol_index(h.committed));
  for (int s : free_symbols(body)) {
    // A sum that reads the deformation or the committed history changes from step to step:
    // a state, evaluated by every kernel; the others are moments, computed once at setup.
    if (std::find(y_symbols.begin(), y_symbols.end(), s) != y_symbols.end()) def.is_state = true;
    for (const SumDef& earlier : sums_) {
      if (symbol_index(earlier.symbol) != s) continue;
      def.is_state = def.is_state || earlier.is_state;
      def.level = std::max(def.level, earlier.level + 1);
    }
  }
  sums_.push_back(def);
  return def.symbol;
}

bool Law::reads_influence() const {
  const int w = symbol_index(w_);
  const auto is_w = [w](int s) { return s == w; };
  for (int c = 0; c < force_.dim(); ++c)
    if (depends_on(force_[c], is_w)) return true;
  for (const SumDef& def : sums_)  // the force reads a sum through its symbol
    if (depends_on(def.body, is_w)) return true;
  return false;
}

Expr Law::dilatation_sum(const std::string& name, Expr body) {
  if (has_dilatation_sum_)
    throw std::invalid_argument("law " + name_ + ": a second dilatation_sum '" + name + "'");
  has_dilatation_sum_ = true;
  const Expr theta = sum(name, dilatation_factor_ * body);
  output("dilatation", theta);  // the surface correction reads it (runtime: output "dilatation")
  return theta;
}

Vec Law::sum(const std::string& name, const Vec& body) {
  Vec r(body.dim());
  for (int i = 0; i < body.dim(); ++i) r[i] = sum(name + "_" + std::to_string(i), body[i]);
  return r;
}

Mat Law::sum(const std::string& name, const Mat& body) {
  Mat r(body.dim());
  for (int i = 0; i < body.dim(); ++i)
    for (int j = 0; j < body.dim(); ++j)
      r(i, j) = sum(name + "_" + std::to_string(i) + "_" + std::to_string(j), body(i, j));
  return r;
}

void Law::force(const Vec& t) {
  if (t.dim() != dim_) throw std::invalid_argument("law " + name_ + ": force state has the wrong dimension");
  force_ = t;
}

Law Law::with_alpha_folded() const {
  const std::unordered_map<int, Expr> one{{symbol_index(alpha_), Expr(1.0)}};
  Law r = *this;
  for (SumDef& d : r.sums_) d.body = substitute(d.body, one);
  for (int c = 0; c < dim_; ++c) r.force_[c] = substitute(force_[c], one);
  if (has_energy_) r.energy_ = substitute(energy_, one);
  for (OutputDef& o : r.outputs_) o.value = substitute(o.value, one);
  for (HistoryDef& h : r.history_) h.updated = substitute(h.updated, one);
  for (HistoryDef& h : r.particle_history_) h.updated = substitute(h.updated, one);
  return r;
}

std::vector<LawEntry>& law_registry() {
  static std::vector<LawEntry> r;
  return r;
}
std::vector<InfluenceDef>& influence_registry() {
  static std::vector<InfluenceDef> r;
  return r;
}
std::string file_stem(const char* path) {
  std::string p(path);
  const auto slash = p.find_last_of("/\\");
  if (slash != std::string::npos) p = p.substr(slash + 1);
  const auto dot = p.find('.');
  return dot == std::string::npos ? p : p.substr(0, dot);
}

}  // namespace pdgen

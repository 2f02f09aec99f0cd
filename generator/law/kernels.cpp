// The kernel builders. The tangent follows paper 000's Appendix: for bond i and
// neighbour k,  d t_i / d Y_k = delta_ik dt/dY |_i + sum_s dt/dS_s |_i (x) dS_s/dY_k,
// where a state S_s = sum_j g_s(Y_j, earlier states) has the total derivative
//     dS_s/dY_k = dg_s/dY |_k + sum_{s'} C[s][s'] dS_{s'}/dY_k,  C[s][s'] = sum_j dg_s/dS_{s'} |_j.
// C is one more horizon sum, accumulated in the loop of S_s, so every block
// factor costs O(1) per bond and the factored tangent O(L).
#include "pdgen/kernels.hpp"

#include <algorithm>
#include <functional>
#include <set>
#include <stdexcept>

#include "emit/abi_text.hpp"
#include "pdgen/diff.hpp"

namespace pdgen {

namespace {
std::string str(int i) { return std::to_string(i); }

class Builder {
 public:
  Builder(const Law& law, std::string prefix) : law_(law), prefix_(std::move(prefix)), D_(law.dim()) {
    for (const SumDef& s : law.sums()) (s.is_state ? states_ : moments_).push_back(&s);
    // Only the states the force needs enter the tangent.
    std::vector<Expr> force_roots;
    for (int c = 0; c < D_; ++c) force_roots.push_back(law.force_state()[c]);
    force_states_ = needed(force_roots, true);
  }

  LawKernelSet build() {
    LawKernelSet out;
    for (const SumDef* m : moments_) out.moment_names.push_back(m->name);
    for (const SumDef* s : force_states_) out.state_names.push_back(s->name);
    out.n_moments = static_cast<int>(moments_.size());
    out.n_states = static_cast<int>(force_states_.size());
    out.moments = moments_kernel();
    out.residual = prune(residual_kernel());
    out.tangent = prune(tangent_kernel(out.factor_structure));
    out.jvp = prune(jvp_kernel());
    out.sensitivity = prune(sensitivity_kernel());
    out.has_energy = law_.has_energy();
    if (out.has_energy)
      out.energy =
          prune(particle_value_kernel("energy", abi_text::Kernel::Energy, {{"W", law_.energy_density()}}));
    out.has_outputs = !law_.outputs().empty();
    if (out.has_outputs) {
      std::vector<std::pair<std::string, Expr>> values;
      for (std::size_t i = 0; i < law_.outputs().size(); ++i)
        values.push_back({abi_text::output(static_cast<int>(i)), law_.outputs()[i].value});
      out.outputs = prune(particle_value_kernel("outputs", abi_text::Kernel::Outputs, values));
    }
    out.has_update = law_.has_history();
    if (out.has_update) out.update = prune(update_kernel());
    return out;
  }

 private:
  // The states (or moments) reachable from `roots`, through sum bodies, in declaration order.
  std::vector<const SumDef*> needed(const std::vector<Expr>& roots, bool states) const {
    std::set<int> seen;
    std::vector<Expr> work = roots;
    while (!work.empty()) {
      const Expr e = work.back();
      work.pop_back();
      for (int s : free_symbols(e))
        for (const SumDef& d : law_.sums())
          if (symbol_index(d.symbol) == s && seen.insert(s).second) work.push_back(d.body);
    }
    std::vector<const SumDef*> out;
    for (const SumDef& d : law_.sums())
      if (d.is_state == states && seen.count(symbol_index(d.symbol))) out.push_back(&d);
    return out;
  }

  static std::string var(const SumDef& s) { return "s_" + s.name; }

  // Bindings shared by every kernel of the law. Moments are read from fam.moments
  // unless the kernel computes them.
  std::map<int, Binding> base_bindings(bool moments_are_inputs) const {
    std::map<int, Binding> b;
    for (int c = 0; c < D_; ++c) {
      b[symbol_index(law_.xi()[c])] = {"xi_" + str(c), abi_text::bond_vector("xi", D_, c), true};
      b[symbol_index(law_.Y()[c])] = {"Y_" + str(c), abi_text::bond_vector("Y", D_, c), true};
    }
    b[symbol_index(law_.w())] = {"w", abi_text::bond_scalar("w"), true};
    b[symbol_index(law_.alpha())] = {"alpha", abi_text::bond_scalar("alpha"), true};
    b[symbol_index(law_.V())] = {"V", abi_text::bond_scalar("V"), true};
    b[symbol_index(law_.dilatation_factor())] = {"sd", abi_text::optional_bond_scalar("dilatation_factor"),
                                                 true};
    b[symbol_index(law_.force_factor())] = {"sf", abi_text::optional_bond_scalar("force_factor"), true};
    b[symbol_index(law_.V0())] = {"V0", abi_text::family_scalar("V0"), false};
    b[symbol_index(law_.delta())] = {"delta", abi_text::family_scalar("delta"), false};
    b[symbol_index(law_.time_step_symbol())] = {"dt", abi_text::family_scalar("time_step"), false};
    for (std::size_t i = 0; i < law_.params().size(); ++i)
      b[symbol_index(law_.params()[i])] = {"P_" + law_.param_names()[i], abi_text::param(static_cast<int>(i)),
                                           false};
    for (const PairParamDef& q : law_.pair_params())
      b[symbol_index(q.symbol)] = {
          "Q_" + law_.param_names()[static_cast<std::size_t>(q.param)],
          abi_text::pair_param(q.param, static_cast<int>(law_.params().size()),
                               q.mean == PairMean::harmonic ? "harmonic_mean" : "arithmetic_mean"),
          true};
    for (std::size_t i = 0; i < moments_.size(); ++i)
      b[symbol_index(moments_[i]->symbol)] = {
          var(*moments_[i]), moments_are_inputs ? abi_text::moment_input(static_cast<int>(i)) : "", false};
    for (const SumDef* s : states_) b[symbol_index(s->symbol)] = {var(*s), "", false};
    const auto n_history = static_cast<int>(law_.history().size());
    for (int i = 0; i < n_history; ++i) {
      const HistoryDef& h = law_.history()[static_cast<std::size_t>(i)];
      b[symbol_index(h.committed)] = {"H_" + h.name, abi_text::history_input(i, n_history, h.initial), true};
    }
    for (std::size_t i = 0; i < law_.particle_history().size(); ++i) {
      const HistoryDef& h = law_.particle_history()[i];
      b[symbol_index(h.committed)] = {
          "PH_" + h.name, abi_text::particle_history_input(static_cast<int>(i), h.initial), false};
    }
    return b;
  }

  KernelProgram program(const std::string& kind, abi_text::Kernel k, bool moments_are_inputs) const {
    const abi_text::Signature sig = abi_text::signature(k);
    KernelProgram p;
    p.name = prefix_ + "_" + kind;
    p.return_type = sig.return_type;
    p.params = sig.params;
    p.param_names = sig.names;
    p.bindings = base_bindings(moments_are_inputs);
    return p;
  }

  // One loop per level of the given sums: level-l sums only use sums of lower levels.
  // `extra(sum, segment)` adds companion accumulations (tangent couplings, JVP sums).
  void sum_loops(KernelProgram& p, const std::vector<const SumDef*>& sums,
                 const std::function<void(const SumDef&, Segment&)>& extra = {}) const {
    int max_level = -1;
    for (const SumDef* s : sums) max_level = std::max(max_level, s->level);
    for (int level = 0; level <= max_level; ++level) {
      Segment seg;
      seg.loop = true;
      for (const SumDef* s : sums) {
        if (s->level != level) continue;
        seg.accumulators.push_back(symbol_index(s->symbol));
        seg.stores.push_back({var(*s), s->body, StoreMode::Accumulate, "", symbol_index(s->symbol)});
        if (extra) extra(*s, seg);
      }
      if (!seg.stores.empty()) p.segments.push_back(seg);
    }
  }

  // The force state the kernels use: the law's, times the bond's surface-correction force
  // factor (1 when Family::force_factor is null), so the forces, the tangent factors
  // (direct, left) and the JVP all carry it and the local matrix needs no change.
  std::vector<Expr> force_roots() const {
    std::vector<Expr> r;
    for (int c = 0; c < D_; ++c) r.push_back(law_.force_factor() * law_.force_state()[c]);
    return r;
  }

  // Nodal forces: f_0 += V0 V t, f_{k+1} = -V0 V t (the convention of kernel_abi.hpp).
  void force_stores(Segment& seg, const std::vector<Expr>& t, const std::string& array,
                    const std::string& guard) const {
    std::string zero;
    for (int c = 0; c < D_; ++c) zero += abi_text::center_component(array, c) + " = 0.0; ";
    seg.before.push_back(guard.empty() ? zero : "if (" + guard + ") { " + zero + "}");
    for (int c = 0; c < D_; ++c) {
      const Expr v = law_.V0() * law_.V() * t[static_cast<std::size_t>(c)];
      seg.stores.push_back({abi_text::neighbour_component(array, D_, c), v, StoreMode::SetNegated, guard});
      seg.stores.push_back({abi_text::center_component(array, c), v, StoreMode::Accumulate, guard});
    }
  }

  KernelProgram moments_kernel() const {
    KernelProgram p = program("moments", abi_text::Kernel::Moments, false);
    sum_loops(p, moments_);
    Segment out;
    for (std::size_t i = 0; i < moments_.size(); ++i)
      out.stores.push_back(
          {abi_text::moment_output(static_cast<int>(i)), moments_[i]->symbol, StoreMode::Set, ""});
    if (!out.stores.empty()) p.segments.push_back(out);
    return p;
  }

  KernelProgram residual_kernel() const {
    KernelProgram p = program("residual", abi_text::Kernel::Residual, true);
    sum_loops(p, force_states_);
    Segment seg;
    seg.loop = true;
    force_stores(seg, force_roots(), "forces", "");
    p.segments.push_back(seg);
    return p;
  }

  // Also records which factor entries are structurally zero (their expression folded to
  // the constant 0), for the form kernel.
  KernelProgram tangent_kernel(FactorStructure& structure) const {
    KernelProgram p = program("tangent", abi_text::Kernel::Tangent, true);
    const int NS = static_cast<int>(force_states_.size());
    structure = {D_, NS, {}, {}, {}};
    // Coupling sums C[s][s'] between states, bound to per-family variables.
    std::map<std::pair<int, int>, Expr> coupling;
    for (int s = 0; s < NS; ++s)
      for (int q = 0; q < s; ++q) {
        const Expr dg = diff(force_states_[s]->body, force_states_[q]->symbol);
        if (dg.is_const(0.0)) continue;
        const std::string name = "c_" + str(s) + "_" + str(q);
        const Expr sym = symbol(name, SymbolKind::Sum);
        p.bindings[symbol_index(sym)] = {name, "", false};
        coupling[{s, q}] = sym;
      }
    sum_loops(p, force_states_, [&](const SumDef& sd, Segment& seg) {
      const int s = index_of(sd);
      for (auto& [key, sym] : coupling)
        if (key.first == s) {
          seg.accumulators.push_back(symbol_index(sym));
          seg.stores.push_back({p.bindings.at(symbol_index(sym)).var,
                                diff(sd.body, force_states_[key.second]->symbol), StoreMode::Accumulate, "",
                                symbol_index(sym)});
        }
    });
    Segment seg;
    seg.loop = true;
    const std::vector<Expr> t = force_roots();
    force_stores(seg, t, "forces", abi_text::forces_requested());
    for (int r = 0; r < D_; ++r)
      for (int c = 0; c < D_; ++c) {
        const Expr v = diff(t[r], law_.Y()[c]);
        structure.direct.push_back(!v.is_const(0.0));
        seg.stores.push_back({abi_text::factor_direct(D_, r, c), v, StoreMode::Set, ""});
      }
    std::vector<std::vector<Expr>> R(static_cast<std::size_t>(NS),
                                     std::vector<Expr>(static_cast<std::size_t>(D_)));
    for (int s = 0; s < NS; ++s) {
      for (int c = 0; c < D_; ++c) {
        Expr v = diff(force_states_[s]->body, law_.Y()[c]);
        for (int q = 0; q < s; ++q)
          if (auto it = coupling.find({s, q}); it != coupling.end()) v = v + it->second * R[q][c];
        R[s][c] = v;
        structure.right.push_back(!v.is_const(0.0));
        seg.stores.push_back({abi_text::factor_right(D_, NS, s, c), v, StoreMode::Set, ""});
      }
      for (int r = 0; r < D_; ++r) {
        const Expr v = diff(t[r], force_states_[s]->symbol);
        structure.left.push_back(!v.is_const(0.0));
        seg.stores.push_back({abi_text::factor_left(D_, NS, s, r), v, StoreMode::Set, ""});
      }
    }
    p.segments.push_back(seg);
    return p;
  }

  // df = (df/dy) dy with dY_k = dy_{k+1} - dy_0, through the states' increments.
  KernelProgram jvp_kernel() const {
    KernelProgram p = program("jvp", abi_text::Kernel::Jvp, true);
    Vec dY(D_);
    for (int c = 0; c < D_; ++c) {
      dY[c] = symbol("dY_" + str(c), SymbolKind::BondInput);
      p.bindings[symbol_index(dY[c])] = {"dY_" + str(c), abi_text::bond_increment(D_, c), true};
    }
    std::vector<Expr> dS;
    for (const SumDef* s : force_states_) {
      dS.push_back(symbol("d_" + s->name, SymbolKind::Sum));
      p.bindings[symbol_index(dS.back())] = {"ds_" + s->name, "", false};
    }
    auto directional = [&](Expr e) {
      std::vector<Expr> terms;
      for (int c = 0; c < D_; ++c) terms.push_back(diff(e, law_.Y()[c]) * dY[c]);
      for (std::size_t s = 0; s < force_states_.size(); ++s)
        terms.push_back(diff(e, force_states_[s]->symbol) * dS[s]);
      return add(terms);
    };
    sum_loops(p, force_states_, [&](const SumDef& sd, Segment& seg) {
      const int ds = symbol_index(dS[static_cast<std::size_t>(index_of(sd))]);
      seg.accumulators.push_back(ds);
      seg.stores.push_back({p.bindings.at(ds).var, directional(sd.body), StoreMode::Accumulate, "", ds});
    });
    Segment seg;
    seg.loop = true;
    std::vector<Expr> dt;
    for (Expr t : force_roots()) dt.push_back(directional(t));
    force_stores(seg, dt, "df", "");
    p.segments.push_back(seg);
    return p;
  }

  // df/dp_i for every material parameter p_i: the whole family's value varied together (the
  // center's and every neighbour's, so a pair mean of equal values moves with it: d mean/dp =
  // 1), the committed history and the deformation held fixed. Forward mode through the sums:
  // a sum S = sum_j g(...) has dS/dp = sum_j [dg/dp + sum_S' dg/dS' dS'/dp], one more horizon
  // sum per (sum, parameter) whose derivative is not structurally zero. Moments that read a
  // parameter get theirs in loops of their own first: the states' loops read them.
  KernelProgram sensitivity_kernel() const {
    KernelProgram p = program("sensitivity", abi_text::Kernel::Sensitivity, true);
    const int NP = static_cast<int>(law_.params().size());
    // Per parameter: (symbol, d symbol / d p_i) for every symbol that moves with p_i.
    std::vector<std::vector<std::pair<Expr, Expr>>> d(static_cast<std::size_t>(NP));
    for (int i = 0; i < NP; ++i) d[i].push_back({law_.params()[static_cast<std::size_t>(i)], Expr(1.0)});
    for (const PairParamDef& q : law_.pair_params()) d[q.param].push_back({q.symbol, Expr(1.0)});
    auto directional = [](Expr e, const std::vector<std::pair<Expr, Expr>>& di) {
      std::vector<Expr> terms;
      for (const auto& [sym, dsym] : di) terms.push_back(diff(e, sym) * dsym);
      return add(terms);
    };
    // Declares d S / d p_i when not zero; returns its store.
    auto derivative_sum = [&](const SumDef& sd, int i, std::vector<Store>& stores, std::vector<int>& acc) {
      const Expr body = directional(sd.body, d[i]);
      if (body.is_const(0.0)) return;
      const Expr sym = symbol("dp" + str(i) + "_" + sd.name, SymbolKind::Sum);
      const int idx = symbol_index(sym);
      p.bindings[idx] = {"dp" + str(i) + "_" + sd.name, "", false};
      acc.push_back(idx);
      stores.push_back({p.bindings.at(idx).var, body, StoreMode::Accumulate, "", idx});
      d[i].push_back({sd.symbol, sym});
    };
    int max_level = -1;
    for (const SumDef* m : moments_) max_level = std::max(max_level, m->level);
    for (int level = 0; level <= max_level; ++level) {
      Segment seg;
      seg.loop = true;
      for (const SumDef* m : moments_)
        if (m->level == level)
          for (int i = 0; i < NP; ++i) derivative_sum(*m, i, seg.stores, seg.accumulators);
      if (!seg.stores.empty()) p.segments.push_back(seg);
    }
    sum_loops(p, force_states_, [&](const SumDef& sd, Segment& seg) {
      for (int i = 0; i < NP; ++i) derivative_sum(sd, i, seg.stores, seg.accumulators);
    });
    Segment seg;
    seg.loop = true;
    const std::vector<Expr> t = force_roots();
    for (int i = 0; i < NP; ++i) {
      std::vector<Expr> dt;
      for (Expr tc : t) dt.push_back(directional(tc, d[i]));
      force_stores(seg, dt, abi_text::sensitivity_column(D_, i), "");
    }
    p.segments.push_back(seg);
    return p;
  }

  // The history update: every variable's value at the end of the step, per bond and for the
  // center particle, from the committed values and the current deformation (through the
  // states it reads).
  KernelProgram update_kernel() const {
    KernelProgram p = program("update", abi_text::Kernel::Update, true);
    std::vector<Expr> roots;
    for (const HistoryDef& h : law_.history()) roots.push_back(h.updated);
    for (const HistoryDef& h : law_.particle_history()) roots.push_back(h.updated);
    sum_loops(p, needed(roots, true));
    const auto n_history = static_cast<int>(law_.history().size());
    if (n_history > 0) {
      Segment seg;
      seg.loop = true;
      for (int i = 0; i < n_history; ++i)
        seg.stores.push_back({abi_text::history_output(i, n_history),
                              law_.history()[static_cast<std::size_t>(i)].updated, StoreMode::Set, ""});
      p.segments.push_back(seg);
    }
    if (!law_.particle_history().empty()) {
      Segment seg;  // the center's values: per-particle expressions, outside the bond loop
      for (std::size_t i = 0; i < law_.particle_history().size(); ++i)
        seg.stores.push_back({abi_text::particle_history_output(static_cast<int>(i)),
                              law_.particle_history()[i].updated, StoreMode::Set, ""});
      p.segments.push_back(seg);
    }
    return p;
  }

  KernelProgram particle_value_kernel(const std::string& kind, abi_text::Kernel k,
                                      const std::vector<std::pair<std::string, Expr>>& values) const {
    KernelProgram p = program(kind, k, true);
    const bool returns = p.return_type != "void";
    std::vector<Expr> roots;
    for (auto& v : values) roots.push_back(v.second);
    sum_loops(p, needed(roots, true));
    Segment seg;
    for (auto& [target, value] : values)
      seg.stores.push_back({returns ? "const double " + target : target, value, StoreMode::Set, ""});
    p.segments.push_back(seg);
    if (returns) p.epilogue.push_back("return " + values.front().first + ";");
    return p;
  }

  // Drops the horizon sums a kernel accumulates but never reads (e.g. the deformed shape
  // tensor in the JVP of a law linear in it): a sum is kept when a store into anything
  // but a sum reads it, directly or through the bodies of other kept sums. Works on the
  // sums' symbols only (Store::sum, Segment::accumulators).
  static KernelProgram prune(KernelProgram p) {
    std::map<int, std::vector<Expr>> bodies;  // sum symbol -> the values accumulated into it
    std::vector<int> work;
    for (const Segment& seg : p.segments)
      for (const Store& st : seg.stores) {
        if (st.sum >= 0) {
          bodies[st.sum].push_back(st.value);
        } else {
          for (int sym : free_symbols(st.value)) work.push_back(sym);
        }
      }
    std::set<int> needed;
    while (!work.empty()) {
      const int sym = work.back();
      work.pop_back();
      if (!needed.insert(sym).second) continue;
      for (Expr body : bodies[sym])
        for (int s2 : free_symbols(body)) work.push_back(s2);
    }
    std::vector<Segment> kept;
    for (Segment seg : p.segments) {
      std::erase_if(seg.stores, [&](const Store& st) { return st.sum >= 0 && !needed.count(st.sum); });
      std::erase_if(seg.accumulators, [&](int sum) { return !needed.count(sum); });
      if (!seg.stores.empty() || !seg.before.empty() || !seg.accumulators.empty()) kept.push_back(seg);
    }
    p.segments = kept;
    return p;
  }

  int index_of(const SumDef& sd) const {
    for (std::size_t i = 0; i < force_states_.size(); ++i)
      if (force_states_[i] == &sd) return static_cast<int>(i);
    throw std::logic_error("state not found");
  }

  const Law& law_;
  std::string prefix_;
  int D_;
  std::vector<const SumDef*> moments_, states_, force_states_;
};
}  // namespace

LawKernelSet build_kernels(const Law& law, const std::string& prefix) { return Builder(law, prefix).build(); }

KernelProgram influence_kernel(const InfluenceDef& inf) {
  const Expr r = symbol("r"), delta = symbol("delta");
  const abi_text::Signature sig = abi_text::signature(abi_text::Kernel::Influence);
  KernelProgram p;
  p.name = "influence_" + inf.name;
  p.return_type = sig.return_type;
  p.params = sig.params;
  p.param_names = sig.names;
  p.bindings[symbol_index(r)] = {"r", "", false};
  p.bindings[symbol_index(delta)] = {"delta", "", false};
  Segment seg;
  seg.stores.push_back({"const double w", inf.weight(r, delta), StoreMode::Set, ""});
  p.segments.push_back(seg);
  p.epilogue.push_back("return w;");
  return p;
}

}  // namespace pdgen

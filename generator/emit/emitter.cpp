// Scheduling and printing: with interning, common-subexpression elimination is
// scheduling. Per segment the reachable low-level nodes are visited in topological
// order; a node becomes a named temporary when it is used twice or is a call.
// Per-family nodes needed inside a loop are hoisted before it. A per-bond call
// needed by several loops is computed once and kept in a per-bond cache, so no
// kernel evaluates the same sqrt/pow twice. The cache is the caller's Family::scratch.
#include <algorithm>
#include <charconv>
#include <functional>
#include <set>
#include <sstream>
#include <stdexcept>

#include "emit/abi_text.hpp"
#include "emit/lir.hpp"

namespace pdgen {

std::string cpp_double(double v) {
  char buf[64];
  auto res = std::to_chars(buf, buf + sizeof buf, v);
  std::string s(buf, res.ptr);
  if (s.find_first_of(".eEn") == std::string::npos) s += ".0";
  return s;
}

namespace {
using lir::Graph;
using lir::Kind;

int precedence(Kind k) {
  switch (k) {
    case Kind::Add:
    case Kind::Sub:
      return 1;
    case Kind::Mul:
    case Kind::Div:
      return 2;
    case Kind::Neg:
      return 3;
    case Kind::Select:
      return 0;
    case Kind::Const:
    case Kind::Var:
    case Kind::Call:
      return 4;
  }
  return 4;
}

void count(const lir::Node& n, EmitCounts& c) {
  switch (n.kind) {
    case Kind::Add:
    case Kind::Sub:
    case Kind::Neg:
    case Kind::Select:
      ++c.adds;
      break;
    case Kind::Mul:
      ++c.muls;
      break;
    case Kind::Div:
      ++c.divs;
      break;
    case Kind::Call:
      ++c.calls;
      break;
    case Kind::Const:
    case Kind::Var:
      break;
  }
}

class Printer {
 public:
  Printer(const KernelProgram& p) : prog_(p), g_(p.bindings) {}

  EmittedKernel run() {
    std::vector<std::vector<int>> roots(prog_.segments.size());
    for (std::size_t s = 0; s < prog_.segments.size(); ++s)
      for (const Store& st : prog_.segments[s].stores) roots[s].push_back(g_.lower(st.value));
    plan_cache(roots);

    std::ostringstream body;
    if (has_loop()) body << "  const int L = " << abi_text::bond_count() << ";\n";
    emit_particle_loads(body, roots);
    // The per-bond cache lives in the caller's scratch (LawDescriptor::scratch_per_bond).
    if (!cached_.empty()) body << "  double* const cache = " << abi_text::scratch() << ";\n";
    for (std::size_t s = 0; s < prog_.segments.size(); ++s)
      emit_segment(body, prog_.segments[s], roots[s], s);
    for (const std::string& line : prog_.epilogue) body << "  " << line << "\n";

    EmittedKernel out;
    out.per_bond = per_bond_;
    out.scratch_per_bond = static_cast<int>(cached_.size());
    out.per_family = per_family_;
    std::string sig = prog_.return_type + " " + prog_.name + "(";
    for (std::size_t i = 0; i < prog_.params.size(); ++i) sig += (i ? ", " : "") + prog_.params[i];
    sig += ")";
    out.declaration = sig + ";";
    std::ostringstream code;
    code << "// " << prog_.name << ": per bond " << per_bond_.adds << " add, " << per_bond_.muls << " mul, "
         << per_bond_.divs << " div, " << per_bond_.calls << " call; per family " << per_family_.adds
         << " add, " << per_family_.muls << " mul, " << per_family_.divs << " div, " << per_family_.calls
         << " call\n";
    code << sig << " {\n";
    const std::string text = body.str();
    for (const std::string& name : prog_.param_names)
      if (!uses_identifier(text, name)) code << "  static_cast<void>(" << name << ");\n";
    code << text << "}\n";
    out.code = code.str();
    return out;
  }

 private:
  static bool uses_identifier(const std::string& text, const std::string& name) {
    for (std::size_t p = text.find(name); p != std::string::npos; p = text.find(name, p + 1)) {
      const bool left =
          p == 0 || !(std::isalnum(static_cast<unsigned char>(text[p - 1])) || text[p - 1] == '_');
      const std::size_t e = p + name.size();
      const bool right =
          e >= text.size() || !(std::isalnum(static_cast<unsigned char>(text[e])) || text[e] == '_');
      if (left && right) return true;
    }
    return false;
  }
  bool has_loop() const {
    for (const Segment& s : prog_.segments)
      if (s.loop) return true;
    return false;
  }

  // Reachable nodes from `roots` in post-order, stopping at `leaf(id)`.
  std::vector<int> reach(const std::vector<int>& roots, const std::function<bool(int)>& leaf) const {
    std::vector<int> order;
    std::set<int> seen;
    std::function<void(int)> visit = [&](int id) {
      if (!seen.insert(id).second) return;
      if (!leaf(id))
        for (int a : g_.node(id).args) visit(a);
      order.push_back(id);
    };
    for (int r : roots) visit(r);
    return order;
  }

  void plan_cache(const std::vector<std::vector<int>>& roots) {
    std::map<int, int> loops_using;
    for (std::size_t s = 0; s < roots.size(); ++s) {
      if (!prog_.segments[s].loop) continue;
      for (int id : reach(roots[s], [&](int i) { return !g_.node(i).per_bond; }))
        if (g_.node(id).kind == Kind::Call && g_.node(id).per_bond) ++loops_using[id];
    }
    for (auto [id, n] : loops_using)
      if (n >= 2) {
        const int slot = static_cast<int>(cached_.size());
        cached_[id] = slot;
      }
  }

  void emit_particle_loads(std::ostringstream& out, const std::vector<std::vector<int>>& roots) {
    std::set<std::string> done;
    for (const auto& r : roots)
      for (int id : reach(r, [](int) { return false; })) {
        const lir::Node& n = g_.node(id);
        if (n.kind != Kind::Var || n.per_bond) continue;
        const Binding& b = prog_.bindings.at(g_.var_symbols().at(id));
        if (b.load.empty() || !done.insert(b.var).second) continue;
        out << "  const double " << b.var << " = " << b.load << ";\n";
      }
  }

  std::string expr_text(int id, const std::map<int, std::string>& names) const {
    if (auto it = names.find(id); it != names.end()) return it->second;
    const lir::Node& n = g_.node(id);
    auto child = [&](int a, int min_prec) {
      const std::string t = expr_text(a, names);
      const bool named = names.count(a) > 0;
      return (!named && precedence(g_.node(a).kind) < min_prec) ? "(" + t + ")" : t;
    };
    switch (n.kind) {
      case Kind::Const:
        return cpp_double(n.value);
      case Kind::Var:
        return n.text;
      // A right operand of the same precedence is parenthesised: C++ groups left to
      // right, and a * (1.0 / b) printed bare would compute (a * 1.0) / b — another
      // division, and not the tree the counts and the other kernels describe.
      case Kind::Add:
        return child(n.args[0], 1) + " + " + child(n.args[1], 2);
      case Kind::Sub:
        return child(n.args[0], 1) + " - " + child(n.args[1], 2);
      case Kind::Mul:
        return child(n.args[0], 2) + " * " + child(n.args[1], 3);
      case Kind::Div:
        return child(n.args[0], 2) + " / " + child(n.args[1], 3);
      case Kind::Neg:
        return "-" + child(n.args[0], 3);
      case Kind::Call: {
        std::string s = n.text + "(";
        for (std::size_t i = 0; i < n.args.size(); ++i) s += (i ? ", " : "") + expr_text(n.args[i], names);
        return s + ")";
      }
      case Kind::Select:
        return "(" + child(n.args[0], 1) + " > 0.0 ? " + child(n.args[1], 1) + " : " + child(n.args[2], 1) +
               ")";
    }
    return "?";
  }

  // Emits temporaries for the nodes of `order` that need names; inlines the rest.
  void emit_nodes(std::ostringstream& out, const std::vector<int>& order, const std::vector<int>& roots,
                  const std::string& indent, const std::string& prefix, EmitCounts& counts, bool in_loop) {
    std::map<int, int> uses;
    for (int id : order)
      if (!names_.count(id))
        for (int a : g_.node(id).args) ++uses[a];
    for (int r : roots) ++uses[r];
    for (int id : order) {
      if (names_.count(id)) continue;
      const lir::Node& n = g_.node(id);
      if (n.kind == Kind::Const || n.kind == Kind::Var) continue;
      count(n, counts);
      if (uses[id] < 2 && n.kind != Kind::Call) continue;
      const std::string name = prefix + std::to_string(temp_counter_++);
      out << indent << "const double " << name << " = " << expr_text(id, names_) << ";\n";
      names_[id] = name;
      if (in_loop)
        if (auto c = cached_.find(id); c != cached_.end()) {
          out << indent << "cache[static_cast<std::size_t>(k) * " << cached_.size() << " + " << c->second
              << "] = " << name << ";\n";
          cache_ready_.insert(id);
        }
    }
  }

  void emit_stores(std::ostringstream& out, const Segment& seg, const std::vector<int>& roots,
                   const std::string& indent) {
    for (std::size_t i = 0; i < seg.stores.size(); ++i) {
      const Store& st = seg.stores[i];
      std::string value = expr_text(roots[i], names_);
      std::string line;
      switch (st.mode) {
        case StoreMode::Set:
          line = st.target + " = " + value + ";";
          break;
        case StoreMode::SetNegated:
          line = st.target + " = -" +
                 (names_.count(roots[i]) || precedence(g_.node(roots[i]).kind) >= 3 ? value
                                                                                    : "(" + value + ")") +
                 ";";
          break;
        case StoreMode::Accumulate:
          line = st.target + " += " + value + ";";
          break;
      }
      if (!st.guard.empty()) line = "if (" + st.guard + ") " + line;
      out << indent << line << "\n";
    }
  }

  void emit_segment(std::ostringstream& out, const Segment& seg, const std::vector<int>& roots, std::size_t) {
    for (int sum : seg.accumulators) out << "  double " << prog_.bindings.at(sum).var << " = 0.0;\n";
    for (const std::string& line : seg.before) out << "  " << line << "\n";
    if (!seg.loop) {
      const auto order = reach(roots, [&](int i) { return names_.count(i) > 0; });
      emit_nodes(out, order, roots, "  ", "p", per_family_, false);
      emit_stores(out, seg, roots, "  ");
      return;
    }
    // Hoist: the maximal per-family subexpressions the loop needs.
    std::vector<int> hoisted;
    for (int id : reach(roots, [&](int i) { return names_.count(i) > 0 || !g_.node(i).per_bond; }))
      if (!g_.node(id).per_bond && !names_.count(id)) hoisted.push_back(id);
    const auto family_order = reach(hoisted, [&](int i) { return names_.count(i) > 0; });
    std::vector<int> family_roots;
    for (int id : hoisted) family_roots.push_back(id), family_roots.push_back(id);  // force names
    emit_nodes(out, family_order, family_roots, "  ", "p", per_family_, false);

    std::map<int, std::string> saved = names_;
    std::ostringstream loop;
    // Per-bond calls computed by an earlier loop are read back from the cache.
    std::set<int> in_loop;
    for (int id : reach(roots, [&](int i) { return names_.count(i) > 0 || cache_ready_.count(i) > 0; }))
      in_loop.insert(id);
    for (auto [id, slot] : cached_)
      if (cache_ready_.count(id) && in_loop.count(id)) {
        const std::string name = "b" + std::to_string(temp_counter_++);
        loop << "    const double " << name << " = cache[static_cast<std::size_t>(k) * " << cached_.size()
             << " + " << slot << "];\n";
        names_[id] = name;
      }
    std::set<std::string> loaded;
    const auto order = reach(roots, [&](int i) { return names_.count(i) > 0; });
    for (int id : order) {
      const lir::Node& n = g_.node(id);
      if (n.kind != Kind::Var || !n.per_bond || names_.count(id)) continue;
      const Binding& b = prog_.bindings.at(g_.var_symbols().at(id));
      if (!b.load.empty() && loaded.insert(b.var).second)
        loop << "    const double " << b.var << " = " << b.load << ";\n";
    }
    // Sums over the bonds are split by the generator into kLanes partial sums (bond k adds
    // to lane k mod kLanes), combined in a fixed order after the loop: a horizon sum's
    // accumulator, and each sum into memory
    // (the center's force, forces[c] +=). The lanes of a group of kLanes bonds are
    // independent, so the compiler may compute them side by side in vector registers
    // (`omp simd` on the lane loop) without reassociating anything: no -ffast-math, and
    // every kernel of a law sums in the same order, so the tangent kernel's forces are
    // the residual kernel's to the bit. Without reductions the loop is one `omp simd` loop.
    constexpr int kLanes = 4;
    Segment body = seg;
    std::vector<std::pair<std::string, std::string>> lanes;  // (lane array, target += line prefix)
    std::vector<std::string> reductions;
    for (Store& st : body.stores) {
      if (st.mode != StoreMode::Accumulate) continue;
      if (std::find(reductions.begin(), reductions.end(), st.target + "|" + st.guard) == reductions.end()) {
        reductions.push_back(st.target + "|" + st.guard);
        const std::string lane = "lane" + std::to_string(acc_counter_++);
        lanes.push_back({lane, (st.guard.empty() ? "" : "if (" + st.guard + ") ") + st.target});
      }
      const auto at =
          std::find(reductions.begin(), reductions.end(), st.target + "|" + st.guard) - reductions.begin();
      st.target = lanes[static_cast<std::size_t>(at)].first + "[lane]";
      st.guard.clear();  // a local partial sum: the guard applies where it reaches memory
    }
    emit_nodes(loop, order, roots, "    ", "b", per_bond_, true);
    emit_stores(loop, body, roots, "    ");
    if (lanes.empty()) {
      out << "#pragma omp simd\n  for (int k = 0; k < L; ++k) {\n" << loop.str() << "  }\n";
    } else {
      const std::string K = std::to_string(kLanes);
      for (auto& [lane, target] : lanes) out << "  double " << lane << "[" << K << "] = {};\n";
      // One copy of the body (a kernel computes each call once, also in its text): the
      // last group has fewer than kLanes bonds.
      out << "  for (int k_group = 0; k_group < L; k_group += " << K
          << ") {\n    const int n_lanes = L - k_group < " << K << " ? L - k_group : " << K
          << ";\n#pragma omp simd\n    for (int lane = 0; lane < n_lanes; ++lane) {\n"
          << "      const int k = k_group + lane;\n"
          << loop.str() << "    }\n  }\n";
      for (auto& [lane, target] : lanes)
        out << "  " << target << " += (" << lane << "[0] + " << lane << "[1]) + (" << lane << "[2] + " << lane
            << "[3]);\n";
    }
    // Per-bond temporaries die with the loop; per-family ones stay visible.
    std::map<int, std::string> kept;
    for (auto& [id, name] : names_)
      if (!g_.node(id).per_bond) kept[id] = name;
    for (auto& [id, name] : saved) kept[id] = name;
    names_ = kept;
  }

  const KernelProgram& prog_;
  Graph g_;
  std::map<int, std::string> names_;  // nodes with a visible C++ name
  std::map<int, int> cached_;         // per-bond call -> cache slot
  std::set<int> cache_ready_;
  int temp_counter_ = 0;
  int acc_counter_ = 0;  // partial-sum arrays of the loops' reductions
  EmitCounts per_bond_, per_family_;
};
}  // namespace

EmittedKernel emit_kernel(const KernelProgram& program) { return Printer(program).run(); }

}  // namespace pdgen

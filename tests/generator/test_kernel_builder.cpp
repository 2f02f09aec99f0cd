// The kernel builders (generator/law/kernels.cpp) on small hand-written laws, checked without
// the emitter: a tiny interpreter below runs a KernelProgram's segments over a family of a few
// bonds with pdgen::evaluate, and its outputs are compared with derivatives written out by
// hand in plain C++ (or, for the assembled tangent, with central differences of the same
// plain C++ force). Nothing expected here is produced by the code under test.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <map>
#include <random>
#include <set>
#include <string>
#include <unordered_map>
#include <vector>

#include "../../generator/emit/abi_text.hpp"  // the spelling of the kernels' store targets
#include "pdgen/dsl.hpp"
#include "pdgen/eval.hpp"
#include "pdgen/kernels.hpp"

using namespace pdgen;

namespace {
constexpr int D = 2;  // every law here is 2D
using V2 = std::array<double, D>;

// ---- The plain C++ side: a family and hand-written formulas. ----

struct Bonds {
  std::vector<V2> xi, Y;
  std::vector<double> w, V, sd, sf;  // influence, volume, dilatation factor, force factor
  double V0 = 0.0, delta = 0.0;
  int L() const { return static_cast<int>(xi.size()); }
};

// A family of L bonds, stretched and sheared a little, with every per-bond factor away from 1
// so that forgetting one of them changes the numbers.
Bonds random_family(int L, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0), pos(0.7, 1.3);
  Bonds b;
  for (int k = 0; k < L; ++k) {
    const double angle = 6.283185307179586 * (k + 0.3 * u(rng)) / L, len = 0.4 + 0.5 * pos(rng);
    const V2 xi{len * std::cos(angle), len * std::sin(angle)};
    b.xi.push_back(xi);
    b.Y.push_back({xi[0] * (1.0 + 0.05 * u(rng)) + 0.03 * u(rng) * xi[1],
                   xi[1] * (1.0 + 0.05 * u(rng)) + 0.03 * u(rng) * xi[0]});
    b.w.push_back(pos(rng));
    b.V.push_back(0.1 * pos(rng));
    b.sd.push_back(pos(rng));
    b.sf.push_back(pos(rng));
  }
  b.V0 = 0.1 * pos(rng);
  b.delta = 1.5;
  return b;
}

double dot2(const V2& a, const V2& b) { return a[0] * b[0] + a[1] * b[1]; }
double r_of(const Bonds& b, int k) { return std::sqrt(dot2(b.xi[k], b.xi[k])); }
// Law::deformed_length: sqrt(Y.Y + 1e-16 xi.xi).
double l_of(const Bonds& b, int k) {
  return std::sqrt(dot2(b.Y[k], b.Y[k]) + 1e-16 * dot2(b.xi[k], b.xi[k]));
}

// Nodal forces from force states t_k (kernel_abi.hpp): f_0 = sum_k V0 V_k t_k, f_{k+1} = -V0 V_k t_k,
// laid out as f[node * D + c].
std::vector<double> nodal(const Bonds& b, const std::vector<V2>& t) {
  std::vector<double> f(static_cast<std::size_t>((b.L() + 1) * D), 0.0);
  for (int k = 0; k < b.L(); ++k)
    for (int c = 0; c < D; ++c) {
      f[static_cast<std::size_t>(c)] += b.V0 * b.V[k] * t[k][c];
      f[static_cast<std::size_t>((k + 1) * D + c)] = -b.V0 * b.V[k] * t[k][c];
    }
  return f;
}

// d t_i[r] / d Y_k[c] of a plain force-state function by central differences.
template <class ForceState>
double fd_tangent(const ForceState& t_of, Bonds b, int i, int r, int k, int c) {
  const double h = 1e-6;
  b.Y[k][c] += h;
  const double plus = t_of(b)[i][r];
  b.Y[k][c] -= 2 * h;
  const double minus = t_of(b)[i][r];
  return (plus - minus) / (2 * h);
}

// ---- The kernel side: binding a family to a law's symbols and running a program. ----

struct Family {
  int L = 0;
  std::unordered_map<int, std::vector<double>> bond;  // per-bond symbol -> value at each bond
  std::unordered_map<int, double> particle;           // per-family symbol -> value
};

Family bind_family(const Law& law, const Bonds& b, const std::vector<double>& params) {
  Family f;
  f.L = b.L();
  auto per_bond = [&](Expr sym, auto get) {
    std::vector<double> v;
    for (int k = 0; k < b.L(); ++k) v.push_back(get(k));
    f.bond[symbol_index(sym)] = v;
  };
  for (int c = 0; c < D; ++c) {
    per_bond(law.xi()[c], [&](int k) { return b.xi[k][c]; });
    per_bond(law.Y()[c], [&](int k) { return b.Y[k][c]; });
  }
  per_bond(law.w(), [&](int k) { return b.w[k]; });
  per_bond(law.V(), [&](int k) { return b.V[k]; });
  per_bond(law.alpha(), [](int) { return 1.0; });
  per_bond(law.dilatation_factor(), [&](int k) { return b.sd[k]; });
  per_bond(law.force_factor(), [&](int k) { return b.sf[k]; });
  f.particle[symbol_index(law.V0())] = b.V0;
  f.particle[symbol_index(law.delta())] = b.delta;
  for (std::size_t i = 0; i < params.size(); ++i) f.particle[symbol_index(law.params()[i])] = params[i];
  // One material: a pair parameter is the center's value on every bond.
  for (const PairParamDef& q : law.pair_params())
    per_bond(q.symbol, [&](int) { return params[static_cast<std::size_t>(q.param)]; });
  return f;
}

// A program symbol's index by the C++ variable the program binds it to (symbols the builder
// creates itself: the JVP's dY_c, the tangent's coupling sums).
int symbol_of_var(const KernelProgram& p, const std::string& var) {
  for (const auto& [sym, binding] : p.bindings)
    if (binding.var == var) return sym;
  ADD_FAILURE() << p.name << " binds no variable " << var;
  return -1;
}

struct RunResult {
  std::map<std::string, std::vector<double>> per_bond;  // Set/SetNegated in a loop: target -> value at k
  std::map<std::string, double> totals;                 // accumulated targets and once-per-family sets
  std::unordered_map<int, double> sums;                 // every horizon sum's final value
  double at(const std::string& target, int k) const {
    auto it = per_bond.find(target);
    if (it == per_bond.end()) {
      ADD_FAILURE() << "no per-bond store into " << target;
      return NAN;
    }
    return it->second[static_cast<std::size_t>(k)];
  }
  double total(const std::string& target) const {
    auto it = totals.find(target);
    if (it == totals.end()) {
      ADD_FAILURE() << "no accumulated store into " << target;
      return NAN;
    }
    return it->second;
  }
};

// The meaning of a KernelProgram (kernel_program.hpp), read directly: segments in order, a loop
// segment once per bond with that bond's inputs, accumulators zeroed first, sums accumulated
// into per-family values that later segments read. Guards are taken as satisfied.
RunResult run(const KernelProgram& p, Family fam) {
  RunResult out;
  for (const Segment& seg : p.segments) {
    for (int a : seg.accumulators) fam.particle[a] = 0.0;
    for (int k = 0; k < (seg.loop ? fam.L : 1); ++k) {
      std::unordered_map<int, double> values = fam.particle;
      if (seg.loop)
        for (const auto& [sym, v] : fam.bond) values[sym] = v[static_cast<std::size_t>(k)];
      for (const Store& st : seg.stores) {
        const double v = evaluate(st.value, values);
        if (st.mode == StoreMode::Accumulate) {
          (st.sum >= 0 ? fam.particle[st.sum] : out.totals[st.target]) += v;
        } else {
          const double stored = st.mode == StoreMode::SetNegated ? -v : v;
          if (seg.loop) {
            auto& column = out.per_bond[st.target];
            column.resize(static_cast<std::size_t>(fam.L), NAN);
            column[static_cast<std::size_t>(k)] = stored;
          } else {
            out.totals[st.target] = stored;
          }
        }
      }
    }
  }
  out.sums = fam.particle;
  return out;
}

// Nodal vector `array` (forces, df, a sensitivity column) as the program stored it.
std::vector<double> nodal_output(const RunResult& r, const std::string& array, int L) {
  std::vector<double> f;
  for (int c = 0; c < D; ++c) f.push_back(r.total(abi_text::center_component(array, c)));
  for (int k = 0; k < L; ++k)
    for (int c = 0; c < D; ++c) f.push_back(r.at(abi_text::neighbour_component(array, D, c), k));
  return f;
}

// The assembled tangent block d t_i / d Y_k from the factors (kernel_abi.hpp's TangentFactors):
// delta_ik direct_i + sum_s left_i[s] (x) right_k[s].
double assembled(const RunResult& r, int NS, int i, int row, int k, int col) {
  double v = i == k ? r.at(abi_text::factor_direct(D, row, col), i) : 0.0;
  for (int s = 0; s < NS; ++s)
    v += r.at(abi_text::factor_left(D, NS, s, row), i) * r.at(abi_text::factor_right(D, NS, s, col), k);
  return v;
}

bool close(double a, double b, double tol = 1e-9) { return std::fabs(a - b) <= tol * (1.0 + std::fabs(b)); }

bool stores_into(const KernelProgram& p, const std::string& fragment) {
  for (const Segment& seg : p.segments)
    for (const Store& st : seg.stores)
      if (st.target.find(fragment) != std::string::npos) return true;
  return false;
}

// ---- The laws. ----

// Bond-based spring t = k w s Y/l, s = (l - r)/r, with a parameter it never reads.
Law spring_law() {
  Law law("kb_spring", D, "test");
  const Expr k = law.param("k", 1.0);
  law.param("unused", 2.0);
  const Expr r = norm(law.xi()), l = law.deformed_length();
  law.force(k * law.w() * ((l - r) / r) * law.Y() / l);
  return law;
}
// Its force state with the force factor the builders apply: t = sf k w (1/r - 1/l) Y.
std::vector<V2> spring_t(const Bonds& b, double k) {
  std::vector<V2> t;
  for (int j = 0; j < b.L(); ++j) {
    const double g = b.sf[j] * k * b.w[j] * (1.0 / r_of(b, j) - 1.0 / l_of(b, j));
    t.push_back({g * b.Y[j][0], g * b.Y[j][1]});
  }
  return t;
}

// One state: a weighted volume m (a moment) and a dilatation theta (LPS-like),
//   m = sum w r^2 V,  theta = sum sd 2 w r e V / m,  t = (kappa theta w r / m + mu w e) Y/l,  e = l - r.
Law dilatation_law() {
  Law law("kb_dilatation", D, "test");
  const Expr kappa = law.param("kappa", 1.0), mu = law.param("mu", 1.0);
  const Expr r = norm(law.xi()), l = law.deformed_length(), e = l - r, w = law.w();
  const Expr m = law.sum("m", w * r * r * law.V());
  const Expr theta = law.dilatation_sum("theta", 2 * w * r * e * law.V() / m);
  law.force((kappa * theta * w * r / m + mu * w * e) * law.Y() / l);
  return law;
}
struct DilatationPlain {
  double m = 0.0, theta = 0.0;
};
DilatationPlain dilatation_sums(const Bonds& b) {
  DilatationPlain p;
  for (int j = 0; j < b.L(); ++j) p.m += b.w[j] * r_of(b, j) * r_of(b, j) * b.V[j];
  for (int j = 0; j < b.L(); ++j)
    p.theta += b.sd[j] * 2 * b.w[j] * r_of(b, j) * (l_of(b, j) - r_of(b, j)) * b.V[j] / p.m;
  return p;
}
std::vector<V2> dilatation_t(const Bonds& b, double kappa, double mu) {
  const DilatationPlain s = dilatation_sums(b);
  std::vector<V2> t;
  for (int j = 0; j < b.L(); ++j) {
    const double r = r_of(b, j), l = l_of(b, j);
    const double g = b.sf[j] * (kappa * s.theta * b.w[j] * r / s.m + mu * b.w[j] * (l - r));
    t.push_back({g * b.Y[j][0] / l, g * b.Y[j][1] / l});
  }
  return t;
}

// Two states, the second reading the first: S1 = sum w e V, S2 = sum w V (e - gamma S1 r)^2,
// t = (a S2 + b e) Y/l. dS2/dY_k has a term through S1: the builder's coupling sum.
Law two_state_law() {
  Law law("kb_two_states", D, "test");
  const Expr a = law.param("a", 1.0), b = law.param("b", 1.0), gamma = law.param("gamma", 1.0);
  const Expr r = norm(law.xi()), l = law.deformed_length(), e = l - r, w = law.w();
  const Expr S1 = law.sum("S1", w * e * law.V());
  const Expr S2 = law.sum("S2", w * law.V() * pow(e - gamma * S1 * r, 2));
  law.force((a * S2 + b * e) * law.Y() / l);
  return law;
}
struct TwoStatePlain {
  double S1 = 0.0, S2 = 0.0;
};
TwoStatePlain two_state_sums(const Bonds& b, double gamma) {
  TwoStatePlain p;
  for (int j = 0; j < b.L(); ++j) p.S1 += b.w[j] * (l_of(b, j) - r_of(b, j)) * b.V[j];
  for (int j = 0; j < b.L(); ++j) {
    const double q = l_of(b, j) - r_of(b, j) - gamma * p.S1 * r_of(b, j);
    p.S2 += b.w[j] * b.V[j] * q * q;
  }
  return p;
}
std::vector<V2> two_state_t(const Bonds& b, double a, double bb, double gamma) {
  const TwoStatePlain s = two_state_sums(b, gamma);
  std::vector<V2> t;
  for (int j = 0; j < b.L(); ++j) {
    const double l = l_of(b, j), g = b.sf[j] * (a * s.S2 + bb * (l - r_of(b, j)));
    t.push_back({g * b.Y[j][0] / l, g * b.Y[j][1] / l});
  }
  return t;
}
}  // namespace

// A bond-based law: the tangent is block diagonal. Its direct factor must be the hand
// derivative d/dY [sf k w (1/r - 1/l) Y] = sf k w [(1/r - 1/l) I + Y Y^T / l^3], and there must be
// no state factors and no horizon sums at all (a spurious state would make the form kernel
// assemble off-diagonal neighbour blocks).
TEST(KernelBuilder, BondBasedTangentIsTheHandDerivativeAndHasNoStateTerms) {
  const Law law = spring_law();
  const LawKernelSet ks = build_kernels(law, "kb_spring");
  EXPECT_EQ(ks.n_states, 0);
  EXPECT_EQ(ks.n_moments, 0);
  EXPECT_TRUE(ks.factor_structure.left.empty());
  EXPECT_TRUE(ks.factor_structure.right.empty());
  EXPECT_EQ(ks.factor_structure.direct, std::vector<bool>(D * D, true));  // Y Y^T fills the block
  EXPECT_FALSE(stores_into(ks.tangent, "factors.left"));
  EXPECT_FALSE(stores_into(ks.tangent, "factors.right"));
  for (const Segment& seg : ks.tangent.segments) {
    EXPECT_TRUE(seg.accumulators.empty());
    for (const Store& st : seg.stores) EXPECT_LT(st.sum, 0) << "a sum in a bond-based tangent: " << st.target;
  }

  const double k = 1.7;
  for (unsigned seed : {1u, 2u, 3u}) {
    const Bonds b = random_family(5, seed);
    const RunResult r = run(ks.tangent, bind_family(law, b, {k, 2.0}));
    for (int j = 0; j < b.L(); ++j) {
      const double rr = r_of(b, j), l = l_of(b, j), pre = b.sf[j] * k * b.w[j];
      for (int row = 0; row < D; ++row)
        for (int col = 0; col < D; ++col) {
          const double hand =
              pre * ((row == col ? 1.0 / rr - 1.0 / l : 0.0) + b.Y[j][row] * b.Y[j][col] / (l * l * l));
          EXPECT_TRUE(close(r.at(abi_text::factor_direct(D, row, col), j), hand))
              << "seed " << seed << " bond " << j << " entry " << row << col;
        }
    }
    // The tangent kernel also writes the forces (when asked): they must be the residual's.
    const std::vector<double> expected = nodal(b, spring_t(b, k));
    const std::vector<double> from_tangent = nodal_output(r, "forces", b.L());
    const std::vector<double> from_residual =
        nodal_output(run(ks.residual, bind_family(law, b, {k, 2.0})), "forces", b.L());
    for (std::size_t i = 0; i < expected.size(); ++i) {
      EXPECT_TRUE(close(from_tangent[i], expected[i])) << i;
      EXPECT_TRUE(close(from_residual[i], expected[i])) << i;
    }
  }
}

// The factor structure tells the form kernel which entries it may skip: t = k w (Y - xi) has
// a diagonal direct block, so the off-diagonal entries must be flagged structurally zero (and
// the diagonal ones not, or the form kernel would drop the whole stiffness).
TEST(KernelBuilder, StructurallyZeroDirectEntriesAreFlagged) {
  Law law("kb_linear", D, "test");
  law.force(law.param("k", 1.0) * law.w() * (law.Y() - law.xi()));
  const LawKernelSet ks = build_kernels(law, "kb_linear");
  EXPECT_EQ(ks.factor_structure.dim, D);
  EXPECT_EQ(ks.factor_structure.direct, (std::vector<bool>{true, false, false, true}));
}

// d(nodal forces)/dk of the spring is t/k exactly (t is linear in k); the parameter the force
// never reads must get a column of constant-zero stores, not merely one that evaluates to 0.
TEST(KernelBuilder, SpringSensitivityIsTheHandDerivativeAndZeroForAnUnusedParameter) {
  const Law law = spring_law();
  const LawKernelSet ks = build_kernels(law, "kb_spring");
  const Bonds b = random_family(4, 11);
  const RunResult r = run(ks.sensitivity, bind_family(law, b, {1.7, 2.0}));
  const std::vector<double> hand = nodal(b, spring_t(b, 1.0));  // d t / d k = t(k = 1)
  const std::vector<double> column = nodal_output(r, abi_text::sensitivity_column(D, 0), b.L());
  for (std::size_t i = 0; i < hand.size(); ++i) EXPECT_TRUE(close(column[i], hand[i])) << i;

  const std::string unused = abi_text::sensitivity_column(D, 1);
  int zero_stores = 0;
  for (const Segment& seg : ks.sensitivity.segments)
    for (const Store& st : seg.stores)
      if (st.target.rfind(unused, 0) == 0) {
        EXPECT_TRUE(st.value.is_const(0.0)) << st.target;
        ++zero_stores;
      }
  EXPECT_EQ(zero_stores, 2 * D) << "the unused parameter's column is still written (as zeros)";
}

// A pair parameter (the mean of the two particles' values) moves with the parameter: its
// sensitivity is not zero. t = Q (Y - xi): d t / d p = Y - xi (times sf).
TEST(KernelBuilder, SensitivityFollowsAPairParameter) {
  Law law("kb_pair", D, "test");
  law.force(law.pair_param("k", PairMean::harmonic) * (law.Y() - law.xi()));
  const LawKernelSet ks = build_kernels(law, "kb_pair");
  const Bonds b = random_family(3, 5);
  std::vector<V2> hand;
  for (int j = 0; j < b.L(); ++j)
    hand.push_back({b.sf[j] * (b.Y[j][0] - b.xi[j][0]), b.sf[j] * (b.Y[j][1] - b.xi[j][1])});
  const std::vector<double> expected = nodal(b, hand);
  const std::vector<double> column = nodal_output(run(ks.sensitivity, bind_family(law, b, {0.8})),
                                                  abi_text::sensitivity_column(D, 0), b.L());
  for (std::size_t i = 0; i < expected.size(); ++i) EXPECT_TRUE(close(column[i], expected[i])) << i;
}

// A one-state law: one state (theta), one moment (m), and the three factors written out by
// hand, with u = Y/l and g = kappa theta w r / m + mu w e:
//   direct_i = sf_i [mu w_i u u^T + g_i (I - u u^T) / l_i]
//   left_i   = sf_i kappa w_i r_i / m u_i               (d t_i / d theta)
//   right_k  = sd_k 2 w_k r_k V_k / m u_k               (d theta / d Y_k: the dilatation factor stays)
// and, independently of those formulas, the assembled blocks against central differences of
// the plain force: the chain rule through the sum must couple every pair of bonds.
TEST(KernelBuilder, OneStateLawFactorsAreTheHandDerivatives) {
  const Law law = dilatation_law();
  const LawKernelSet ks = build_kernels(law, "kb_dilatation");
  ASSERT_EQ(ks.n_states, 1);
  ASSERT_EQ(ks.n_moments, 1);
  EXPECT_EQ(ks.state_names, std::vector<std::string>{"theta"});
  EXPECT_EQ(ks.moment_names, std::vector<std::string>{"m"});
  EXPECT_EQ(ks.factor_structure.left, std::vector<bool>(D, true));
  EXPECT_EQ(ks.factor_structure.right, std::vector<bool>(D, true));
  // One state: nothing to couple it to, so the only sum the tangent accumulates is theta.
  const int theta_sym = symbol_index(law.sums()[1].symbol);
  for (const Segment& seg : ks.tangent.segments)
    for (const Store& st : seg.stores)
      if (st.sum >= 0) {
        EXPECT_EQ(st.sum, theta_sym) << st.target;
      }

  const double kappa = 1.3, mu = 0.6;
  const Bonds b = random_family(5, 21);
  const DilatationPlain s = dilatation_sums(b);
  Family fam = bind_family(law, b, {kappa, mu});
  // The moments kernel computes m; the other kernels read it as an input.
  EXPECT_TRUE(close(run(ks.moments, fam).total(abi_text::moment_output(0)), s.m));
  fam.particle[symbol_index(law.sums()[0].symbol)] = s.m;

  const RunResult r = run(ks.tangent, fam);
  EXPECT_TRUE(close(r.sums.at(theta_sym), s.theta));
  for (int j = 0; j < b.L(); ++j) {
    const double rr = r_of(b, j), l = l_of(b, j), e = l - rr;
    const V2 u{b.Y[j][0] / l, b.Y[j][1] / l};
    const double g = kappa * s.theta * b.w[j] * rr / s.m + mu * b.w[j] * e;
    for (int row = 0; row < D; ++row) {
      for (int col = 0; col < D; ++col) {
        const double hand =
            b.sf[j] * (mu * b.w[j] * u[row] * u[col] + g * ((row == col ? 1.0 : 0.0) - u[row] * u[col]) / l);
        EXPECT_TRUE(close(r.at(abi_text::factor_direct(D, row, col), j), hand)) << j << row << col;
      }
      EXPECT_TRUE(
          close(r.at(abi_text::factor_left(D, 1, 0, row), j), b.sf[j] * kappa * b.w[j] * rr / s.m * u[row]))
          << j << row;
      EXPECT_TRUE(close(r.at(abi_text::factor_right(D, 1, 0, row), j),
                        b.sd[j] * 2 * b.w[j] * rr * b.V[j] / s.m * u[row]))
          << j << row;
    }
  }
  const auto t_of = [&](const Bonds& bb) { return dilatation_t(bb, kappa, mu); };
  for (int i = 0; i < b.L(); ++i)
    for (int k = 0; k < b.L(); ++k)
      for (int row = 0; row < D; ++row)
        for (int col = 0; col < D; ++col)
          EXPECT_TRUE(close(assembled(r, 1, i, row, k, col), fd_tangent(t_of, b, i, row, k, col), 1e-6))
              << "block " << i << "," << k << " entry " << row << col;
}

// Sensitivities of the one-state law (theta does not read a parameter, so no derivative sum):
// d t / d kappa = sf theta w r / m u,  d t / d mu = sf w e u.
TEST(KernelBuilder, OneStateLawSensitivitiesAreTheHandDerivatives) {
  const Law law = dilatation_law();
  const LawKernelSet ks = build_kernels(law, "kb_dilatation");
  for (const auto& [sym, binding] : ks.sensitivity.bindings)
    EXPECT_NE(binding.var.rfind("dp", 0), 0u)
        << "a derivative sum for a sum no parameter enters: " << binding.var;
  const Bonds b = random_family(4, 31);
  const DilatationPlain s = dilatation_sums(b);
  Family fam = bind_family(law, b, {1.3, 0.6});
  fam.particle[symbol_index(law.sums()[0].symbol)] = s.m;
  const RunResult r = run(ks.sensitivity, fam);
  std::vector<V2> dkappa, dmu;
  for (int j = 0; j < b.L(); ++j) {
    const double rr = r_of(b, j), l = l_of(b, j);
    const double a = b.sf[j] * s.theta * b.w[j] * rr / s.m, c = b.sf[j] * b.w[j] * (l - rr);
    dkappa.push_back({a * b.Y[j][0] / l, a * b.Y[j][1] / l});
    dmu.push_back({c * b.Y[j][0] / l, c * b.Y[j][1] / l});
  }
  const std::vector<double> hk = nodal(b, dkappa), hm = nodal(b, dmu);
  const std::vector<double> ck = nodal_output(r, abi_text::sensitivity_column(D, 0), b.L());
  const std::vector<double> cm = nodal_output(r, abi_text::sensitivity_column(D, 1), b.L());
  for (std::size_t i = 0; i < hk.size(); ++i) {
    EXPECT_TRUE(close(ck[i], hk[i])) << i;
    EXPECT_TRUE(close(cm[i], hm[i])) << i;
  }
}

// Two states where S2's body reads S1: d S2 / d Y_k = d g2/dY |_k + C d S1 / d Y_k with the
// coupling sum C = sum_j d g2 / d S1 |_j = sum_j -2 gamma w V r (e - gamma S1 r). The builder must
// accumulate exactly that one extra sum, and the assembled tangent must match central
// differences: dropping the coupling term leaves every S2 right factor wrong.
TEST(KernelBuilder, ChainRuleThroughASumThatReadsAnotherSum) {
  const Law law = two_state_law();
  const LawKernelSet ks = build_kernels(law, "kb_two_states");
  ASSERT_EQ(ks.n_states, 2);
  EXPECT_EQ(ks.state_names, (std::vector<std::string>{"S1", "S2"}));
  const int s1 = symbol_index(law.sums()[0].symbol), s2 = symbol_index(law.sums()[1].symbol);
  std::set<int> couplings;
  for (const Segment& seg : ks.tangent.segments)
    for (const Store& st : seg.stores)
      if (st.sum >= 0 && st.sum != s1 && st.sum != s2) couplings.insert(st.sum);
  ASSERT_EQ(couplings.size(), 1u) << "expected one coupling sum C[S2][S1]";
  const int coupling = *couplings.begin();

  const double a = 0.9, bb = 1.4, gamma = 0.7;
  const Bonds b = random_family(5, 41);
  const RunResult r = run(ks.tangent, bind_family(law, b, {a, bb, gamma}));
  const TwoStatePlain s = two_state_sums(b, gamma);
  EXPECT_TRUE(close(r.sums.at(s1), s.S1));
  EXPECT_TRUE(close(r.sums.at(s2), s.S2));
  double C = 0.0;
  for (int j = 0; j < b.L(); ++j) {
    const double rr = r_of(b, j), e = l_of(b, j) - rr;
    C += -2.0 * gamma * b.w[j] * b.V[j] * rr * (e - gamma * s.S1 * rr);
  }
  EXPECT_TRUE(close(r.sums.at(coupling), C));

  const auto t_of = [&](const Bonds& x) { return two_state_t(x, a, bb, gamma); };
  for (int i = 0; i < b.L(); ++i)
    for (int k = 0; k < b.L(); ++k)
      for (int row = 0; row < D; ++row)
        for (int col = 0; col < D; ++col)
          EXPECT_TRUE(close(assembled(r, 2, i, row, k, col), fd_tangent(t_of, b, i, row, k, col), 1e-6))
              << "block " << i << "," << k << " entry " << row << col;
}

// The JVP is the tangent applied to a nodal direction dy (dY_k = dy_{k+1} - dy_0), through the
// states' increments: compared with a central difference of the plain nodal forces along dy.
TEST(KernelBuilder, JvpIsTheDirectionalDerivativeOfTheNodalForces) {
  const Law law = two_state_law();
  const LawKernelSet ks = build_kernels(law, "kb_two_states");
  const double a = 0.9, bb = 1.4, gamma = 0.7;
  const Bonds b = random_family(4, 51);
  std::mt19937 rng(52);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<V2> dy(static_cast<std::size_t>(b.L() + 1));
  for (V2& v : dy) v = {u(rng), u(rng)};
  Family fam = bind_family(law, b, {a, bb, gamma});
  for (int c = 0; c < D; ++c) {
    std::vector<double> inc;
    for (int k = 0; k < b.L(); ++k) inc.push_back(dy[k + 1][c] - dy[0][c]);
    fam.bond[symbol_of_var(ks.jvp, "dY_" + std::to_string(c))] = inc;
  }
  const std::vector<double> df = nodal_output(run(ks.jvp, fam), "df", b.L());
  const double h = 1e-6;
  Bonds plus = b, minus = b;
  for (int k = 0; k < b.L(); ++k)
    for (int c = 0; c < D; ++c) {
      plus.Y[k][c] += h * (dy[k + 1][c] - dy[0][c]);
      minus.Y[k][c] -= h * (dy[k + 1][c] - dy[0][c]);
    }
  const std::vector<double> fp = nodal(plus, two_state_t(plus, a, bb, gamma));
  const std::vector<double> fm = nodal(minus, two_state_t(minus, a, bb, gamma));
  for (std::size_t i = 0; i < df.size(); ++i) EXPECT_TRUE(close(df[i], (fp[i] - fm[i]) / (2 * h), 1e-6)) << i;
}

// Forward-mode sensitivity through a state: only S2 reads gamma, so exactly one derivative sum
// (d S2 / d gamma) is declared, none for a or b; its column is the hand derivative
//   d t / d gamma = sf a (d S2 / d gamma) u,  d S2 / d gamma = sum_j w V 2 (e - gamma S1 r)(-S1 r).
TEST(KernelBuilder, SensitivityThroughAStateIsTheHandDerivative) {
  const Law law = two_state_law();
  const LawKernelSet ks = build_kernels(law, "kb_two_states");
  std::vector<std::string> derivative_sums;
  for (const auto& [sym, binding] : ks.sensitivity.bindings)
    if (binding.var.rfind("dp", 0) == 0) derivative_sums.push_back(binding.var);
  EXPECT_EQ(derivative_sums, std::vector<std::string>{"dp2_S2"});

  const double a = 0.9, bb = 1.4, gamma = 0.7;
  const Bonds b = random_family(4, 61);
  const TwoStatePlain s = two_state_sums(b, gamma);
  double dS2 = 0.0;
  for (int j = 0; j < b.L(); ++j) {
    const double rr = r_of(b, j), e = l_of(b, j) - rr;
    dS2 += b.w[j] * b.V[j] * 2.0 * (e - gamma * s.S1 * rr) * (-s.S1 * rr);
  }
  std::vector<V2> dt, db;
  for (int j = 0; j < b.L(); ++j) {
    const double l = l_of(b, j), e = l - r_of(b, j);
    dt.push_back({b.sf[j] * a * dS2 * b.Y[j][0] / l, b.sf[j] * a * dS2 * b.Y[j][1] / l});
    db.push_back({b.sf[j] * e * b.Y[j][0] / l, b.sf[j] * e * b.Y[j][1] / l});
  }
  const RunResult r = run(ks.sensitivity, bind_family(law, b, {a, bb, gamma}));
  const std::vector<double> hand_gamma = nodal(b, dt), hand_b = nodal(b, db);
  const std::vector<double> col_gamma = nodal_output(r, abi_text::sensitivity_column(D, 2), b.L());
  const std::vector<double> col_b = nodal_output(r, abi_text::sensitivity_column(D, 1), b.L());
  for (std::size_t i = 0; i < hand_gamma.size(); ++i) {
    EXPECT_TRUE(close(col_gamma[i], hand_gamma[i])) << i;
    EXPECT_TRUE(close(col_b[i], hand_b[i])) << i;
  }
}

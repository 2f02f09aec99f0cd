// Finite-difference checks of the generated tangent, block kind by block kind, and the
// balance and finiteness checks, on every family kind.
#include "verify/tangent_check.hpp"

#include <algorithm>
#include <cmath>
#include <random>

#include "verify/balance.hpp"

namespace pd::verify {

double BlockErrors::worst() const { return std::max({center, on_diagonal, off_diagonal, center_coupling}); }

BlockErrors block_errors(const TestFamily& f, const std::vector<double>& M, const std::vector<double>& Mfd) {
  const int d = f.dim, n = f.dofs();
  double err[4] = {0, 0, 0, 0}, scale[4] = {0, 0, 0, 0};
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const int a = i / d, b = j / d;
      const int kind = (a == 0 && b == 0) ? 0 : (a == 0 || b == 0) ? 3 : (a == b ? 1 : 2);
      err[kind] = std::max(err[kind], std::fabs(M[i * n + j] - Mfd[i * n + j]));
      scale[kind] = std::max(scale[kind], std::fabs(Mfd[i * n + j]));
    }
  auto rel = [&](int k) { return scale[k] > 0 ? err[k] / scale[k] : err[k]; };
  return {rel(0), rel(1), rel(2), rel(3)};
}

namespace {
bool all_finite(const std::vector<double>& v) {
  return std::all_of(v.begin(), v.end(), [](double x) { return std::isfinite(x); });
}

FamilyCheck check_family(const abi::LawDescriptor& law, TestFamily& f, std::string description,
                         bool differenced) {
  FamilyCheck c;
  c.description = std::move(description);
  c.bonds = f.bonds();
  c.differenced = differenced;
  const auto M = f.tangent_matrix(law.damaged);
  const int n = f.dofs();
  std::vector<double> dy(static_cast<std::size_t>(n)), df(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) dy[i] = std::sin(1.3 * i + 0.4);
  law.damaged.jvp(f.view(), dy.data(), df.data());
  const auto forces = f.forces(law.damaged);
  c.finite = all_finite(forces) && all_finite(f.forces(law.intact)) && all_finite(M) && all_finite(df);
  if (differenced) {
    c.tangent = block_errors(f, M, f.fd_matrix(law.damaged, 1e-6 * f.delta));
    double err = 0, scale = 0;
    for (int i = 0; i < n; ++i) {
      double v = 0;
      for (int j = 0; j < n; ++j) v += M[i * n + j] * dy[j];
      err = std::max(err, std::fabs(df[i] - v));
      scale = std::max(scale, std::fabs(v));
    }
    c.jvp_error = scale > 0 ? err / scale : err;
  }
  c.momentum_error = momentum_error(f, forces);
  c.angular_momentum_error = angular_momentum_error(f, forces);
  return c;
}
// A law with history: its kernels are those of the incremental problem, the committed
// history held fixed, so the tangent is checked against differences with that history.
// "yielding": a virgin family with the parameters' declared test values (a yield stress
// the random strain exceeds); "committed": the history a first step to one random
// deformation leaves, then a second random deformation (loading on, or unloading, from a
// plastic state: either branch, away from the yield surface with probability 1).
void add_history_checks(const abi::LawDescriptor& law, const FamilyOptions& base,
                        std::vector<FamilyCheck>& out) {
  const char* names[] = {"interior", "free edge", "corner"};
  for (Truncation t : {Truncation::Interior, Truncation::Edge, Truncation::Corner})
    for (bool broken : {false, true}) {
      FamilyOptions o = base;
      o.truncation = t;
      o.broken_bonds = broken;
      const std::string where = std::string(names[static_cast<int>(t)]) + (broken ? ", broken bonds" : "");
      TestFamily virgin = make_family(law, o);
      virgin.use_declared_test_values();
      out.push_back(check_family(law, virgin, where + ", yielding from virgin (test values)", true));
      TestFamily f = make_family(law, o);
      f.use_declared_test_values();
      f.commit_update(law.damaged);
      std::mt19937 rng(base.seed + 7919);  // a second, independent random deformation
      f.set_positions(random_deformation(f, o.strain, std::pow(f.V0, 1.0 / f.dim), rng));
      out.push_back(check_family(law, f, where + ", committed plastic history", true));
    }
}
}  // namespace

std::vector<FamilyCheck> check_law(const abi::LawDescriptor& law, unsigned seed) {
  std::vector<FamilyCheck> out;
  FamilyOptions base;
  base.dim = law.dim;
  base.horizon_ratio = law.dim == 2 ? 3.0 : 2.0;
  base.seed = seed;
  const char* names[] = {"interior", "free edge", "corner"};
  for (Truncation t : {Truncation::Interior, Truncation::Edge, Truncation::Corner})
    for (bool broken : {false, true}) {
      FamilyOptions o = base;
      o.truncation = t;
      o.broken_bonds = broken;
      TestFamily f = make_family(law, o);
      out.push_back(check_family(
          law, f, std::string(names[static_cast<int>(t)]) + (broken ? ", broken bonds" : ""), true));
    }
  // A material interface through the family (neighbours' parameters differ): what a
  // law with pair parameters reads through Family::nbr_params.
  for (Truncation t : {Truncation::Interior, Truncation::Corner}) {
    FamilyOptions o = base;
    o.truncation = t;
    o.broken_bonds = t == Truncation::Corner;
    o.material_jump = true;
    TestFamily f = make_family(law, o);
    out.push_back(check_family(law, f,
                               std::string(names[static_cast<int>(t)]) +
                                   (o.broken_bonds ? ", broken bonds" : "") + ", material jump",
                               true));
  }
  FamilyOptions lattice = base;
  lattice.regular = true;
  TestFamily at_horizon = make_family(law, lattice);
  out.push_back(check_family(law, at_horizon, "lattice, r = delta", true));
  // One neighbour moved onto the center: Y_0 = 0.
  TestFamily collapsed = make_family(law, base);
  std::vector<double> y = collapsed.y;
  for (int c = 0; c < collapsed.dim; ++c) y[collapsed.dim + c] = y[c];
  collapsed.set_positions(y);
  out.push_back(check_family(law, collapsed, "collapsed bond", false));
  if (abi::has_history(law)) add_history_checks(law, base, out);
  return out;
}

bool passes(const abi::LawDescriptor& law, const FamilyCheck& c, const CheckTolerances& tol) {
  if (!c.finite) return false;
  if (c.differenced && !(c.tangent.worst() <= tol.tangent && c.jvp_error <= tol.jvp)) return false;
  if (!(c.momentum_error <= tol.momentum)) return false;
  return !law.balances_angular_momentum || c.angular_momentum_error <= tol.angular_momentum;
}

}  // namespace pd::verify

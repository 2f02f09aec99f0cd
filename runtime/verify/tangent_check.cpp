// Finite-difference checks of the generated tangent, block kind by block kind.
#include "verify/tangent_check.hpp"

#include <algorithm>
#include <cmath>

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

std::vector<FamilyCheck> check_law(const abi::LawDescriptor& law, unsigned seed) {
  std::vector<FamilyCheck> out;
  const char* names[] = {"interior", "free edge", "corner"};
  for (Truncation t : {Truncation::Interior, Truncation::Edge, Truncation::Corner})
    for (bool broken : {false, true}) {
      FamilyOptions o;
      o.dim = law.dim;
      o.truncation = t;
      o.broken_bonds = broken;
      o.horizon_ratio = law.dim == 2 ? 3.0 : 2.0;
      o.seed = seed;
      TestFamily f = make_family(law, o);
      FamilyCheck c;
      c.description = std::string(names[static_cast<int>(t)]) + (broken ? ", broken bonds" : "");
      c.bonds = f.bonds();
      const auto M = f.tangent_matrix(law.damaged);
      c.tangent = block_errors(f, M, f.fd_matrix(law.damaged, 1e-6 * f.delta));
      const int n = f.dofs();
      std::vector<double> dy(static_cast<std::size_t>(n)), df(static_cast<std::size_t>(n));
      for (int i = 0; i < n; ++i) dy[i] = std::sin(1.3 * i + 0.4);
      law.damaged.jvp(f.view(), dy.data(), df.data());
      double err = 0, scale = 0;
      for (int i = 0; i < n; ++i) {
        double v = 0;
        for (int j = 0; j < n; ++j) v += M[i * n + j] * dy[j];
        err = std::max(err, std::fabs(df[i] - v));
        scale = std::max(scale, std::fabs(v));
      }
      c.jvp_error = scale > 0 ? err / scale : err;
      const auto forces = f.forces(law.damaged);
      double total = 0;
      for (int comp = 0; comp < f.dim; ++comp) {
        double s = 0;
        for (int a = 0; a <= f.bonds(); ++a) s += forces[a * f.dim + comp], total += std::fabs(forces[a * f.dim + comp]);
        c.momentum_error = std::max(c.momentum_error, std::fabs(s));
      }
      if (total > 0) c.momentum_error /= total;
      out.push_back(c);
    }
  return out;
}

}  // namespace pd::verify

// Random families for law checks (tests and `pd check-law`): a perturbed lattice neighbourhood of one center
// particle, interior or truncated by a free edge or corner, optionally with broken
// bonds, under a random smooth deformation plus noise.
#pragma once

#include <algorithm>
#include <cmath>
#include <random>
#include <tuple>
#include <utility>
#include <vector>

#include "kernel_abi.hpp"
#include "local_matrix.hpp"

namespace pd::verify {

enum class Truncation { Interior, Edge, Corner };

struct TestFamily {
  int dim = 2;
  std::vector<double> x;  // [(L+1)*dim] reference positions, center first
  std::vector<double> y;  // [(L+1)*dim] deformed positions
  std::vector<double> xi, Y, w, alpha, V, params, moments;
  std::vector<double> nbr_params;  // [L*n_params] the neighbours' parameters; empty: Family::nbr_params null
  // [L*n_history] the committed history (Family::history), the law's initial values until
  // commit_update; empty for a law without history (Family::history null).
  std::vector<double> history;
  // [n_particle_history] the center's committed history (Family::particle_history), likewise.
  std::vector<double> particle_history;
  mutable std::vector<double> kernel_scratch;  // the kernels' Family::scratch, sized on first view()
  double V0 = 1.0, delta = 3.0;
  // Family::time_step: a step a rate-dependent law's test relaxation time (0.7) makes neither
  // instantaneous nor fully relaxed.
  double time_step = 0.3;
  const abi::LawDescriptor* law = nullptr;

  int bonds() const { return static_cast<int>(w.size()); }
  int dofs() const { return (bonds() + 1) * dim; }

  abi::Family view() const {
    abi::Family f;
    f.n_bonds = bonds();
    f.xi = xi.data();
    f.Y = Y.data();
    f.w = w.data();
    f.alpha = alpha.data();
    f.V = V.data();
    f.V0 = V0;
    f.delta = delta;
    f.time_step = time_step;
    f.params = params.data();
    f.nbr_params = nbr_params.empty() ? nullptr : nbr_params.data();
    f.moments = moments.data();
    f.history = history.empty() ? nullptr : history.data();
    f.particle_history = particle_history.empty() ? nullptr : particle_history.data();
    const auto need = static_cast<std::size_t>(bonds() * (law ? law->scratch_per_bond : 0));
    if (kernel_scratch.size() < need) kernel_scratch.resize(need);  // once: a family's bond count is fixed
    f.scratch = kernel_scratch.data();
    return f;
  }
  std::pair<std::vector<double>, std::vector<double>> update(const abi::KernelVariant& v) const {
    std::pair<std::vector<double>, std::vector<double>> out{std::vector<double>(history.size()),
                                                            std::vector<double>(particle_history.size())};
    if (v.update != nullptr)
      v.update(view(), out.first.empty() ? nullptr : out.first.data(),
               out.second.empty() ? nullptr : out.second.data());
    return out;
  }
  void set_positions(const std::vector<double>& positions) {
    y = positions;
    for (int k = 0; k < bonds(); ++k)
      for (int c = 0; c < dim; ++c) Y[k * dim + c] = y[(k + 1) * dim + c] - y[c];
  }
  void update_moments(const abi::KernelVariant& v) {
    moments.assign(static_cast<std::size_t>(law->n_moments) + 1, 0.0);
    v.moments(view(), moments.data());
  }
  // The history at the end of a step to the current positions (the update kernel): per
  // bond, and the center's.
  std::vector<double> updated_history(const abi::KernelVariant& v) const { return update(v).first; }
  std::vector<double> updated_particle_history(const abi::KernelVariant& v) const { return update(v).second; }
  // Commits a step to the current positions: the updated history becomes the committed one.
  void commit_update(const abi::KernelVariant& v) { std::tie(history, particle_history) = update(v); }
  // Gives every parameter the law declares a test value that value (law.param(name, v)),
  // at the center and at the neighbours: e.g. a yield stress the random strains exceed.
  void use_declared_test_values() {
    const int np = law->n_params;
    for (int p = 0; p < np; ++p) {
      if (law->param_test_values == nullptr || std::isnan(law->param_test_values[p])) continue;
      params[static_cast<std::size_t>(p)] = law->param_test_values[p];
      for (std::size_t k = 0; k * np < nbr_params.size(); ++k)
        nbr_params[k * np + p] = law->param_test_values[p];
    }
  }
  std::vector<double> forces(const abi::KernelVariant& v) const {
    std::vector<double> f(static_cast<std::size_t>(dofs()));
    v.residual(view(), f.data());
    return f;
  }
  // d f / d y formed from the kernel's tangent factors by the variant's form kernel (the
  // generic forming when it has none, or when `generic`).
  std::vector<double> tangent_matrix(const abi::KernelVariant& v, bool generic = false) const {
    TangentScratch scratch;
    const auto fac = scratch.view(dim, law->n_states, bonds());
    v.tangent(view(), nullptr, fac);
    std::vector<double> M(static_cast<std::size_t>(dofs() * dofs()));
    if (generic)
      form_local_matrix(dim, law->n_states, view(), fac, M.data());
    else
      form_local_matrix(v, dim, law->n_states, view(), fac, M.data());
    return M;
  }
  // Central differences of the residual in y, column by column.
  std::vector<double> fd_matrix(const abi::KernelVariant& v, double step) {
    const int n = dofs();
    std::vector<double> M(static_cast<std::size_t>(n * n));
    const std::vector<double> y0 = y;
    for (int j = 0; j < n; ++j) {
      std::vector<double> p = y0;
      p[j] += step;
      set_positions(p);
      const auto fp = forces(v);
      p[j] -= 2 * step;
      set_positions(p);
      const auto fm = forces(v);
      for (int i = 0; i < n; ++i) M[i * n + j] = (fp[i] - fm[i]) / (2 * step);
    }
    set_positions(y0);
    return M;
  }
};

struct FamilyOptions {
  int dim = 2;
  double horizon_ratio = 3.0;  // delta / h
  Truncation truncation = Truncation::Interior;
  bool broken_bonds = false;
  // An unperturbed lattice around a center on a lattice point, with weights from
  // `weight`: the horizon_ratio lattice bonds lie at r = delta exactly (the bonds a
  // real grid has, and where a law with 1/(delta - r) is infinite).
  bool regular = false;
  double (*weight)(double r, double delta) = nullptr;  // regular only; null: w = 1
  double strain = 0.05;                                // size of the random displacement gradient
  // A material interface through the family: the neighbours beyond the plane x_0 = x_c
  // + h/2 take parameters 2^(3 u) times the center's (u uniform in [-1, 1], one factor
  // per parameter, at least 3 apart), passed as Family::nbr_params.
  bool material_jump = false;
  unsigned seed = 1;
};

// y = x + H x + noise: a random displacement gradient H of size `strain` and a noise of
// 0.2 strain h per component (h the lattice spacing).
inline std::vector<double> random_deformation(const TestFamily& f, double strain, double h,
                                              std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const int d = f.dim;
  double H[9];
  for (double& e : H) e = strain * u(rng);
  std::vector<double> y(f.x.size());
  for (int a = 0; a <= f.bonds(); ++a)
    for (int r = 0; r < d; ++r) {
      double v = f.x[a * d + r] + 0.2 * strain * h * u(rng);
      for (int c = 0; c < d; ++c) v += H[r * 3 + c] * f.x[a * d + c];
      y[a * d + r] = v;
    }
  return y;
}

inline TestFamily make_family(const abi::LawDescriptor& law, const FamilyOptions& o) {
  std::mt19937 rng(o.seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const int d = o.dim;
  const double h = 0.5 + 0.5 * (u(rng) + 1.0);  // lattice spacing in [0.5, 1.5]
  TestFamily f;
  f.dim = d;
  f.law = &law;
  f.delta = o.horizon_ratio * h;
  f.V0 = std::pow(h, d);
  const double jitter = o.regular ? 0.0 : 1.0;
  for (int c = 0; c < d; ++c) f.x.push_back(jitter * 0.1 * h * u(rng));
  const int n = static_cast<int>(std::ceil(o.horizon_ratio)) + 1;
  for (int i = -n; i <= n; ++i)
    for (int j = -n; j <= n; ++j)
      for (int l = (d == 3 ? -n : 0); l <= (d == 3 ? n : 0); ++l) {
        if (i == 0 && j == 0 && l == 0) continue;
        const int idx[3] = {i, j, l};
        double p[3] = {0, 0, 0}, r2 = 0.0;
        for (int c = 0; c < d; ++c) {
          p[c] = idx[c] * h + jitter * 0.15 * h * u(rng);
          r2 += (p[c] - f.x[c]) * (p[c] - f.x[c]);
        }
        if (r2 > f.delta * f.delta) continue;
        if (o.truncation != Truncation::Interior && p[0] > 0.5 * h) continue;
        if (o.truncation == Truncation::Corner && p[1] > 0.5 * h) continue;
        for (int c = 0; c < d; ++c) f.x.push_back(p[c]);
      }
  const int L = static_cast<int>(f.x.size()) / d - 1;
  f.xi.resize(static_cast<std::size_t>(L * d));
  f.Y.resize(f.xi.size());
  for (int k = 0; k < L; ++k) {
    for (int c = 0; c < d; ++c) f.xi[k * d + c] = f.x[(k + 1) * d + c] - f.x[c];
    double r = 0;
    for (int c = 0; c < d; ++c) r += f.xi[k * d + c] * f.xi[k * d + c];
    const double w = 0.2 + 0.4 * (u(rng) + 1.0);
    f.w.push_back(!o.regular ? w : o.weight ? o.weight(std::sqrt(r), f.delta) : 1.0);
    f.V.push_back(f.V0 * (0.8 + 0.2 * (u(rng) + 1.0)));
    f.alpha.push_back(o.broken_bonds && (k % 4 == 1 || u(rng) > 0.6) ? 0.0 : 1.0);
  }
  for (int p = 0; p < law.n_params; ++p) f.params.push_back(0.5 + 0.5 * (u(rng) + 1.0));
  if (o.material_jump) {
    std::vector<double> other = f.params;
    for (double& v : other) {
      const double e = u(rng);
      v *= std::exp2(3.0 * (e < 0 ? std::min(e, -0.5) : std::max(e, 0.5)));
    }
    for (int k = 0; k < L; ++k) {
      const bool beyond = f.xi[k * d] > 0.5 * h;
      for (int p = 0; p < law.n_params; ++p) f.nbr_params.push_back(beyond ? other[p] : f.params[p]);
    }
  }
  f.set_positions(random_deformation(f, o.strain, h, rng));
  f.update_moments(law.damaged);
  for (int k = 0; k < L; ++k)
    for (int i = 0; i < law.n_history; ++i) f.history.push_back(law.history_initial[i]);
  f.particle_history.assign(law.particle_history_initial,
                            law.particle_history_initial + law.n_particle_history);
  return f;
}

}  // namespace pd::verify

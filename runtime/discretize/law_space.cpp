// Reproducing spaces per law and influence (derivation in law_space.hpp).
#include "discretize/law_space.hpp"

#include <fmt/format.h>

#include <Eigen/Dense>
#include <cmath>
#include <stdexcept>

namespace pd {

namespace {
constexpr int kLowest = -2, kHighest = 6;  // the powers of rho a fit may use

// Least-squares coefficients of rho^k, k in `powers`, through samples of g on `rho`.
Eigen::VectorXd fit(const std::vector<int>& powers, const Eigen::VectorXd& rho, const Eigen::VectorXd& g) {
  Eigen::MatrixXd A(rho.size(), static_cast<int>(powers.size()));
  for (int i = 0; i < rho.size(); ++i)
    for (int k = 0; k < static_cast<int>(powers.size()); ++k) A(i, k) = std::pow(rho[i], powers[k]);
  return A.colPivHouseholderQr().solve(g);
}
}  // namespace

std::vector<RadialPower> influence_power_series(double (*weight)(double r, double delta),
                                                std::string_view name) {
  // Samples at Chebyshev points of [0.05, 1]; the fit is of rho^2 w, a polynomial of
  // degree <= 8 when w is a sum of rho^-2 ... rho^6, which keeps the first fit well posed.
  const int n = 40;
  Eigen::VectorXd rho(n), g(n);
  for (int i = 0; i < n; ++i) {
    rho[i] = 0.525 - 0.475 * std::cos(M_PI * (i + 0.5) / n);
    g[i] = weight(rho[i], 1.0);
  }
  std::vector<int> all;
  for (int k = kLowest; k <= kHighest; ++k) all.push_back(k);
  const Eigen::VectorXd first = fit(all, rho, g);
  // Keep the powers that matter, refit on them alone (well conditioned), then check.
  const double big = first.cwiseAbs().maxCoeff();
  std::vector<int> kept;
  for (int k = 0; k < static_cast<int>(all.size()); ++k)
    if (std::abs(first[k]) > 1e-7 * big) kept.push_back(all[k]);
  const Eigen::VectorXd c = fit(kept, rho, g);
  std::vector<RadialPower> series;
  for (int k = 0; k < static_cast<int>(kept.size()); ++k) series.push_back({c[k], kept[k]});
  auto series_at = [&series](double x) {
    double v = 0;
    for (const RadialPower& t : series) v += t.coefficient * std::pow(x, t.power);
    return v;
  };
  // Verify at other points and another horizon (the ratio must be one constant).
  const double delta2 = 2.7;
  const double scale2 = weight(0.5 * delta2, delta2) / series_at(0.5);
  double worst = 0, size = 0;
  for (int i = 1; i <= 97; ++i) {
    const double x = i / 97.0;
    const double s = series_at(x);
    size = std::max(size, std::abs(s));
    worst = std::max(worst, std::abs(weight(x, 1.0) - s));
    if (std::isfinite(scale2)) worst = std::max(worst, std::abs(weight(x * delta2, delta2) / scale2 - s));
  }
  if (!std::isfinite(scale2) || !(worst <= 1e-11 * size))
    throw std::invalid_argument(
        fmt::format("influence '{}' is not a sum of powers (r/delta)^k, {} <= k <= {} (misfit {:.3g} of "
                    "{:.3g}): the law's "
                    "reproducing space needs its ball moments in closed form; use obq_space: paper001",
                    name, kLowest, kHighest, worst, size));
  return series;
}

ReproducingSpace law_reproducing_space(const abi::LawDescriptor& law, int dim,
                                       double (*weight)(double r, double delta), std::string_view influence) {
  if (law.n_reproducing_groups <= 0)
    throw std::invalid_argument(fmt::format(
        "law '{}': it declares no reproducing space (no law.reproducing_terms in its laws/*.cpp source, so "
        "its descriptor has no reproducing_groups; docs/laws.md); use obq_space: paper001",
        law.name));
  ReproducingSpace space;
  space.dim = dim;
  for (int i = 0; i < law.n_reproducing_groups; ++i) {
    const abi::MonomialGroup& g = law.reproducing_groups[i];
    const std::vector<BondMonomial> t = monomials(dim, g.lowest_degree, g.highest_degree, g.inverse_r_power);
    space.terms.insert(space.terms.end(), t.begin(), t.end());
  }
  std::string radial = std::string(influence);
  if (law.ignores_influence) {
    // The sums carry the kernel built into the law, whatever the scene's influence.
    if (law.kernel_description == nullptr)
      throw std::invalid_argument(fmt::format(
          "law '{}': its force ignores the influence, and it declares no built-in kernel "
          "(law.built_in_kernel "
          "in its laws/*.cpp source; descriptor kernel_terms) for its reproducing space; use obq_space: "
          "paper001",
          law.name));
    for (int i = 0; i < law.n_kernel_terms; ++i)
      space.weight.push_back({law.kernel_terms[i].coefficient, law.kernel_terms[i].power});
    // The constant 1 is the space's empty weight (reproducing_space.hpp).
    if (space.weight.size() == 1 && space.weight[0].coefficient == 1.0 && space.weight[0].power == 0)
      space.weight.clear();
    radial = law.kernel_description;
  } else {
    space.weight = influence_power_series(weight, influence);
  }
  for (const BondMonomial& f : space.terms)
    for (const auto& [c, g] : weighted_term(space, f))
      if (g.degree() - g.inverse_r_power + dim <= 0)
        throw std::invalid_argument(
            fmt::format("law '{}' with influence '{}': its horizon sum of xi^b/|xi|^{} (|b| = {}) is not "
                        "integrable at r = 0 "
                        "in {}D (the continuum law diverges); choose another influence",
                        law.name, influence, g.inverse_r_power, g.degree(), dim));
  space.name = fmt::format("{} with {}", law.name, radial);
  return space;
}

ReproducingSpace law_reproducing_space(std::string_view law, int dim,
                                       double (*weight)(double r, double delta), std::string_view influence) {
  const abi::LawDescriptor* d = abi::find_law(law);
  if (d == nullptr)
    throw std::invalid_argument(
        fmt::format("law '{}': not in the law table (pd laws lists them); no reproducing space", law));
  return law_reproducing_space(*d, dim, weight, influence);
}

}  // namespace pd

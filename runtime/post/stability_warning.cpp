// The zero-energy-mode content of a solution and the warning that names the remedy.
#include "post/stability_warning.hpp"

#include <fmt/core.h>

#include <Eigen/Dense>
#include <cmath>

namespace pd {

namespace {
// One family's residual and total: the least-squares fit eta ~ H xi over the intact bonds.
template <int D>
void family_sums(const Particles& p, const Bonds& b, const std::vector<double>& u, int i, double& residual,
                 double& total, double& weights) {
  using Mat = Eigen::Matrix<double, D, D>;
  using Vec = Eigen::Matrix<double, D, 1>;
  Mat shape = Mat::Zero(), moment = Mat::Zero();
  for (int e = b.offsets[i]; e < b.offsets[i + 1]; ++e) {
    const int j = b.neighbor[e];
    const double weight = b.alpha[e] * b.w[e] * p.volume[j];
    if (weight == 0) continue;
    const Vec xi = Eigen::Map<const Vec>(b.xi.data() + static_cast<std::ptrdiff_t>(e) * D);
    const Vec eta = Eigen::Map<const Vec>(u.data() + static_cast<std::ptrdiff_t>(j) * D) -
                    Eigen::Map<const Vec>(u.data() + static_cast<std::ptrdiff_t>(i) * D);
    shape += weight * xi * xi.transpose();
    moment += weight * eta * xi.transpose();
  }
  // A degenerate (collinear or empty) family: its bonds are left out of both sums. The
  // shape tensor is symmetric positive semi-definite; compare det with trace^D.
  const double scale = std::pow(shape.trace() / D, D);
  if (!(shape.determinant() > 1e-12 * scale)) return;
  const Mat grad = moment * shape.inverse();
  for (int e = b.offsets[i]; e < b.offsets[i + 1]; ++e) {
    const int j = b.neighbor[e];
    const double weight = b.alpha[e] * b.w[e] * p.volume[j] * p.volume[i];
    if (weight == 0) continue;
    const Vec xi = Eigen::Map<const Vec>(b.xi.data() + static_cast<std::ptrdiff_t>(e) * D);
    const Vec eta = Eigen::Map<const Vec>(u.data() + static_cast<std::ptrdiff_t>(j) * D) -
                    Eigen::Map<const Vec>(u.data() + static_cast<std::ptrdiff_t>(i) * D);
    residual += weight * (eta - grad * xi).squaredNorm();
    total += weight * eta.squaredNorm();
    weights += weight;
  }
}
}  // namespace

ZeroEnergyContent zero_energy_content(const Particles& p, const Bonds& b, const std::vector<double>& u) {
  double residual = 0, total = 0, weights = 0, u2 = 0, volume = 0;
  for (int i = 0; i < p.size(); ++i) {
    if (p.dim == 2)
      family_sums<2>(p, b, u, i, residual, total, weights);
    else
      family_sums<3>(p, b, u, i, residual, total, weights);
    for (int c = 0; c < p.dim; ++c)
      u2 += p.volume[i] * u[static_cast<std::size_t>(i) * p.dim + c] *
            u[static_cast<std::size_t>(i) * p.dim + c];
    volume += p.volume[i];
  }
  ZeroEnergyContent c;
  c.ratio = total > 0 ? residual / total : 0;
  c.amplitude = u2 > 0 && weights > 0 ? std::sqrt((residual / weights) / (u2 / volume)) : 0;
  return c;
}

std::string zero_energy_warning(const ZeroEnergyContent& c, const std::string& law) {
  if (!(c.amplitude > zero_energy_warning_amplitude)) return "";
  return fmt::format(
      "  warning: zero-energy modes: the bond deformation the families' deformation gradients do not see has "
      "an rms "
      "{:.2g} of the rms displacement (above {:.2g} the solution is not to be trusted). {} does not resist "
      "these modes "
      "(on a perturbed cloud the load excites them): use a stabilised law "
      "(correspondence_silling_plane_strain with "
      "parameters {{stab: 1}}), an unperturbed lattice, or a dilatation law (docs/stability.md)",
      c.amplitude, zero_energy_warning_amplitude, law);
}

void log_zero_energy_content(const Particles& p, const Bonds& b, const std::vector<double>& u,
                             const std::string& law, const std::function<void(const std::string&)>& log) {
  const ZeroEnergyContent c = zero_energy_content(p, b, u);
  log(
      fmt::format("  zero-energy content: {:.3g} of the bond deformation is not seen by F; its rms {:.3g} of "
                  "the rms displacement",
                  c.ratio, c.amplitude));
  const std::string warning = zero_energy_warning(c, law);
  if (!warning.empty()) log(warning);
}

}  // namespace pd

// G0(s0) of a pairwise law from its energy kernel: bond_fracture_energy.hpp.
#include "damage/bond_fracture_energy.hpp"

#include <fmt/core.h>

#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace pd {

bool is_pairwise_law(const abi::LawDescriptor& law) { return law.n_moments == 0 && law.n_states == 0; }

namespace {
// Pair energy omega(xi, s) of one bond along x, from a family of that single bond.
double pair_energy(const abi::LawDescriptor& law, const std::vector<double>& params, double w, double delta,
                   double r, double s) {
  std::array<double, 3> xi{}, Y{};
  xi[0] = r;
  Y[0] = (1 + s) * r;
  const double one = 1.0;
  abi::Family f;
  f.n_bonds = 1;
  f.xi = xi.data();
  f.Y = Y.data();
  f.w = &w;
  f.alpha = &one;
  f.V = &one;
  f.V0 = 1.0;
  f.delta = delta;
  f.params = params.data();
  return 2 * law.intact.energy(f);  // each of the two families holds half
}
}  // namespace

double pairwise_fracture_energy_per_stretch2(const abi::LawDescriptor& law, const std::vector<double>& params,
                                             double (*weight)(double r, double delta), double delta) {
  if (!is_pairwise_law(law))
    throw std::invalid_argument(
        fmt::format("law {} is state-based (moments or states): its G0(s0) is not a bond sum", law.name));
  if (law.intact.energy == nullptr)
    throw std::invalid_argument(fmt::format("law {} has no energy kernel", law.name));
  // 5-point Gauss-Legendre on 16 equal pieces of (0, delta).
  static constexpr std::array<double, 5> node{0.0, -0.5384693101056831, 0.5384693101056831,
                                              -0.9061798459386640, 0.9061798459386640};
  static constexpr std::array<double, 5> weight5{0.5688888888888889, 0.4786286704993665, 0.4786286704993665,
                                                 0.2369268850561891, 0.2369268850561891};
  constexpr int pieces = 16;
  constexpr double s_ref = 1e-6;
  const double piece = delta / pieces;
  double integral = 0;
  for (int k = 0; k < pieces; ++k)
    for (int q = 0; q < 5; ++q) {
      const double r = piece * (k + 0.5 + 0.5 * node[q]);
      const double w = weight(r, delta);
      const double omega = pair_energy(law, params, w, delta, r, s_ref);
      // omega must be quadratic in s for G0 = s0^2 g: compare with twice the stretch.
      const double omega2 = pair_energy(law, params, w, delta, r, 2 * s_ref);
      if (!(std::fabs(omega2 - 4 * omega) <= 1e-4 * std::fabs(4 * omega) + 1e-300))
        throw std::runtime_error(
            fmt::format("law {}: the bond energy is not quadratic in the stretch at |xi| = {:.6g} "
                        "({:.9g} at s = {:.1e}, {:.9g} at twice that)",
                        law.name, r, omega, s_ref, omega2));
      const double c = 2 * omega / (s_ref * s_ref * r);  // omega = c s^2 xi / 2
      integral += 0.5 * piece * weight5[q] * c *
                  (law.dim == 2 ? std::pow(r, 3) : std::numbers::pi / 2 * std::pow(r, 4));
    }
  return integral;
}

}  // namespace pd

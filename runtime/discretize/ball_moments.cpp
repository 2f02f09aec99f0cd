// Closed-form ball moments (derivation in ball_moments.hpp).
#include "discretize/ball_moments.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace pd {

double BondMonomial::value(int dim, const double* xi, double r) const {
  double v = 1.0;
  for (int c = 0; c < dim; ++c)
    for (int k = 0; k < powers[c]; ++k) v *= xi[c];
  for (int k = 0; k < inverse_r_power; ++k) v /= r;
  for (int k = 0; k > inverse_r_power; --k) v *= r;  // a negative power multiplies
  return v;
}

double sphere_monomial_integral(int dim, const std::array<int, 3>& powers) {
  if (dim != 2 && dim != 3) throw std::invalid_argument("sphere_monomial_integral: dim must be 2 or 3");
  double product = 1.0;
  int total = 0;
  for (int c = 0; c < dim; ++c) {
    if (powers[c] % 2 != 0) return 0.0;  // odd in one coordinate: the sphere's symmetry cancels it
    product *= std::tgamma(0.5 * (powers[c] + 1));
    total += powers[c];
  }
  return 2.0 * product / std::tgamma(0.5 * (total + dim));
}

double ball_moment(int dim, const BondMonomial& f, double delta) {
  const int p = f.degree() - f.inverse_r_power + dim;
  if (p <= 0)
    throw std::invalid_argument("ball_moment: xi^b/|xi|^" + std::to_string(f.inverse_r_power) +
                                " with |b| = " + std::to_string(f.degree()) +
                                " is not integrable at the origin in " + std::to_string(dim) + "D");
  const double angular = sphere_monomial_integral(dim, f.powers);
  return angular == 0.0 ? 0.0 : angular * std::pow(delta, p) / p;
}

}  // namespace pd

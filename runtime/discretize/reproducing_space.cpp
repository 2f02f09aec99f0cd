// Reproducing spaces of the optimisation-based quadrature.
#include "discretize/reproducing_space.hpp"

#include <cmath>
#include <stdexcept>

namespace pd {

std::vector<BondMonomial> monomials(int dim, int min_degree, int max_degree, int inverse_r_power) {
  if (dim != 2 && dim != 3) throw std::invalid_argument("monomials: dim must be 2 or 3");
  std::vector<BondMonomial> out;
  for (int degree = min_degree; degree <= max_degree; ++degree) {
    const int top_z = dim == 3 ? degree : 0;
    for (int bz = 0; bz <= top_z; ++bz)
      for (int by = 0; by + bz <= degree; ++by) {
        const int bx = degree - by - bz;
        if (dim == 2 && bx + by != degree) continue;
        out.push_back(BondMonomial{{bx, by, bz}, inverse_r_power});
      }
  }
  return out;
}

double radial_weight(const ReproducingSpace& space, double rho) {
  if (space.weight.empty()) return 1.0;
  double w = 0;
  for (const RadialPower& t : space.weight) w += t.coefficient * std::pow(rho, t.power);
  return w;
}

std::vector<std::pair<double, BondMonomial>> weighted_term(const ReproducingSpace& space,
                                                           const BondMonomial& f) {
  if (space.weight.empty()) return {{1.0, f}};
  std::vector<std::pair<double, BondMonomial>> out;
  for (const RadialPower& t : space.weight)
    out.push_back({t.coefficient, BondMonomial{f.powers, f.inverse_r_power - t.power}});
  return out;
}

ReproducingSpace paper001_space(int dim) {
  ReproducingSpace space{"paper001 P2 + S_(1/r,2)", dim, monomials(dim, 0, 2, 0), {}};
  const std::vector<BondMonomial> tensor_kernel = monomials(dim, 3, 4, 3);
  space.terms.insert(space.terms.end(), tensor_kernel.begin(), tensor_kernel.end());
  return space;
}

ReproducingSpace paper001_odd_space(int dim) {
  ReproducingSpace space = paper001_space(dim);
  space.name = "paper001 P2 + S_(1/r,2) + xi^5/r^3";
  const std::vector<BondMonomial> odd = monomials(dim, 5, 5, 3);
  space.terms.insert(space.terms.end(), odd.begin(), odd.end());
  return space;
}

}  // namespace pd

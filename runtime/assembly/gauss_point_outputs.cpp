// Gauss-point families: strain energy, per-family energy density, law outputs and stresses.
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include "assembly/gauss_point_assembler.hpp"
#include "assembly/gauss_point_gather.hpp"
#include "assembly/peridynamic_stress.hpp"
#include "local_matrix.hpp"

namespace pd {

double GaussPointAssembler::strain_energy(const double* u) const {
  if (variant_.energy == nullptr)
    throw std::logic_error(std::string("law ") + law_.name + " has no energy kernel");
  const std::vector<double> ug = point_displacements(u);
  std::vector<double> per_family(static_cast<std::size_t>(particles_->size()));
  for_each_family_coloured("strain energy (Gauss points)", [&](Gather& g, int p) -> const char* {
    const abi::Family fam = g.family(p, u, u ? ug.data() : nullptr);
    per_family[p] = fam.V0 * variant_.energy(fam);
    return nullptr;
  });
  // Summed in particle order: the same value for any thread count.
  double total = 0.0;
  for (double e : per_family) total += e;
  return total;
}

double GaussPointAssembler::family_energy_density(int p, const double* u) const {
  if (variant_.energy == nullptr)
    throw std::logic_error(std::string("law ") + law_.name + " has no energy kernel");
  const std::vector<double> ug = point_displacements(u);
  Gather g(*this);
  return variant_.energy(g.family(p, u, u ? ug.data() : nullptr));
}

std::vector<double> GaussPointAssembler::particle_outputs(const double* u) const {
  const int n = particles_->size(), no = law_.n_outputs;
  std::vector<double> out(static_cast<std::size_t>(n) * no, 0.0);
  if (no == 0 || variant_.outputs == nullptr) return out;
  const std::vector<double> ug = point_displacements(u);
  for_each_family_coloured("outputs (Gauss points)", [&](Gather& g, int p) -> const char* {
    variant_.outputs(g.family(p, u, u ? ug.data() : nullptr),
                     out.data() + static_cast<std::ptrdiff_t>(p) * no);
    return nullptr;
  });
  return out;
}

std::vector<double> GaussPointAssembler::family_stresses(const double* u) const {
  const int n = particles_->size(), d = particles_->dim;
  std::vector<double> sigma(static_cast<std::size_t>(n) * d * d, 0.0);
  const std::vector<double> ug = point_displacements(u);
  for_each_family_coloured("stress (Gauss points)", [&](Gather& g, int p) -> const char* {
    double* s = sigma.data() + static_cast<std::ptrdiff_t>(p) * d * d;
    family_stress(variant_.residual, g.family(p, u, u ? ug.data() : nullptr), d, g.local(), s);
    return finite(s, static_cast<std::size_t>(d) * d) ? nullptr : "stress";
  });
  return sigma;
}

}  // namespace pd

// The one choice between the bond-family and the Gauss-point operator, and the checks both make.
#include "assembly/force_operator.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "assembly/assembler.hpp"
#include "assembly/gauss_point_assembler.hpp"

namespace pd {

bool check_law_inputs(const Particles& particles, const abi::LawDescriptor& law,
                      const std::vector<std::vector<double>>& params, const char* who) {
  const std::string prefix = std::string(who) + ": ";
  if (law.dim != particles.dim)
    throw std::invalid_argument(prefix + "law " + law.name + " is " + std::to_string(law.dim) +
                                "D, the body is " + std::to_string(particles.dim) + "D");
  int max_material = -1;
  for (int m : particles.material) max_material = std::max(max_material, m);
  if (max_material >= static_cast<int>(params.size()))
    throw std::invalid_argument(prefix + "material " + std::to_string(max_material) + " has no parameters");
  for (const auto& p : params)
    if (static_cast<int>(p.size()) != law.n_params)
      throw std::invalid_argument(prefix + "law " + law.name + " takes " + std::to_string(law.n_params) +
                                  " parameters, got " + std::to_string(p.size()));
  bool pair_jump = false;
  if (law.uses_pair_params)
    for (int m : particles.material)
      pair_jump = pair_jump || params[static_cast<std::size_t>(m)] !=
                                   params[static_cast<std::size_t>(particles.material[0])];
  return pair_jump;
}

const FamilyAssembler& bond_families(const ForceOperator& op, const char* feature) {
  if (const FamilyAssembler* a = op.bond_families()) return *a;
  throw std::invalid_argument(std::string(feature) +
                              ": runs on bond families only, not over Gauss points (domain.gauss_points)");
}

std::unique_ptr<ForceOperator> make_force_operator(const Particles& particles, const Bonds& bonds,
                                                   const abi::LawDescriptor& law,
                                                   std::vector<std::vector<double>> params,
                                                   const AssemblerOptions& options) {
  if (!options.gauss_points)
    return std::make_unique<FamilyAssembler>(particles, bonds, law, std::move(params), options);
  if (options.collocation)
    throw std::invalid_argument("force operator: Gauss points carry their own weights, not OBQ collocation");
  return std::make_unique<GaussPointAssembler>(particles, *options.gauss_points, law,
                                               options.intact ? law.intact : law.damaged, std::move(params),
                                               options.matrix, options.threads);
}

}  // namespace pd

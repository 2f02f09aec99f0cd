// Families that a law cannot stiffen against some homogeneous strain. A law whose bond
// forces follow bond stretches (bond-based, dilatation, LPS) sees no shear in a family
// whose bonds lie only along the lattice axes (delta/h < sqrt(2) on a square lattice):
// the stiffness is then singular, and the solver would only say "singular matrix".
#pragma once

#include <string>
#include <vector>

#include "assembly/assembler.hpp"

namespace pd {

struct StrainModeReport {
  std::vector<int> blind;   // families with no stiffness against some homogeneous strain
  std::vector<int> non_finite;  // families whose response is inf or NaN (overflowing constants)
  double worst_ratio = 1;  // smallest lambda_min / lambda_max of a family's response Gram matrix
  int worst_particle = -1;
};

// For each family, the law's linearised nodal-force response (the generated tangent-
// vector product at u = 0) to each unit homogeneous strain, and the smallest eigenvalue
// of their Gram matrix relative to the largest: below `tolerance` some combination of
// strains produces no force in that family.
StrainModeReport find_strain_blind_families(const FamilyAssembler& assembler, double tolerance = 1e-12);

// Throws std::runtime_error naming the particles when a family's response is not finite
// (material constants that overflow: "no stiffness" would mislead), and naming the law,
// influence, delta/h and particles when more than half of the families are blind (the body then has a mechanism); returns the
// report otherwise (a few blind families at corners are stiffened by their neighbours').
StrainModeReport check_strain_modes(const FamilyAssembler& assembler, const std::string& influence, double delta_over_h);

}  // namespace pd

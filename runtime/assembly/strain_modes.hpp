// Families that a law cannot stiffen against some homogeneous strain. A law whose bond
// forces follow bond stretches (bond-based, dilatation, LPS) sees no shear in a family
// whose bonds lie only along the lattice axes (delta/h < sqrt(2) on a square lattice):
// the stiffness is then singular, and the solver would only say "singular matrix".
#pragma once

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "assembly/assembler.hpp"

namespace pd {

struct StrainModeReport {
  std::vector<int> blind;       // families with no stiffness against some homogeneous strain
  std::vector<int> non_finite;  // families whose response is inf or NaN (overflowing constants)
  double worst_ratio = 1;       // smallest lambda_min / lambda_max of a family's response Gram matrix
  int worst_particle = -1;
};

// For each family, the law's linearised nodal-force response (the generated tangent-
// vector product at u = 0) to each unit homogeneous strain, and the smallest eigenvalue
// of their Gram matrix relative to the largest: below `tolerance` some combination of
// strains produces no force in that family.
StrainModeReport find_strain_blind_families(const FamilyAssembler& assembler, double tolerance = 1e-12);

// Throws std::runtime_error naming the particles when a family's response is not finite
// (material constants that overflow: "no stiffness" would mislead), and naming the law,
// influence, delta/h and particles when more than half of the families are blind (the body then has a
// mechanism); returns the report otherwise (a few blind families at corners are stiffened by their
// neighbours').
StrainModeReport check_strain_modes(const FamilyAssembler& assembler, const std::string& influence,
                                    double delta_over_h);

// The discrete moduli of particle p's family: its response to the unit homogeneous
// strains eps_k (k over the pairs r <= c: 11, 12, 22 in 2D; 11, 12, 13, 22, 23, 33 in
// 3D; eps_k = (e_r e_c^T + e_c e_r^T) / 2), from the generated tangent-vector product at
// u = 0. `stress` (d*d rows, a*d + b, one column per k) is the family's stress
// sigma = sum_j t_j (x) xi_j V_j, which for a homogeneous deformation is the continuum
// stress (Silling & Lehoucq 2008); with a quadrature exact for the law's horizon sums
// (law_space.hpp) it is the material's C : eps_k. `force` (d rows) is sum_j t_j V_j, zero
// in the continuum. V_j is the family's quadrature weight (the collocation weight under
// obq). Nodal forces are -V0 V_j t_j on neighbour j and +V0 sum_j V_j t_j on the centre
// (kernel_abi.hpp).
struct FamilyModuli {
  Eigen::MatrixXd stress;
  Eigen::MatrixXd force;
};
FamilyModuli family_moduli(const FamilyAssembler& assembler, int p);

}  // namespace pd

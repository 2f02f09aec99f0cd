// The peridynamic stress of paper 002 (section 2, eqs. 2.9-2.13; Silling 2000): the areal
// force density tau(x, n) -- the force per unit area that the material on the + side of a
// plane through x exerts on the material on the - side -- written as tau = sigma n.
//
// For a deformation that is homogeneous over a horizon the line-and-volume integral of
// eq. (2.12) collapses to a horizon sum (substitute x' - x_hat = xi; the line length that
// sees a bond xi is xi . n):
//
//   sigma n = int_{xi . n > 0} f(xi) (xi . n) dV_xi = 1/2 int_H f(xi) (xi . n) dV_xi,
//
// with f the pairwise force density. Per particle i of the discrete body, f_ij =
// t_i<j> - t_j<i> (both families' force states, so the definition holds for every law):
//
//   sigma_i = 1/2 sum_j V_j (t_i<j> - t_j<i>) (outer) xi_ij ,    xi_ij = x_j - x_i
//
// V_j is the quadrature's share of the neighbour (domain.quadrature), as in the forces.
// On a lattice, with n along a lattice axis and the plane halfway between two particle
// layers, this is exactly the discrete eq. (2.12) (a column of x_hat at spacing h, each
// bond xi counted by the (xi . n)/h points of the column that see it) whenever the
// deformation is homogeneous. It is a first Piola-Kirchhoff stress (reference xi and
// reference area). Near a free surface the horizon is cut and sigma_i falls short: that
// is the skin effect the compensation factor of section 3 addresses, not an error here.
#pragma once

#include <vector>

#include "assembly/assembler.hpp"

namespace pd {

// sigma of every particle at displacement u ([n*dim]), row-major per particle:
// [n * dim * dim], sigma_ab at [i*dim*dim + a*dim + b] (a: force component, b: bond
// component), over the bond families (the Gauss families' is GaussPointAssembler::stresses; both are
// ForceOperator::stresses). One residual kernel call per family; t_q<k> comes
// from family q's nodal force on neighbour k (-V_q V_k t_q<k>, kernel_abi.hpp). Throws std::runtime_error
// when a value is not finite (naming the particle).
std::vector<double> peridynamic_stress(const FamilyAssembler& assembler, const double* u);

// The centre's own half of sigma doubled: sum_k V_k t_0<k> (outer) xi_k, from one residual
// call on `family` (forces: scratch of (L+1)*dim doubles; sigma: dim*dim, row-major,
// overwritten). It equals peridynamic_stress at a particle whose neighbours' force states
// mirror its own (t_j<i> = -t_i<j>: a homogeneous deformation, whole families), and needs
// only the one family: the infinite-body studies use it (studies/paper002_stress).
void family_stress(abi::ResidualKernel residual, const abi::Family& family, int dim, double* forces,
                   double* sigma);

}  // namespace pd

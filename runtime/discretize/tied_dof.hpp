// A linear multipoint constraint between dofs, as the discretization makes them (the
// fictitious layers, discretize/fictitious_layer.hpp) and the dof map eliminates them
// (constraints/dof_map.hpp).
#pragma once

#include <vector>

namespace pd {

// u[dof] = sum_k coefficient_k u[master_k] + load * offset (a fictitious-layer particle
// following its mirror image, paper 003 eqs. 29-35). Masters are free or constrained dofs,
// never tied ones.
struct TiedDof {
  int dof = -1;
  std::vector<int> masters;
  std::vector<double> coefficients;
  double offset = 0.0;
};

}  // namespace pd

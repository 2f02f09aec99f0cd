// The stable time step of explicit central-difference (velocity Verlet) integration.
//
// Derivation (paper 003 eq. (20) is garbled in the extracted text; this replaces it).
// Linearise the nodal forces about u: M a = f(u) ~ f(u0) - K du, K = -df/du the
// stiffness (docs/conventions.md), M = diag(m) with m_p = rho_p V_p per component. The
// central-difference scheme is stable for every mode when dt <= 2 / omega_max, with
// omega_max^2 = lambda_max(M^-1 K). M^-1 K is similar to M^-1/2 K M^-1/2, and the
// Gershgorin bound on the rows of M^-1 K gives
//     lambda_max <= max_r (sum_c |K_rc|) / m_r,
// hence dt_crit = 2 / sqrt(max_r S_r / m_r), S_r = sum_c |K_rc|, a bound that needs only
// one assembly of K and holds for any law (state-based couplings included). The block
// (per-particle) form of the theorem gives Silling & Askari's dt = sqrt(2 rho / sum_q
// V_q c / |xi|) for a bond-based law; the row form used here keeps the bond direction
// factors and is 1.27 times larger on the square lattice at delta = 3h, still an
// upper bound on omega_max (docs/dynamics.md derives both and measures the ratio). The
// scene's safety_factor (default 0.8) multiplies it. The same row sums give the fictitious
// density of adaptive dynamic relaxation (dynamic_relaxation.hpp).
#pragma once

#include <vector>

namespace pd {

// The row sums S_r come from ForceOperator::stiffness_row_sums (assembly/force_operator.hpp).

struct StableStep {
  double dt = 0;  // 2 / sqrt(max_r S_r / m_r)
  int dof = -1;   // the dof that sets it
};

// mass: m_r per dof. Throws if no row has stiffness.
StableStep stable_time_step(const std::vector<double>& row_sums, const std::vector<double>& mass);

}  // namespace pd

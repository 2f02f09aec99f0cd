// A cheap after-the-solve check for zero-energy modes in the solution: the part of the
// bond deformations that the family's deformation gradient does not see.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "particles.hpp"

namespace pd {

struct ZeroEnergyContent {
  // Sum over families and intact bonds of V_i alpha w V_j |eta - (F_i - I) xi|^2 over the
  // same sum of |eta|^2 (eta = u_j - u_i; F_i the least-squares deformation gradient of
  // i's family, so the ratio is in [0, 1]): a linear field gives 0. It measures oscillation
  // against the strain, so it is near 1 whenever any grid-scale oscillation is present,
  // even one the probes average out (F, unperturbed lattice, cubic, delta/h 3.5: 0.93).
  double ratio = 0;
  // The rms of that unseen bond deformation (alpha w V-weighted) over the rms
  // displacement: oscillation against the solution itself, what the warning tests.
  double amplitude = 0;
};

ZeroEnergyContent zero_energy_content(const Particles& p, const Bonds& b, const std::vector<double>& u);

// Above this amplitude the solution is dominated by deformations F does not see. Measured
// on confined tension (docs/stability.md): 0.6-1.1 for correspondence_plane_strain on
// clouds perturbed by 0.05 and 0.2 at delta/h 3, 0.016-0.03 unperturbed, 0.006-0.012 for
// the stabilised law on the same clouds; it misses the perturbed delta/h = 1.5 cubic 20^2
// case (0.097, probe error 240 %), which the documented table lists.
inline constexpr double zero_energy_warning_amplitude = 0.2;

// The warning line for a run (empty when the amplitude is below the threshold); it names
// the remedy, a stabilised variant of the law.
std::string zero_energy_warning(const ZeroEnergyContent& c, const std::string& law);

// Measures the content of a solved u and logs it, and the warning when there is one.
void log_zero_energy_content(const Particles& p, const Bonds& b, const std::vector<double>& u,
                             const std::string& law, const std::function<void(const std::string&)>& log);

}  // namespace pd

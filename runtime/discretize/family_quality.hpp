// Checks on the families before any solve: a weighted volume that is (nearly) zero or a
// (nearly) singular shape tensor makes the laws divide by zero or invert a singular
// matrix, and the NaN would surface only inside the solver. Tiny horizons (delta/h
// close to 1) and influence functions that vanish at r = delta or blow up at r = 0
// (inv, rational n = 2) are where this happens.
#pragma once

#include <string>

#include "particles.hpp"

namespace pd {

struct FamilyQualityLimits {
  // m_p = sum alpha w |xi|^2 V relative to the same sum over a full ball in the
  // continuum, 2 pi int_0^delta w r^3 dr (3D: 4 pi int w r^4 dr). A full interior
  // family has about 1, a corner about 1/4; below this the family carries no weight.
  double min_weighted_volume_ratio = 1e-3;
  // Condition number of the shape tensor K_p = sum alpha w xi (x) xi V: above this the
  // family cannot resolve every direction of deformation (collinear or one-sided bonds),
  // and F = N K^-1 (correspondence) or the stiffness (every law) is singular.
  double max_shape_condition = 1e8;
};

struct FamilyQualityReport {
  int worst_weighted_volume_particle = -1;
  double worst_weighted_volume_ratio = 0;
  int worst_condition_particle = -1;
  double worst_condition = 0;
};

// Throws std::runtime_error naming the influence function, delta/h and the particles
// (index, position, intact bonds) whose families fail a limit; returns the worst values.
FamilyQualityReport check_family_quality(const Particles& particles, const Bonds& bonds,
                                         double (*influence)(double, double),
                                         const std::string& influence_name, double h,
                                         const FamilyQualityLimits& limits = {});

// The continuum weighted volume of a full ball of radius delta (the denominator above).
double continuum_weighted_volume(double (*influence)(double, double), double delta, int dim);

}  // namespace pd

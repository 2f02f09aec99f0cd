// Smoothing of a nodal field with an influence function (paper 000 eq. 49).
#pragma once

#include <vector>

#include "input/smoothing_influence.hpp"  // InfluenceWeight, can_smooth_with: what smooth_field accepts
#include "particles.hpp"

namespace pd {

// The discrete form of paper 000 eq. (49),
//   u_s(x_i) = sum_j w(|x_j - x_i|) u_j V_j / sum_j w(|x_j - x_i|) V_j,
// where j runs over the horizon of x_i *including x_i itself* (the integral is over the
// whole ball H_x, whose centre is a material point like any other) and over intact
// bonds only: a crack face separates material, so averaging across it would smear the
// very opening the field error measures. `field` holds `components` values per
// particle. Throws std::invalid_argument when w(0) is not finite (inv, rational n > 0):
// the self term of eq. (49) is then undefined.
std::vector<double> smooth_field(const Particles& particles, const Bonds& bonds, InfluenceWeight w,
                                 const std::vector<double>& field, int components);

}  // namespace pd

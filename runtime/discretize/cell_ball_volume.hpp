// The exact volume of a cubic cell inside a ball: the 3D `partial_exact` volume factor of
// paper 002 (the 2D one is cell_disc_area, partial_volume.hpp).
//
// Closed form, no quadrature. Let F(a, b, c) be the volume of the ball |p| <= R beyond a
// corner, {x > a, y > b, z > c}. The box [x0,x1]x[y0,y1]x[z0,z1] is the inclusion-exclusion
// sum over its 8 corners, sum (-1)^(number of upper coordinates) F(corner). A negative
// coordinate is reflected away, F(-a, b, c) = Q(b, c) - F(a, b, c) with Q(b, c) the volume
// beyond the edge {y > b, z > c} (and likewise Q from the cap beyond a plane), so only
// a, b, c >= 0 is needed. There, with X = sqrt(R^2 - b^2 - c^2) and ρ^2 = R^2 - x^2,
//   F = int_a^X q(x) dx,  q = ρ^2/2 (π/2 - asin(b/ρ) - asin(c/ρ)) - b sqrt(ρ^2-b^2)/2
//                             - c sqrt(ρ^2-c^2)/2 + bc
// (q is the disc-of-radius-ρ area beyond the 2D corner (b, c), one formula on all of
// [a, X]), and every term of q has an elementary antiderivative (atan2 terms; the formula
// is in cell_ball_volume.cpp). No truncation error; rounding grows like eps (R/h)^3 of h^3
// because the corner terms are of size R^3: the worst of 20000 cut cells against a long
// double evaluation was 3e-14 h^3 at R/h = 3, 1.3e-13 at 5, 8e-13 at 10. About 0.6 us a cell.
#pragma once

namespace pd {

// Volume of the cube of side h centred at c (3 coordinates) inside the ball of radius
// delta about the origin. Exactly h^3 for a cell inside, 0 for one outside, 4/3 π delta^3
// when the ball is inside the cell; otherwise clamped to [0, h^3].
double cell_ball_volume(const double* c, double delta, double h);

}  // namespace pd

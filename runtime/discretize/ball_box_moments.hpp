// Moments of a ball cut by the faces of a rectangle (2D): the right-hand sides of the
// optimisation-based quadrature (paper 001 eq. 2.12) for a family near a free surface,
// whose bonds cover only B_delta(x) ∩ Omega. Integrating there -- and not over the whole
// ball, which a half-ball family can only reach by extrapolation -- is what paper 001's
// dilatation correction (eqs. 3.2-3.3) and its free-surface problems integrate over.
//
// In polar coordinates about the centre, the integrand xi^b / |xi|^s separates:
//     I[f] = int_0^{2 pi} n(t)^b R(t)^p / p dt,   p = |b| - s + 2,
// with R(t) = min(delta, the distance along n(t) to the nearest face ahead). R is smooth
// between the angles where a face starts or stops cutting the circle and the corner
// angles, so Gauss-Legendre on each of those arcs is exact to rounding with 24 points.
#pragma once

#include "discretize/ball_moments.hpp"

namespace pd {

struct Box2 {
  double lo[2] = {0, 0}, hi[2] = {0, 0};
};

// int_{B_delta(center) ∩ box} f(y - center) dy for a centre inside the box.
double ball_box_moment_2d(const BondMonomial& f, double delta, const double* center, const Box2& box);

// True when the ball B_delta(center) lies inside the box (the closed-form ball moment holds).
bool ball_inside_box(double delta, const double* center, const Box2& box);

// int over the part of B_delta(center) that the centre sees past a disk (disk centre
// `disk`, radius a, the centre outside it) of f(y - center) dy: the points y whose segment
// from the centre does not meet the disk, which are the bonds a hole leaves intact when it
// breaks every bond crossing its circle (paper 001 §4.2). Polar form as above, with R(t)
// the distance to the circle where the ray meets it; Gauss-Legendre on the arcs between
// the tangent directions and the circle's crossings of the horizon, in a variable that
// smooths R's square-root edge at a tangent.
double ball_disk_shadow_moment_2d(const BondMonomial& f, double delta, const double* center,
                                  const double* disk, double a);

}  // namespace pd

// Bond volume factors of paper 002: how much of a neighbour's cell lies inside the
// horizon. The factor multiplies the neighbour's volume in V[k] (family_gather), so the
// moments, the force, the tangent and the JVP all see the same quadrature.
#pragma once

#include "input/quadrature.hpp"
#include "particles.hpp"

namespace pd {

// Eq. (2.16)/(3.4) of paper 002: 1 up to delta - h/2, falling linearly to 0 at delta + h/2.
double linear_volume_factor(double r, double delta, double h);

// Exact area of the square cell of side h centred at (cx, cy) inside the disc of radius
// delta about the origin (closed form: the disc's chord integrated between breakpoints).
double cell_disc_area(double cx, double cy, double delta, double h);

// The distance from the origin to the nearest point of the cell of side h centred at c:
// the cell meets the horizon when it is below delta (paper 002 §2.4.1).
double cell_distance(const double* c, int dim, double h);

// The bond search radius a quadrature needs: delta for `volume`, delta + h/2 for the
// linear factor, the cell's half-diagonal beyond delta for the exact intersection.
double quadrature_reach(Quadrature q, double delta, double h, int dim);

// The share of the neighbour's cell (centre xi from the source, side h) the bond carries.
double volume_factor(Quadrature q, const double* xi, int dim, double delta, double h);

// Bonds for a quadrature: find_bonds for `volume`; otherwise the search out to
// quadrature_reach, the factor on every bond (bonds with factor 0 left out), and the
// influence weight of a neighbour beyond delta taken at delta -- the weight at the
// horizon, so a function that vanishes there gives the outer sliver no weight.
Bonds find_quadrature_bonds(const Particles& p, double delta, double h, Quadrature q,
                            double (*influence)(double r, double delta));

}  // namespace pd

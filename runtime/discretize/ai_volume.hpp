// The adaptive integration (AI) of paper 002 §2.4: the volume of a neighbour's cubic
// cell inside the source's horizon sphere by nested composite trapezoid rules
// (eqs. 2.41-2.51), refined until a combined relative-absolute test passes.
//
// The paper classifies the cell-sphere intersections into 3 + 18 configurations
// (Table 2.1) so that each part's integration limits are smooth functions. Here the same
// parts come from one rule: an interval is cut wherever its inner limits change form --
// X where the sphere's cross-section passes a cell edge or corner
// (R^2 - X^2 = a^2 + b^2, a a face or the axis in Y, b likewise in Z), Y where the chord
// passes a face in Z. Every configuration of Table 2.1 is one pattern of these cuts.
#pragma once

namespace pd {

// The paper's TOL (the switch from relative to absolute error), and the prescribed
// accuracy EPS used by the runtime; both on the volume as a fraction of the cell's.
constexpr double kAiTol = 1e-4;
constexpr double kAiEps = 1e-4;

struct AiResult {
  double volume = 0;  // cell volume inside the sphere
  long points = 0;    // integration points of the last (accepted) refinement
  int index = 0;      // trapezoidal index n of that refinement (M = 2^(n-1) subintervals)
};

// Cell of side h centred at c (3 coordinates, relative to the source) against the sphere
// of radius delta about the origin. A cell entirely inside takes one trapezoid step
// (n = 1, 8 points: exact for a constant); entirely outside gives 0 and no points.
AiResult ai_cell_ball_volume(const double* c, double delta, double h, double eps);

}  // namespace pd

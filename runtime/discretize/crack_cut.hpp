// Bond cutting by pre-cracks: which bonds a crack segment (2D) or polygon (3D) breaks.
#pragma once

#include <vector>

#include "input/scene.hpp"
#include "particles.hpp"

namespace pd {

// Geometric ties are decided with a tolerance of tie_tolerance x |xi| (the bond's length),
// never by the sign of a rounded zero: a particle closer than that to a crack's line is on
// it (on neither side, so its bonds along the crack stay intact), and a bond whose
// crossing point is that close to a 2D crack tip passes through the tip and follows the
// crack's `tips` rule (cut or kept). Mirror-image bonds then get the same answer.
inline constexpr double tie_tolerance = 1e-9;

// Whether the segment from xa to xb crosses the crack (a segment in 2D, a planar
// polygon in 3D) under the rules above. cut_bonds passes the lower-indexed particle as xa.
bool crack_crosses(const Crack& crack, const double* xa, const double* xb, int dim);

// Sets alpha = 0 on every bond whose segment crosses a crack. Returns the count of
// broken bonds (each counted once per direction).
int cut_bonds(const std::vector<Crack>& cracks, const Particles& p, Bonds& bonds);
// The same, also counting per crack the bond directions it crosses (cut by it or already
// cut by an earlier crack): a crack that crosses none has no effect.
int cut_bonds(const std::vector<Crack>& cracks, const Particles& p, Bonds& bonds,
              std::vector<int>* crossed_per_crack);

}  // namespace pd

// Influence functions the smoothing accepts (smoothing_influence.hpp).
#include "input/smoothing_influence.hpp"

#include <cmath>

namespace pd {

bool can_smooth_with(InfluenceWeight w) {
  // The weights scale with delta only through r/delta (or a power of delta that the
  // ratio in eq. 49 cancels), so delta = 1 decides.
  const double w0 = w(0.0, 1.0);
  return std::isfinite(w0) && w0 > 0;
}

}  // namespace pd

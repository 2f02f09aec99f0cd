// Which influence functions the smoothing of paper 000 eq. (49) can use: the scene reader
// refuses the others naming the key (output.smoothing.influence), post/smoothing.cpp
// refuses them in code.
#pragma once

namespace pd {

using InfluenceWeight = double (*)(double r, double delta);

// True when w(0, delta) is finite and positive: eq. (49) weights each particle itself by w(0).
bool can_smooth_with(InfluenceWeight w);

}  // namespace pd

// The analytic value a probe's mean displacement is compared with (paper 000 eq. 36), at
// the point the probe's `reference_at` names.
#pragma once

#include <string>
#include <vector>

#include "fields/analytic.hpp"
#include "input/scene.hpp"
#include "particles.hpp"

namespace pd {

// The point of `reference_at: region` (the default): the centre of a box region, moved onto
// the domain face the box reaches (when it does not also reach the opposite one), or the
// centre of a side region's face -- where paper 000 measures (eq. 36: the analytic
// displacement at y = H for the top probe, whatever rows the particles sit on).
// Throws SceneError naming the probe for regions without one (all, outside, collar).
Point probe_region_point(const Probe& probe, const Scene& scene);

// The reference of one probe over its particles `ids`: the analytic field at the region
// point, at the probe's explicit point, or (`reference_at: particles`) its mean over the
// particles themselves.
double probe_reference(const Probe& probe, const AnalyticField& field, const std::vector<int>& ids,
                       const Particles& p, const Scene& scene);

}  // namespace pd

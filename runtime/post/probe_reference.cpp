// Where a probe's analytic reference is taken: the region's point (the paper's), an explicit
// point, or the mean over the probe's particles.
#include "post/probe_reference.hpp"

#include <algorithm>

#include "input/yaml_keys.hpp"

namespace pd {

Point probe_region_point(const Probe& probe, const Scene& s) {
  const Region& r = probe.region;
  Point x{};
  if (r.kind == Region::Kind::Box) {
    // A box reaching a face of the domain (and not the opposite one) measures on the face:
    // the paper's top probe is at y = H even when the particles' top row is at H - h/2.
    for (int c = 0; c < s.dim; ++c) {
      const bool low = r.min[c] <= s.lo[c], high = r.max[c] >= s.hi[c];
      x[c] = high && !low ? s.hi[c] : low && !high ? s.lo[c] : 0.5 * (r.min[c] + r.max[c]);
    }
    return x;
  }
  if (r.kind == Region::Kind::Side) {
    // The middle of the face, or of its part `within` selects; then onto the face itself.
    for (int c = 0; c < 3; ++c)
      x[c] = r.has_within ? 0.5 * (std::max(s.lo[c], r.within_min[c]) + std::min(s.hi[c], r.within_max[c]))
                          : 0.5 * (s.lo[c] + s.hi[c]);
    const Region::Side side = r.side;
    if (side == Region::Side::left)
      x[0] = s.lo[0];
    else if (side == Region::Side::right)
      x[0] = s.hi[0];
    else if (side == Region::Side::bottom)
      x[1] = s.lo[1];
    else if (side == Region::Side::top)
      x[1] = s.hi[1];
    else if (side == Region::Side::back)
      x[2] = s.lo[2];
    else if (side == Region::Side::front)
      x[2] = s.hi[2];
    return x;
  }
  throw SceneError(
      probe.where +
      ": reference_at: region needs a box or side region; give reference_at: particles or a point");
}

double probe_reference(const Probe& probe, const AnalyticField& field, const std::vector<int>& ids,
                       const Particles& p, const Scene& scene) {
  const int c = probe.component;
  switch (probe.reference_at) {
    case Probe::ReferenceAt::region:
      return field.displacement(probe_region_point(probe, scene).data())[c];
    case Probe::ReferenceAt::point:
      return field.displacement(probe.reference_point.data())[c];
    case Probe::ReferenceAt::particles:
      break;
  }
  double sum = 0;
  for (int i : ids) sum += field.displacement(p.position(i))[c];
  return sum / static_cast<double>(ids.size());
}

}  // namespace pd

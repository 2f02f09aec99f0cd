// Point-in-shape and point-in-region tests for scenes.
#include <cmath>

#include "input/scene.hpp"

namespace pd {

bool Shape::contains(const double* x, int dim) const {
  switch (kind) {
    case Kind::Circle: {
      double r2 = 0;
      for (int i = 0; i < dim; ++i) r2 += (x[i] - center[i]) * (x[i] - center[i]);
      return r2 <= radius * radius;
    }
    case Kind::Box:
      for (int i = 0; i < dim; ++i)
        if (x[i] < min[i] || x[i] > max[i]) return false;
      return true;
    case Kind::Polygon: {  // even-odd rule
      bool inside = false;
      const std::size_t n = vertices.size();
      for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
        const Point& a = vertices[i];
        const Point& b = vertices[j];
        if ((a[1] > x[1]) != (b[1] > x[1]) && x[0] < (b[0] - a[0]) * (x[1] - a[1]) / (b[1] - a[1]) + a[0])
          inside = !inside;
      }
      return inside;
    }
  }
  return false;
}

bool Region::contains(const double* x, int dim, const Point& lo, const Point& hi, double h) const {
  if (has_within)
    for (int i = 0; i < dim; ++i)
      if (x[i] < within_min[i] || x[i] > within_max[i]) return false;
  switch (kind) {
    case Kind::All:
      return true;
    case Kind::Side: {
      const double t = thickness > 0 ? thickness : 0.5 * h;  // default: the outermost row
      const int axis = (side == Side::left || side == Side::right)   ? 0
                       : (side == Side::bottom || side == Side::top) ? 1
                                                                     : 2;
      if (axis >= dim) return false;
      const bool low = side == Side::left || side == Side::bottom || side == Side::back;
      return low ? x[axis] <= lo[axis] + t : x[axis] >= hi[axis] - t;
    }
    case Kind::Box:
    case Kind::Outside: {
      bool in = true;
      for (int i = 0; i < dim; ++i) in = in && x[i] >= min[i] && x[i] <= max[i];
      return kind == Kind::Box ? in : !in;
    }
    case Kind::Collar: {
      bool near = false;
      for (int i = 0; i < dim; ++i) near = near || x[i] - lo[i] < thickness || hi[i] - x[i] < thickness;
      return near;
    }
  }
  return false;
}

}  // namespace pd

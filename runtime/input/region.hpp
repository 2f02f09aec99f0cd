// Points and regions of a scene: where a boundary condition, probe or initial condition applies.
#pragma once

#include <array>

#include "input/enum_names.hpp"

namespace pd {

using Point = std::array<double, 3>;

// Where a boundary condition or probe applies.
struct Region {
  // Collar: the particles whose family the domain box truncates, `horizons` deep (1: the
  // particles with a missing neighbour within delta) -- a Dirichlet collar that keeps one
  // horizon thick when a study refines h or changes delta/h.
  enum class Kind { All, Side, Box, Outside, Collar } kind = Kind::All;
  enum class Side { left, right, bottom, top, back, front } side = Side::left;  // back, front: 3D
  double thickness = 0;  // Side: depth into the body; 0 = half a spacing (the outermost row).
                         // Collar: depth from the box faces, set from `horizons` by region_particles
  double horizons = 0;   // Collar: depth in horizons
  Point min{}, max{};    // Box / Outside (the complement of the box)
  // Optional `within: {min, max}`: only the region's particles inside this box (the middle
  // of a side, whatever the placement puts its outermost row).
  bool has_within = false;
  Point within_min{}, within_max{};
  // True when a particle at x belongs (domain bounds lo/hi, spacing h).
  bool contains(const double* x, int dim, const Point& lo, const Point& hi, double h) const;
};
template <>
struct enum_names<Region::Side> {
  static constexpr std::array<EnumName<Region::Side>, 6> table{{{Region::Side::left, "left"},
                                                                {Region::Side::right, "right"},
                                                                {Region::Side::bottom, "bottom"},
                                                                {Region::Side::top, "top"},
                                                                {Region::Side::back, "back"},
                                                                {Region::Side::front, "front"}}};
};

}  // namespace pd

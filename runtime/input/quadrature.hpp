// The quadrature of the horizon integral: how much of each neighbour's volume a bond
// carries (docs/scene_format.md, `domain.quadrature`). A property of the discretisation:
// the kernels see it only through the per-bond volume V[k] (and, for weights that are
// not symmetric, through the assembly of eq. 2.13 of paper 001).
#pragma once

#include <array>

#include "input/enum_names.hpp"

namespace pd {

enum class Quadrature {
  Volume,         // a neighbour counts with its whole volume when its centre is inside the horizon
  PartialLinear,  // paper 002 eq. (2.16): the share falls linearly from delta - h/2 to delta + h/2
  PartialExact,   // paper 002 §2.4: the exact cell-horizon overlap (closed form 2D, adaptive 3D)
  Obq,     // per-family least-norm weights exact for paper 001's reproducing space, collocation assembly
  ObqCut,  // the same, a family cut by a face of the body's box integrating over the cut ball (free surfaces)
};

// Either OBQ choice.
inline bool is_obq(Quadrature q) { return q == Quadrature::Obq || q == Quadrature::ObqCut; }

// The scene spelling of each choice, in the order of the enum.
template <>
struct enum_names<Quadrature> {
  static constexpr std::array<EnumName<Quadrature>, 5> table{{{Quadrature::Volume, "volume"},
                                                              {Quadrature::PartialLinear, "partial_linear"},
                                                              {Quadrature::PartialExact, "partial_exact"},
                                                              {Quadrature::Obq, "obq"},
                                                              {Quadrature::ObqCut, "obq_cut"}}};
};

}  // namespace pd

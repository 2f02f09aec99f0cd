// The quadrature of the horizon integral: how much of each neighbour's volume a bond
// carries (docs/scene_format.md, `domain.quadrature`). A property of the discretisation:
// the kernels see it only through the per-bond volume V[k] (and, for weights that are
// not symmetric, through the assembly of eq. 2.13 of paper 001).
#pragma once

#include <array>
#include <vector>

#include "input/enum_names.hpp"

namespace pd {

enum class Quadrature {
  Volume,         // a neighbour counts with its whole volume when its centre is inside the horizon
  PartialLinear,  // paper 002 eq. (2.16): the share falls linearly from delta - h/2 to delta + h/2
  PartialExact,   // paper 002 §2.4: the exact cell-horizon overlap (closed form 2D, adaptive 3D)
  Obq,     // per-family least-norm weights exact for paper 001's reproducing space, collocation assembly
  ObqCut,  // the same, a family cut by a face of the body's box integrating over the cut ball (free surfaces)
};

// The scene spelling of each choice, in the order of the enum.
template <>
struct enum_names<Quadrature> {
  static constexpr std::array<EnumName<Quadrature>, 5> table{{{Quadrature::Volume, "volume"},
                                                              {Quadrature::PartialLinear, "partial_linear"},
                                                              {Quadrature::PartialExact, "partial_exact"},
                                                              {Quadrature::Obq, "obq"},
                                                              {Quadrature::ObqCut, "obq_cut"}}};
};

// What each rule is and what it goes with: the one table that the scene reader's
// compatibility checks (input/read_domain.cpp, input/block_domain.cpp), the model's first
// phase (model/model.cpp), the dynamic driver (run/dynamic_run.cpp) and the test
// QuadratureRules (which also holds docs/scene_format.md to it) read. A rule's mechanism --
// its bonds' reach and volume share, its weights -- lives in discretize/ and assembly/.
struct QuadratureRule {
  Quadrature id;
  bool own_weights;     // per-family weights assembled by collocation (paper 001), not bond volumes
  bool cut_box_body;    // families cut by a face of the body's box integrate over the cut ball (2D boxes)
  bool blocks;          // on a body of blocks (domain.blocks: paper 003 eq. 17)
  bool dynamics;        // in a dynamic run (explicit or relaxation)
  bool scales_volumes;  // compensation and the surface correction may scale its bond volumes
  bool gauss_points;    // under domain.gauss_points (the points carry their own volumes, eq. 3.14)
};

// clang-format off
inline constexpr std::array<QuadratureRule, 5> kQuadratureRules{{
    // id                     own_weights cut_box blocks dynamics scales gauss
    {Quadrature::Volume,        false,     false,  true,  true,    true,  true},
    {Quadrature::PartialLinear, false,     false,  true,  true,    true,  false},
    {Quadrature::PartialExact,  false,     false,  false, true,    true,  false},
    {Quadrature::Obq,           true,      false,  false, false,   false, false},
    {Quadrature::ObqCut,        true,      true,   false, false,   false, false},
}};
// clang-format on

constexpr const QuadratureRule& quadrature_rule(Quadrature q) {
  for (const QuadratureRule& r : kQuadratureRules)
    if (r.id == q) return r;
  return kQuadratureRules[0];  // unreachable: the test holds the table to the enum
}

// The rules that have `feature` (a member pointer of QuadratureRule), in table order.
template <typename F>
std::vector<Quadrature> quadratures_with(F feature) {
  std::vector<Quadrature> out;
  for (const QuadratureRule& r : kQuadratureRules)
    if (r.*feature) out.push_back(r.id);
  return out;
}

// The rules that weigh bonds by their own per-family weights (obq, obq_cut).
inline bool is_obq(Quadrature q) { return quadrature_rule(q).own_weights; }

}  // namespace pd

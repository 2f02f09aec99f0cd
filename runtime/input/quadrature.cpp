// Scene spellings of the quadrature choices.
#include "input/quadrature.hpp"

#include <utility>

namespace pd {

namespace {
constexpr std::pair<Quadrature, std::string_view> kNames[] = {
    {Quadrature::Volume, "volume"},
    {Quadrature::PartialLinear, "partial_linear"},
    {Quadrature::PartialExact, "partial_exact"},
    {Quadrature::Obq, "obq"},
    {Quadrature::ObqCut, "obq_cut"},
};
}  // namespace

std::string_view quadrature_name(Quadrature q) {
  for (const auto& [value, name] : kNames)
    if (value == q) return name;
  return "unknown";
}

std::optional<Quadrature> parse_quadrature(std::string_view name) {
  for (const auto& [value, spelling] : kNames)
    if (spelling == name) return value;
  return std::nullopt;
}

}  // namespace pd

// How domain.surface_correction matches a cut family to the full one (paper 003 eq. 19;
// assembly/surface_correction.hpp says what each does).
#pragma once

namespace pd {

// Terms: the references' 2D recipe (the dilatation, then the sum of the deviatoric
// responses). Responses: both summed responses at once. Directions: one factor per axis
// from the uniaxial stretch along it, combined per bond by the bond's direction (Madenci
// and Oterkus's 3D recipe).
enum class SurfaceMatch { Terms, Responses, Directions };

// The scene's word for it.
inline const char* surface_match_name(SurfaceMatch m) {
  return m == SurfaceMatch::Terms ? "terms" : m == SurfaceMatch::Responses ? "responses" : "directions";
}

}  // namespace pd

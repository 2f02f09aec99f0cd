// Analytic displacement fields of paper 000's test problems (plane strain), used as
// prescribed boundary fields and as references for probes and error norms.
//   uniaxial:   bottom clamped, rollers on the sides, traction T on top (u_y only)
//   biaxial:    rollers left and bottom, traction T on top and right
//   shear:      bottom clamped, horizontal rollers on the sides, tangential T on top
//   westergaard: pressurised crack on y = 0, |x| < a, pressure p (eqs. 42-47)
#pragma once

#include <array>
#include <map>
#include <string>

#include "input/scene.hpp"

namespace pd {

class AnalyticField {
 public:
  // Parameters: traction T (or pressure p, half_length a), E, nu, and the loaded
  // edge height H (uniaxial/biaxial/shear; default 1) -- any not given in `spec`
  // are taken from `material` (E, nu).
  AnalyticField(const FieldSpec& spec, const IsotropicElastic& material);
  std::array<double, 3> displacement(const double* x) const;
  const std::string& name() const { return name_; }

 private:
  std::string name_;
  double T_ = 0, E_ = 0, nu_ = 0, a_ = 0, x0_ = 0, y0_ = 0;
};

}  // namespace pd

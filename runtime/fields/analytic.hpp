// Analytic displacement fields of paper 000's test problems (plane strain), used as
// prescribed boundary fields and as references for probes and error norms.
//   uniaxial:   bottom clamped, rollers on the sides, traction T on top (u_y only)
//   biaxial:    rollers left and bottom, traction T on top and right
//   shear:      bottom clamped, horizontal rollers on the sides, tangential T on top
//   westergaard: pressurised crack on y = 0, |x| < a, pressure p (eqs. 42-47)
//   rotation:   rigid rotation by `angle` degrees about (x0, y0), times 1 + `stretch`
//   affine:     u = eps (x - x0), eps symmetric from e11 e22 e33 e12 e13 e23 (default 0), 2D or 3D
//   inclusion:  circular inclusion of radius a (E_inclusion, nu_inclusion) at (x0, y0)
//               in an infinite plane under remote equibiaxial traction T
//   michell:    paper 001's traction-free hole of `radius` at (x0, y0) in an infinite plane
//               under tension `traction` along x (fields/michell.hpp)
//   u1, u2:     paper 001's manufactured solutions (fields/manufactured.hpp) times
//               `amplitude` (default 1); the only fields with a body force
#pragma once

#include <array>
#include <map>
#include <string>

#include "fields/manufactured.hpp"
#include "fields/michell.hpp"
#include "input/scene.hpp"

namespace pd {

class AnalyticField {
 public:
  // Parameters: traction T (or pressure p, half_length a), E, nu, and the loaded
  // edge height H (uniaxial/biaxial/shear; default 1) -- any not given in `spec`
  // are taken from `material` (E, nu).
  AnalyticField(const FieldSpec& spec, const IsotropicElastic& material);
  std::array<double, 3> displacement(const double* x) const;
  // The field at a load factor in [0, 1]: load * displacement for the elastic solutions;
  // the rotation by load * angle with stretch load * stretch (so every intermediate
  // state of a load-stepped rotation is itself a rotation).
  std::array<double, 3> displacement_at_load(const double* x, double load) const;
  const std::string& name() const { return name_; }
  // The body force density b = -div sigma that makes the field an equilibrium (plane
  // strain, lambda and mu from E and nu): non-zero only for the manufactured fields.
  bool has_body_force() const { return manufactured_.displacement != nullptr; }
  std::array<double, 3> body_force(const double* x) const;

 private:
  std::string name_;
  double T_ = 0, E_ = 0, nu_ = 0, a_ = 0, x0_ = 0, y0_ = 0;
  double angle_ = 0, stretch_ = 0;           // rotation
  double inner_ = 0, outer_ = 0, hole_ = 0;  // inclusion: u_r = inner r (r < a), outer r + hole / r
  double strain_[3][3] = {};                 // affine: u = strain (x - (x0, y0, z0))
  double z0_ = 0;
  MichellHole michell_;             // michell
  ManufacturedField manufactured_;  // u1, u2
  double amplitude_ = 1;
};

}  // namespace pd

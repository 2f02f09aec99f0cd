// Constant-strain solutions and the Westergaard crack field (papers/README.md forms).
#include "fields/analytic.hpp"

#include <cmath>
#include <complex>
#include <stdexcept>

namespace pd {

namespace {
double param(const FieldSpec& s, const std::string& key, double fallback) {
  auto it = s.parameters.find(key);
  return it == s.parameters.end() ? fallback : it->second;
}

// Refuses a parameter that no analytic field reads (a misspelt key would otherwise be ignored).
void check_known_parameters(const FieldSpec& spec, const std::string& name) {
  for (const auto& [k, v] : spec.parameters) {
    static const char* known[] = {"E",
                                  "nu",
                                  "x0",
                                  "y0",
                                  "pressure",
                                  "half_length",
                                  "traction",
                                  "angle",
                                  "stretch",
                                  "radius",
                                  "E_inclusion",
                                  "nu_inclusion",
                                  "inclusion_stress",
                                  "e11",
                                  "e22",
                                  "e33",
                                  "e12",
                                  "e13",
                                  "e23",
                                  "z0",
                                  "amplitude"};
    bool ok = false;
    for (const char* n : known) ok = ok || k == n;
    if (!ok) throw std::invalid_argument("field " + name + ": unknown parameter '" + k + "'");
  }
}
}  // namespace

AnalyticField::AnalyticField(const FieldSpec& spec, const IsotropicElastic& m) : name_(spec.solution) {
  E_ = param(spec, "E", m.E);
  nu_ = param(spec, "nu", m.nu);
  x0_ = param(spec, "x0", 0.0);  // origin: the fixed corner, or the crack center
  y0_ = param(spec, "y0", 0.0);
  if (name_ == "westergaard") {
    T_ = param(spec, "pressure", NAN);
    a_ = param(spec, "half_length", NAN);
    if (!std::isfinite(T_) || !std::isfinite(a_) || a_ <= 0)
      throw std::invalid_argument("westergaard field needs pressure and a positive half_length");
  } else if (name_ == "uniaxial" || name_ == "biaxial" || name_ == "shear") {
    T_ = param(spec, "traction", NAN);
    if (!std::isfinite(T_)) throw std::invalid_argument(name_ + " field needs traction");
  } else if (name_ == "rotation") {
    angle_ = param(spec, "angle", NAN) * M_PI / 180;
    stretch_ = param(spec, "stretch", 0.0);
    if (!std::isfinite(angle_)) throw std::invalid_argument("rotation field needs angle (degrees)");
  } else if (name_ == "affine") {
    // u = eps (x - x0) with a symmetric strain tensor, in 2D or 3D (paper 002 eq. 2.54).
    const char* keys[3][3] = {{"e11", "e12", "e13"}, {"e12", "e22", "e23"}, {"e13", "e23", "e33"}};
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) strain_[a][b] = param(spec, keys[a][b], 0.0);
    z0_ = param(spec, "z0", 0.0);
  } else if (name_ == "inclusion") {
    // Plane strain, axisymmetric: u_r = A r inside, B r + C / r outside. Far field
    // sigma_rr = T gives B = T / (2 (lambda_m + mu_m)); continuity of u_r and of
    // sigma_rr at r = a gives A = B (lambda_m + 2 mu_m) / (lambda_i + mu_i + mu_m) and
    // C = (A - B) a^2 (sigma_rr = 2 (lambda + mu) u_r' ... with u = A r: 2 (lambda + mu) A;
    // with C / r: -2 mu C / r^2).
    // Or, with `inclusion_stress` P instead of `traction`, paper 001's form (eqs. 4.8-4.10,
    // fields/manufactured.hpp): P is the stress inside the inclusion.
    T_ = param(spec, "traction", NAN);
    const double P = param(spec, "inclusion_stress", NAN);
    a_ = param(spec, "radius", NAN);
    const IsotropicElastic mi =
        IsotropicElastic::from_E_nu(param(spec, "E_inclusion", NAN), param(spec, "nu_inclusion", NAN));
    const IsotropicElastic mm = IsotropicElastic::from_E_nu(E_, nu_);
    if (std::isfinite(T_) == std::isfinite(P) || !(a_ > 0))
      throw std::invalid_argument(
          "inclusion field needs a positive radius and one of traction (remote) or inclusion_stress");
    if (std::isfinite(P)) {
      const InclusionCoefficients k =
          paper001_inclusion_coefficients(P, a_, mi.lambda, mi.G, mm.lambda, mm.G);
      inner_ = k.A, outer_ = k.B, hole_ = k.C;
    } else {
      outer_ = T_ / (2 * (mm.lambda + mm.G));
      inner_ = outer_ * (mm.lambda + 2 * mm.G) / (mi.lambda + mi.G + mm.G);
      hole_ = (inner_ - outer_) * a_ * a_;
    }
  } else if (name_ == "michell") {
    // Paper 001 §4.2: a traction-free hole of `radius` at (x0, y0), tension `traction` along x.
    michell_.T = param(spec, "traction", NAN);
    michell_.a = param(spec, "radius", NAN);
    michell_.x0 = x0_, michell_.y0 = y0_;
    if (!std::isfinite(michell_.T) || !(michell_.a > 0))
      throw std::invalid_argument("michell field needs traction and a positive radius");
    const auto lame = lame_from_young_poisson(E_, nu_);
    michell_.lambda = lame[0], michell_.mu = lame[1];
  } else if (name_ == "u1" || name_ == "u2") {
    manufactured_ = name_ == "u1" ? paper001_u1() : paper001_u2();
    amplitude_ = param(spec, "amplitude", 1.0);
  } else {
    throw std::invalid_argument("unknown analytic solution '" + name_ + "'");
  }
  check_known_parameters(spec, name_);
}

std::array<double, 3> AnalyticField::displacement_at_load(const double* p, double load) const {
  if (name_ == "rotation") {
    AnalyticField part = *this;
    part.angle_ *= load;
    part.stretch_ *= load;
    return part.displacement(p);
  }
  const auto u = displacement(p);
  return {load * u[0], load * u[1], load * u[2]};
}

std::array<double, 3> AnalyticField::displacement(const double* p) const {
  const double x = p[0] - x0_, y = p[1] - y0_, E = E_, nu = nu_, T = T_;
  // Plane-strain constant-strain fields; at the loaded edge y = H they give the
  // table after Table 1 of paper 000 (positive T: tension along the traction).
  if (name_ == "uniaxial") return {0.0, T * y * (1 - nu - 2 * nu * nu) / (E * (1 - nu)), 0.0};
  if (name_ == "biaxial") {
    const double s = T * (1 - nu - 2 * nu * nu) / E;
    return {s * x, s * y, 0.0};
  }
  if (name_ == "shear") return {2 * T * y * (1 + nu) / E, 0.0, 0.0};
  if (name_ == "affine") {
    // p has 3 coordinates only in 3D scenes: the reader refuses e13, e23, e33 and z0 in 2D,
    // so a 2D field never reads p[2].
    const double r[3] = {x, y,
                         (strain_[0][2] != 0 || strain_[1][2] != 0 || strain_[2][2] != 0) ? p[2] - z0_ : 0.0};
    std::array<double, 3> u{};
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) u[a] += strain_[a][b] * r[b];
    return u;
  }
  if (name_ == "rotation") {
    const double c = std::cos(angle_), s = std::sin(angle_), k = 1 + stretch_;
    return {k * (c * x - s * y) - x, k * (s * x + c * y) - y, 0.0};
  }
  if (has_body_force()) {
    const auto u = manufactured_.displacement(x, y);
    return {amplitude_ * u[0], amplitude_ * u[1], 0.0};
  }
  if (name_ == "michell") {
    const auto u = michell_.displacement(p[0], p[1]);
    return {u[0], u[1], 0.0};
  }
  if (name_ == "inclusion") {
    const double r = std::hypot(x, y);
    if (r == 0) return {0.0, 0.0, 0.0};
    const double ur = r < a_ ? inner_ * r : outer_ * r + hole_ / r;
    return {ur * x / r, ur * y / r, 0.0};
  }
  // Westergaard: Z = p (z / sqrt(z^2 - a^2) - 1), Zhat = p (sqrt(z^2 - a^2) - z),
  // 2G u_x = (1 - 2 nu) Re Zhat - y Im Z, 2G u_y = 2 (1 - nu) Im Zhat - y Re Z,
  // evaluated in the first quadrant, signs restored by symmetry.
  const double G = E / (2 * (1 + nu));
  const double ax = std::fabs(x), ay = std::fabs(y);
  const std::complex<double> z(ax, ay);
  const std::complex<double> root = std::sqrt(z * z - a_ * a_);
  const std::complex<double> Z = T * (z / root - 1.0), Zhat = T * (root - z);
  double ux = ((1 - 2 * nu) * Zhat.real() - ay * Z.imag()) / (2 * G);
  double uy = (2 * (1 - nu) * Zhat.imag() - ay * Z.real()) / (2 * G);
  if (x < 0) ux = -ux;
  if (y < 0) uy = -uy;
  return {ux, uy, 0.0};
}

std::array<double, 3> AnalyticField::body_force(const double* p) const {
  if (!has_body_force()) return {0.0, 0.0, 0.0};
  const auto [lambda, mu] = lame_from_young_poisson(E_, nu_);
  const auto b = manufactured_.body_force(p[0] - x0_, p[1] - y0_, lambda, mu);
  return {amplitude_ * b[0], amplitude_ * b[1], 0.0};
}

}  // namespace pd

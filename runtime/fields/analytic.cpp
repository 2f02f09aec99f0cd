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
  } else {
    throw std::invalid_argument("unknown analytic solution '" + name_ + "'");
  }
  for (const auto& [k, v] : spec.parameters) {
    static const char* known[] = {"E", "nu", "x0", "y0", "pressure", "half_length", "traction"};
    bool ok = false;
    for (const char* n : known) ok = ok || k == n;
    if (!ok) throw std::invalid_argument("field " + name_ + ": unknown parameter '" + k + "'");
  }
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

}  // namespace pd

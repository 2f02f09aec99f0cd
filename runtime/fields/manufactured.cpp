// Paper 001's manufactured solutions; div(sigma) derived in the comments and tested
// against finite differences of the stress (tests/runtime/test_manufactured.cpp).
#include "fields/manufactured.hpp"

#include <cmath>

namespace pd {

namespace {
std::array<double, 2> u1(double x, double y) { return {x * x, 4 * y * y}; }
// div u = 2x + 8y, grad div u = (2, 8), Laplacian u = (2, 8):
// div sigma = (lambda + mu) grad div u + mu Laplacian u = (2 lambda + 4 mu, 8 lambda + 16 mu).
std::array<double, 2> f1(double, double, double lambda, double mu) {
  return {2 * lambda + 4 * mu, 8 * lambda + 16 * mu};
}

}  // namespace

ManufacturedField paper001_u1() { return {"u1", u1, f1}; }
ManufacturedField paper001_u2() { return paper001_u2_wavenumber(1); }

// u = <sin kx sin ky, -cos kx cos ky>: div u = 2k cos kx sin ky, grad div u = -2 k^2 u,
// Laplacian u = -2 k^2 u, so div sigma = (lambda + mu) grad div u + mu Laplacian u
// = -2 k^2 (lambda + 2 mu) u (k = 1: the paper's eq. 4.4).
ManufacturedField paper001_u2_wavenumber(double k) {
  auto u = [k](double x, double y) -> std::array<double, 2> {
    return {std::sin(k * x) * std::sin(k * y), -std::cos(k * x) * std::cos(k * y)};
  };
  auto f = [k, u](double x, double y, double lambda, double mu) -> std::array<double, 2> {
    const auto v = u(x, y);
    const double c = -2 * k * k * (lambda + 2 * mu);
    return {c * v[0], c * v[1]};
  };
  return {k == 1 ? "u2" : "u2(k=" + std::to_string(k) + ")", u, f};
}

InclusionCoefficients paper001_inclusion_coefficients(double P, double a, double lambda1, double mu1,
                                                      double lambda2, double mu2) {
  const double d = 2 * (lambda1 + mu1) * (lambda2 + 2 * mu2);
  return {P / (2 * (lambda1 + mu1)), P * (lambda1 + mu1 + mu2) / d,
          -P * a * a * (lambda1 - lambda2 + mu1 - mu2) / d};
}

ManufacturedField paper001_inclusion(double P, double a, double cx, double cy, double lambda1, double mu1,
                                     double lambda2, double mu2) {
  const InclusionCoefficients k = paper001_inclusion_coefficients(P, a, lambda1, mu1, lambda2, mu2);
  auto u = [k, a, cx, cy](double x, double y) -> std::array<double, 2> {
    const double dx = x - cx, dy = y - cy, r = std::hypot(dx, dy);
    if (r == 0) return {0.0, 0.0};
    const double ur = r < a ? k.A * r : k.B * r + k.C / r;
    return {ur * dx / r, ur * dy / r};
  };
  auto f = [](double, double, double, double) -> std::array<double, 2> { return {0.0, 0.0}; };
  return {"inclusion", u, f};
}

std::array<double, 2> lame_from_young_poisson(double E, double nu) {
  return {E * nu / ((1 + nu) * (1 - 2 * nu)), E / (2 * (1 + nu))};
}

}  // namespace pd

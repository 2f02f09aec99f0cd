// Paper 001's manufactured solutions; div(sigma) derived in the comments and tested
// against finite differences of the stress (tests/runtime/test_manufactured.cpp).
#include "fields/manufactured.hpp"

#include <cmath>

namespace pd {

namespace {
std::array<double, 2> u1(double x, double y) { return {x * x, 4 * y * y}; }
// div u = 2x + 8y, grad div u = (2, 8), Laplacian u = (2, 8):
// div sigma = (lambda + mu) grad div u + mu Laplacian u = (2 lambda + 4 mu, 8 lambda + 16 mu).
std::array<double, 2> f1(double, double, double lambda, double mu) { return {2 * lambda + 4 * mu, 8 * lambda + 16 * mu}; }

std::array<double, 2> u2(double x, double y) { return {std::sin(x) * std::sin(y), -std::cos(x) * std::cos(y)}; }
// div u = cos x sin y + cos x sin y = 2 cos x sin y; grad div u = (-2 sin x sin y, 2 cos x cos y)
// = -2 u; Laplacian u = -2 u: div sigma = -2 (lambda + 2 mu) u.
std::array<double, 2> f2(double x, double y, double lambda, double mu) {
  const auto u = u2(x, y);
  return {-2 * (lambda + 2 * mu) * u[0], -2 * (lambda + 2 * mu) * u[1]};
}
}  // namespace

ManufacturedField paper001_u1() { return {"u1", u1, f1}; }
ManufacturedField paper001_u2() { return {"u2", u2, f2}; }

std::array<double, 2> lame_from_young_poisson(double E, double nu) {
  return {E * nu / ((1 + nu) * (1 - 2 * nu)), E / (2 * (1 + nu))};
}

}  // namespace pd

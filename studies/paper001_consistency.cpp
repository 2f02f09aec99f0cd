// Consistency of paper 001's discrete LPS on a perturbed cloud: the RMS of the residual
// density F(u_ex)/V + b for u2 (lambda = mu = 1/2) over the particles at least 2 delta
// inside the unit square, with the paper's reproducing space and with the odd terms.
//   build/bin/paper001_consistency [n ...]     (default 24 48)
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "assembly/assembler.hpp"
#include "discretize/discretization.hpp"
#include "discretize/obq_weights.hpp"
#include "fields/manufactured.hpp"

namespace {
bool inside(const double* x, double margin) {
  return x[0] >= margin && x[0] <= 1 - margin && x[1] >= margin && x[1] <= 1 - margin;
}

double residual_rms(int n, bool odd) {
  pd::Scene s;
  s.dim = 2;
  s.lo = {0, 0, 0};
  s.hi = {1, 1, 0};
  s.h = 1.0 / n;
  s.perturbation = 0.2;
  s.seed = 1;
  s.materials.resize(1);
  const pd::Particles P = pd::discretize(s);
  const double delta = 3.5 * s.h;
  const pd::Bonds B = pd::find_bonds(P, delta, pd::abi::find_influence("inv")->weight);
  // OBQ on the full-ball families (all that reach the measured particles).
  std::vector<char> full(P.size());
  for (int p = 0; p < P.size(); ++p) full[p] = inside(P.position(p), delta);
  const pd::Collocation col = pd::make_collocation(
      P, B, pd::obq_weights(P, B, odd ? pd::paper001_odd_space(2) : pd::paper001_space(2), full));
  pd::AssemblerOptions options;
  options.collocation = &col;
  options.intact = true;
  const pd::FamilyAssembler A(P, B, *pd::abi::find_law("lps_plane_strain"), {{0.5, 0.5}}, options);
  const pd::ManufacturedField field = pd::paper001_u2();
  std::vector<double> u(2 * P.size()), f(2 * P.size());
  for (int p = 0; p < P.size(); ++p) {
    const auto v = field.displacement(P.position(p)[0], P.position(p)[1]);
    u[2 * p] = v[0], u[2 * p + 1] = v[1];
  }
  A.internal_forces(u.data(), f.data());
  double sum = 0;
  int count = 0;
  for (int p = 0; p < P.size(); ++p) {
    const double* x = P.position(p);
    if (!inside(x, 2 * delta)) continue;
    const auto b = field.body_force(x[0], x[1], 0.5, 0.5);
    for (int c = 0; c < 2; ++c) sum += std::pow(f[2 * p + c] / P.volume[p] + b[c], 2);
    ++count;
  }
  return std::sqrt(sum / count);
}
}  // namespace

int main(int argc, char** argv) {
  std::vector<int> grids;
  for (int i = 1; i < argc; ++i) grids.push_back(std::atoi(argv[i]));
  if (grids.empty()) grids = {24, 48};
  std::printf("%6s | %14s %6s | %14s %6s\n", "N", "paper space", "order", "+ odd terms", "order");
  double prev[2] = {0, 0};
  int prev_n = 0;
  for (int n : grids) {
    const double e[2] = {residual_rms(n, false), residual_rms(n, true)};
    std::printf("%4d^2 |", n);
    for (int k = 0; k < 2; ++k)
      std::printf(" %14.4e %6.2f%s", e[k],
                  prev_n ? std::log(prev[k] / e[k]) / std::log(double(n) / prev_n) : NAN,
                  k == 0 ? " |" : "\n");
    prev[0] = e[0], prev[1] = e[1], prev_n = n;
  }
}

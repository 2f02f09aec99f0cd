// Which set-up gives paper 001's Table 1 magnitudes? Our u2 errors with the paper's
// stated set-up are ~1/180 of its numbers, u2,inc ~1/16 (docs/paper001.md). This study
// solves u2 (lambda = mu = 1/2) and u2,inc (E = 1, nu = 0.495) under variants of the
// set-up -- the wavenumber k of u2, the square, the Dirichlet layer -- and prints each
// error beside the paper's and the ratio.
//   build/bin/paper001_table1_variants [--only VARIANT] [n ...]     (default 24 48)
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <vector>

#include "run/manufactured_solve.hpp"

namespace {
const std::map<int, std::array<double, 2>> kPaper{
    {24, {0.02207, 0.13057}}, {48, {0.00506, 0.02597}}, {96, {0.00117, 0.00632}}, {192, {0.00028, 0.00158}}};

struct Variant {
  std::string name;
  double k = 1;           // wavenumber of u2
  double lo = 0, hi = 1;  // the square
  double layer = 1;       // Dirichlet layer in horizons
  bool outside = false;   // the layer as a collar outside the square
  bool whole = false;     // the layer inside, its families whole (whole_layer_families)
};
}  // namespace

int main(int argc, char** argv) {
  std::vector<int> grids;
  std::string only;  // --only NAME: one variant
  for (int i = 1; i < argc; ++i) {
    if (std::string(argv[i]) == "--only" && i + 1 < argc)
      only = argv[++i];
    else
      grids.push_back(std::atoi(argv[i]));
  }
  if (grids.empty()) grids = {24, 48};
  const std::vector<Variant> variants{{"as stated", 1},
                                      {"k = pi/2", M_PI / 2},
                                      {"k = pi", M_PI},
                                      {"k = 2 pi", 2 * M_PI},
                                      {"[-1,1]^2", 1, -1, 1},
                                      {"[0,pi]^2", 1, 0, M_PI},
                                      {"[0,2pi]^2", 1, 0, 2 * M_PI},
                                      {"layer 2 delta", 1, 0, 1, 2},
                                      {"collar outside", 1, 0, 1, 1, true},
                                      {"whole layer fam.", 1, 0, 1, 1, false, true},
                                      {"k=pi, whole layer", M_PI, 0, 1, 1, false, true},
                                      {"k=pi, outside", M_PI, 0, 1, 1, true},
                                      {"k=4", 4},
                                      {"k=4, outside", 4, 0, 1, 1, true},
                                      {"[-1,1]^2, outside", 1, -1, 1, 1, true},
                                      {"k=2pi, outside", 2 * M_PI, 0, 1, 1, true}};
  const auto inc = pd::lame_from_young_poisson(1.0, 0.495);
  std::printf("%-18s %6s | %11s %8s %7s | %11s %8s %7s | %8s %8s\n", "variant", "N", "u2", "ratio", "order",
              "u2,inc", "ratio", "order", "ex+ey", "ex+ey");
  for (const Variant& v : variants) {
    if (!only.empty() && v.name != only) continue;
    double prev[2] = {0, 0};
    int prev_n = 0;
    for (int n : grids) {
      std::printf("%-18s %4d^2 |", v.name.c_str(), n);
      double components[2] = {0, 0};
      for (int c = 0; c < 2; ++c) {
        pd::ManufacturedSetup s;
        s.n = n;
        s.lo = v.lo, s.hi = v.hi;
        s.layer_horizons = v.layer;
        s.collar_outside = v.outside;
        s.whole_layer_families = v.whole;
        s.lambda = c == 0 ? 0.5 : inc[0];
        s.mu = c == 0 ? 0.5 : inc[1];
        const pd::ManufacturedResult r = pd::solve_manufactured(pd::paper001_u2_wavenumber(v.k), s);
        const double e = r.rms_error;
        components[c] = r.rms_component[0] + r.rms_component[1];
        const double paper = kPaper.count(n) ? kPaper.at(n)[c] : NAN;
        const double order = prev_n ? std::log(prev[c] / e) / std::log(double(n) / prev_n) : NAN;
        std::printf(" %11.4e %8.3g %7.2f |", e, e / paper, order);
        prev[c] = e;
      }
      // ||e_x|| + ||e_y||, another reading of the norm, as a ratio to the paper's.
      const double p0 = kPaper.count(n) ? kPaper.at(n)[0] : NAN, p1 = kPaper.count(n) ? kPaper.at(n)[1] : NAN;
      std::printf(" %8.3g %8.3g\n", components[0] / p0, components[1] / p1);
      std::fflush(stdout);
      prev_n = n;
    }
  }
}

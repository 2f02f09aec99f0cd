// Paper 001 Table 1: the manufactured solutions u1 (patch test), u2 and u2 at nu = 0.495
// on perturbed unit-square grids, beside the paper's numbers, with the time each costs.
//   build/bin/paper001_table1 [--only COLUMN] [n ...]   (default 24 48 96; the paper also has 192)
// Set-up as paper 001 §4: lattice spacing h = 1/n perturbed by 0.2 h, delta = 3.5 h, a
// Dirichlet layer of width delta, OBQ weights with paper001_space, LPS, K = 1/r.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iterator>
#include <map>
#include <string>
#include <vector>

#include "run/manufactured_solve.hpp"

namespace {
// Table 1 of paper 001: ||u - u_ex||_l2 for u1, u2, u2,inc.
const std::map<int, std::array<double, 3>> kPaper{
    {24, {4.11e-14, 0.02207, 0.13057}},
    {48, {2.47e-13, 0.00506, 0.02597}},
    {96, {2.69e-12, 0.00117, 0.00632}},
    {192, {4.01e-13, 0.00028, 0.00158}},
};
}  // namespace

int main(int argc, char** argv) {
  std::vector<int> grids;
  std::string only;
  for (int i = 1; i < argc; ++i) {
    if (std::string(argv[i]) == "--only" && i + 1 < argc)
      only = argv[++i];
    else
      grids.push_back(std::atoi(argv[i]));
  }
  if (grids.empty()) grids = {24, 48, 96};
  const auto inc = pd::lame_from_young_poisson(1.0, 0.495);
  struct Column {
    const char* name;
    pd::ManufacturedField field;
    double lambda, mu;
    bool odd = false;    // paper001_odd_space, with
    double layer = 1.0;  // a Dirichlet layer of this many horizons
  };
  // The paper's three columns, then ours beyond it: the odd terms (docs/paper001.md)
  // need a layer of two horizons (the one-face families of a delta layer have too few
  // bonds for 21 functions); u1 at nu = 0.3 tests the dilatation term, absent at lambda = mu.
  const auto nu3 = pd::lame_from_young_poisson(1.0, 0.3);
  const Column columns[] = {{"u1", pd::paper001_u1(), 0.5, 0.5},
                            {"u2", pd::paper001_u2(), 0.5, 0.5},
                            {"u2,inc", pd::paper001_u2(), inc[0], inc[1]},
                            {"u1,nu.3", pd::paper001_u1(), nu3[0], nu3[1]},
                            {"u1,nu.3o", pd::paper001_u1(), nu3[0], nu3[1], true, 2.0},
                            {"u2,odd", pd::paper001_u2(), 0.5, 0.5, true, 2.0},
                            {"u2,2dl", pd::paper001_u2(), 0.5, 0.5, false, 2.0}};
  std::printf("%6s %8s %7s | %12s %12s %6s | %8s %8s\n", "N", "column", "solved", "ours", "paper", "order",
              "ours/pap", "seconds");
  for (int c = 0; c < static_cast<int>(std::size(columns)); ++c) {
    if (!only.empty() && only != columns[c].name) continue;
    double previous = 0;
    int previous_n = 0;
    for (int n : grids) {
      pd::ManufacturedSetup s;
      s.n = n;
      s.lambda = columns[c].lambda;
      s.mu = columns[c].mu;
      s.odd_terms = columns[c].odd;
      s.layer_horizons = columns[c].layer;
      const pd::ManufacturedResult r = pd::solve_manufactured(columns[c].field, s);
      const double paper = c < 3 && kPaper.count(n) ? kPaper.at(n)[c] : NAN;
      const double order =
          previous_n ? std::log(previous / r.rms_error) / std::log(double(n) / previous_n) : NAN;
      std::printf("%4d^2 %8s %7d | %12.4e %12.4e %6.2f | %8.3g %8.2f\n", n, columns[c].name, r.solved,
                  r.rms_error, paper, order, r.rms_error / paper,
                  r.weights_seconds + r.assembly_seconds + r.solve_seconds);
      std::fflush(stdout);
      previous = r.rms_error, previous_n = n;
    }
  }
}

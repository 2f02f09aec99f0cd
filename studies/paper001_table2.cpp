// Paper 001 Table 2: the hydrostatically loaded circular inclusion (§4.3, eqs. 4.8-4.12)
// on uniform and perturbed unit-square grids, beside the paper's numbers, with the time
// each run costs.
//   build/bin/paper001_table2 [--only COLUMN] [--P value] [--perturbation p] [--seed s] [--law LAW] [n ...]
// (default grids 16 32 64 128; --perturbation replaces the perturbed columns' 0.2 h; --law:
// another LPS of (lambda, mu), e.g. lps_paper_plane_strain with paper 001's analytic m(delta))
// Set-up as paper 001 §4 and Table 1: lattice spacing h = 1/n (perturbed by 0.2 h in the
// "perturbed" columns), delta = 3.5 h, the exact field imposed on a Dirichlet layer of
// width delta, OBQ weights with paper001_space, LPS with the harmonic pair means of eq.
// (2.4), K = 1/r. Inclusion of radius a = 0.2 at the centre of the square; bulk moduli
// K1 = 2 (inclusion) and K2 = 1 (matrix), read as the 3D bulk modulus E / (3 (1 - 2 nu));
// P = 1 (the paper does not give it; the errors scale with it).
// Columns: the paper's text sets nu1 = 0.49 (inclusion) with nu2 = 0.25 for the
// near-incompressible case; its table heads that column "nu2 = 0.49". Both are run:
// "nu1=.49" is the text's reading, "nu2=.49" the table's.
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iterator>
#include <map>
#include <string>
#include <vector>

#include "run/manufactured_solve.hpp"

namespace {
// Table 2 of paper 001: RMS error for uniform (nu 0.25, 0.49) then nonuniform (0.25, 0.49).
const std::map<int, std::array<double, 4>> kPaper{
    {16, {0.00569, 0.04463, 0.00661, 0.04629}},  {32, {0.00201, 0.03926, 0.00242, 0.03941}},
    {64, {0.00099, 0.02260, 0.00144, 0.02304}},  {128, {0.00045, 0.01205, 0.00055, 0.01211}},
    {256, {0.00023, 0.00595, 0.00044, 0.00614}},
};

// Lame parameters of plane strain from the bulk modulus K = E / (3 (1 - 2 nu)) and nu.
std::array<double, 2> lame_from_bulk(double K, double nu) {
  const double E = 3 * K * (1 - 2 * nu);
  return pd::lame_from_young_poisson(E, nu);
}
}  // namespace

int main(int argc, char** argv) {
  std::vector<int> grids;
  std::string only, law = "lps_plane_strain";
  double P = 1.0, perturbation = 0.2;
  int seed = 1;
  for (int i = 1; i < argc; ++i) {
    if (std::string(argv[i]) == "--only" && i + 1 < argc)
      only = argv[++i];
    else if (std::string(argv[i]) == "--P" && i + 1 < argc)
      P = std::atof(argv[++i]);
    else if (std::string(argv[i]) == "--perturbation" && i + 1 < argc)
      perturbation = std::atof(argv[++i]);
    else if (std::string(argv[i]) == "--seed" && i + 1 < argc)
      seed = std::atoi(argv[++i]);
    else if (std::string(argv[i]) == "--law" && i + 1 < argc)
      law = argv[++i];
    else
      grids.push_back(std::atoi(argv[i]));
  }
  if (grids.empty()) grids = {16, 32, 64, 128};
  struct Column {
    const char* name;
    double nu1, nu2;  // inclusion, matrix
    double perturbation;
    int paper;  // index into kPaper's rows
  };
  const Column columns[] = {{"uni,.25", 0.25, 0.25, 0.0, 0},     {"uni,nu1=.49", 0.49, 0.25, 0.0, 1},
                            {"uni,nu2=.49", 0.25, 0.49, 0.0, 1}, {"per,.25", 0.25, 0.25, 0.2, 2},
                            {"per,nu1=.49", 0.49, 0.25, 0.2, 3}, {"per,nu2=.49", 0.25, 0.49, 0.2, 3}};
  const double a = 0.2, cx = 0.5, cy = 0.5;
  std::printf("%6s %12s %7s | %12s %12s %6s | %8s %8s\n", "N", "column", "solved", "ours", "paper", "order",
              "ours/pap", "seconds");
  for (const Column& col : columns) {
    if (!only.empty() && only != col.name) continue;
    const auto in = lame_from_bulk(2.0, col.nu1), out = lame_from_bulk(1.0, col.nu2);
    const pd::ManufacturedField field = pd::paper001_inclusion(P, a, cx, cy, in[0], in[1], out[0], out[1]);
    double previous = 0;
    int previous_n = 0;
    for (int n : grids) {
      pd::ManufacturedSetup s;
      s.n = n;
      s.law = law;
      s.perturbation = col.perturbation > 0 ? perturbation : 0.0;
      s.seed = seed;
      s.lambda = out[0], s.mu = out[1];
      s.inclusion_radius = a;
      s.inclusion_centre[0] = cx, s.inclusion_centre[1] = cy;
      s.inclusion_lambda = in[0], s.inclusion_mu = in[1];
      const pd::ManufacturedResult r = pd::solve_manufactured(field, s);
      const double paper = kPaper.count(n) ? kPaper.at(n)[col.paper] : NAN;
      const double order =
          previous_n ? std::log(previous / r.rms_error) / std::log(double(n) / previous_n) : NAN;
      std::printf("%4d^2 %12s %7d | %12.4e %12.4e %6.2f | %8.3g %8.2f\n", n, col.name, r.solved, r.rms_error,
                  paper, order, r.rms_error / paper,
                  r.weights_seconds + r.assembly_seconds + r.solve_seconds);
      std::fflush(stdout);
      previous = r.rms_error, previous_n = n;
    }
  }
}

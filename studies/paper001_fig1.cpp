// Paper 001 Fig. 1: the traction-free hole (Michell solution, eqs. 4.5-4.7) in the unit
// square, first-order convergence of the RMS displacement error, far from and close to the
// incompressible limit, on uniform and perturbed clouds, with the time each run costs.
//   build/bin/paper001_fig1 [--csv FILE] [--laws LAW,...] [--inside] [--far D]
//                         [--nu 0.25|0.495] [--perturbation 0|0.2] [--seed S] [--cut-weights] [n ...]
//                         (default 24 48 96)
// Set-up as §4: lattice h = 1/n (perturbed by 0.2 h, or not), delta = 3.5 h, K = 1/r, OBQ
// weights with paper001_space computed on the whole cloud, then every bond that meets the
// circle of radius a = 0.2 about (0.5, 0.5) broken; the exact field on a Dirichlet collar of
// one horizon (outside the square by default: the reading that reproduces Table 1's shape,
// docs/paper001.md; --inside puts the layer inside), the RMS error of §4 over the solved
// particles (--far D: only those at least D from the hole's circle). --cut-weights (not the
// paper's): the families that lost bonds get new weights over their intact bonds, exact over
// the part of the ball they see past the hole (ManufacturedSetup::hole_cut_weights). Far-field tension T = 1
// along x (the paper gives no T; the problem is linear).
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "fields/michell.hpp"
#include "run/manufactured_solve.hpp"

int main(int argc, char** argv) {
  std::vector<int> grids;
  std::vector<std::string> laws{"lps_plane_strain", "lps_corrected_plane_strain"};
  std::string csv_path;
  bool inside = false, cut_weights = false;
  double far = 0;  // --far D: the error only over particles at least D from the hole
  int seed = 1;
  double only_nu = 0, only_perturbation = -1;  // --nu V, --perturbation P: only those cases
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--csv" && i + 1 < argc)
      csv_path = argv[++i];
    else if (a == "--inside")
      inside = true;
    else if (a == "--cut-weights")
      cut_weights = true;
    else if (a == "--far" && i + 1 < argc)
      far = std::atof(argv[++i]);
    else if (a == "--seed" && i + 1 < argc)
      seed = std::atoi(argv[++i]);
    else if (a == "--nu" && i + 1 < argc)
      only_nu = std::atof(argv[++i]);
    else if (a == "--perturbation" && i + 1 < argc)
      only_perturbation = std::atof(argv[++i]);
    else if (a == "--laws" && i + 1 < argc) {
      laws.clear();
      std::stringstream ss(argv[++i]);
      for (std::string l; std::getline(ss, l, ',');) laws.push_back(l);
    } else
      grids.push_back(std::atoi(a.c_str()));
  }
  if (grids.empty()) grids = {24, 48, 96};
  FILE* csv = csv_path.empty() ? nullptr : std::fopen(csv_path.c_str(), "w");
  if (!csv_path.empty() && !csv) {
    std::fprintf(stderr, "paper001_fig1: cannot write %s\n", csv_path.c_str());
    return 2;
  }
  if (csv) std::fprintf(csv, "law,nu,perturbation,n,solved,broken_bonds,rms_error,seconds\n");
  const auto inc = pd::lame_from_young_poisson(1.0, 0.495);
  struct Material {
    const char* name;
    double nu, lambda, mu;
  };
  const Material materials[] = {{"nu=0.25", 0.25, 0.5, 0.5}, {"nu=0.495", 0.495, inc[0], inc[1]}};
  std::printf("%-28s %-9s %5s %6s | %7s %7s | %12s %6s | %8s\n", "law", "material", "pert", "N", "solved",
              "broken", "rms error", "order", "seconds");
  for (const std::string& law : laws)
    for (const Material& m : materials)
      for (double perturbation : {0.0, 0.2}) {
        if ((only_nu != 0 && m.nu != only_nu) ||
            (only_perturbation >= 0 && perturbation != only_perturbation))
          continue;
        pd::MichellHole hole;
        hole.T = 1, hole.a = 0.2, hole.x0 = 0.5, hole.y0 = 0.5, hole.lambda = m.lambda, hole.mu = m.mu;
        pd::ManufacturedField field{"michell", [hole](double x, double y) { return hole.displacement(x, y); },
                                    [](double, double, double, double) {
                                      return std::array<double, 2>{0.0, 0.0};
                                    }};
        double previous = 0;
        int previous_n = 0;
        for (int n : grids) {
          pd::ManufacturedSetup s;
          s.n = n;
          s.lambda = m.lambda, s.mu = m.mu;
          s.law = law;
          s.perturbation = perturbation;
          s.seed = seed;
          s.collar_outside = !inside;
          s.hole_radius = hole.a;
          s.hole_error_margin = far;
          s.hole_cut_weights = cut_weights;
          const pd::ManufacturedResult r = pd::solve_manufactured(field, s);
          const double seconds = r.weights_seconds + r.assembly_seconds + r.solve_seconds;
          const double order =
              previous_n ? std::log(previous / r.rms_error) / std::log(double(n) / previous_n) : NAN;
          std::printf("%-28s %-9s %5.1f %4d^2 | %7d %7d | %12.4e %6.2f | %8.2f\n", law.c_str(), m.name,
                      perturbation, n, r.solved, r.broken_bonds, r.rms_error, order, seconds);
          if (cut_weights)
            std::printf("    reweighed %d cut families, %d kept the whole-ball weights\n",
                        r.cut_weight_families, r.cut_weight_fallbacks);
          std::fflush(stdout);
          if (csv)
            std::fprintf(csv, "%s,%g,%g,%d,%d,%d,%.6e,%.3f\n", law.c_str(), m.nu, perturbation, n, r.solved,
                         r.broken_bonds, r.rms_error, seconds),
                std::fflush(csv);
          previous = r.rms_error, previous_n = n;
        }
      }
  if (csv) std::fclose(csv);
}

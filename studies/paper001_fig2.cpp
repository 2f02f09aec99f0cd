// Paper 001 Fig. 2: u_x along the line through the inclusion's centre, computed and
// analytic, for shear-modulus ratios mu2/mu1 = 2^k (nu1 = nu2 = 1/4, mu1 = 1, a = 0.2,
// P = 1), on the uniform grid; written as CSV for studies/paper001_fig2.py.
//   build/bin/paper001_fig2 [--n N] [--ks k1,k2,...] > out/paper001_fig2.csv
// Default: N = 64 (the paper's right panel) and k = -8, -6, ..., 8. Columns: n, ratio,
// x, u_x computed, u_x exact, for the particles of the row just above the centre (an even
// n has no row on the centre line; the analytic value is taken at the particle).
// Each run's RMS error and time go to stderr.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "run/manufactured_solve.hpp"

int main(int argc, char** argv) {
  int n = 64;
  std::vector<int> ks;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--n" && i + 1 < argc)
      n = std::atoi(argv[++i]);
    else if (a == "--ks" && i + 1 < argc) {
      std::stringstream list(argv[++i]);
      for (std::string item; std::getline(list, item, ',');) ks.push_back(std::stoi(item));
    } else {
      std::fprintf(stderr, "usage: paper001_fig2 [--n N] [--ks k1,k2,...]\n");
      return 2;
    }
  }
  if (ks.empty())
    for (int k = -8; k <= 8; k += 2) ks.push_back(k);
  const double a = 0.2, c = 0.5, P = 1.0, nu = 0.25;
  const double h = 1.0 / n, row = c + 0.5 * h;  // cell-centred lattice: rows at (j + 1/2) h
  std::printf("n,ratio,x,ux,ux_exact\n");
  for (int k : ks) {
    const double ratio = std::ldexp(1.0, k);
    const auto in = pd::lame_from_young_poisson(2 * (1 + nu), nu);  // mu1 = 1
    const auto out = pd::lame_from_young_poisson(2 * (1 + nu) * ratio, nu);
    pd::ManufacturedSetup s;
    s.n = n;
    s.perturbation = 0;
    s.lambda = out[0], s.mu = out[1];
    s.inclusion_radius = a;
    s.inclusion_lambda = in[0], s.inclusion_mu = in[1];
    s.keep_solution = true;
    const pd::ManufacturedResult r =
        pd::solve_manufactured(pd::paper001_inclusion(P, a, c, c, in[0], in[1], out[0], out[1]), s);
    for (int p = 0; p < r.particles; ++p)
      if (std::fabs(r.x[2 * p + 1] - row) < 0.25 * h)
        std::printf("%d,%.17g,%.17g,%.17g,%.17g\n", n, ratio, r.x[2 * p], r.u[2 * p], r.exact[2 * p]);
    std::fprintf(stderr, "n %d mu2/mu1 2^%d: rms error %.4e, %.2f s\n", n, k, r.rms_error,
                 r.weights_seconds + r.assembly_seconds + r.solve_seconds);
  }
}

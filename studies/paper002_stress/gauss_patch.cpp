// The Gauss-point rule of paper 002 §3.3 (domain.gauss_points) against the one-point
// rules on an n x n lattice (spacing 1, delta = 3h) under the homogeneous strain
// u = eps x, plane strain, E = 1, nu = 1/4 (1/4 is every law's ratio here):
//   ghost   the largest nodal force over the interior nodes (those farther than
//           delta + r_w + 2h from every face, whose families, Gauss points and MLS supports
//           are all whole), over |C:eps| h (the force a node's cell face carries): the
//           discrete equilibrium error of the affine field, 0 for a rule whose families
//           are point-symmetric;
//   sigma   |sigma - C:eps| / |C:eps| at the centre (family_stress of each family);
//   ms      CPU time of one force evaluation.
// Usage: paper002_gauss_patch [n]   (default 40)
#include <Eigen/Dense>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <memory>
#include <string>
#include <vector>

#include "assembly/assembler.hpp"
#include "assembly/peridynamic_stress.hpp"
#include "discretize/discretization.hpp"
#include "discretize/gauss_points.hpp"
#include "discretize/partial_volume.hpp"
#include "material/elastic_constants.hpp"

int main(int argc, char** argv) {
  const int n = argc > 1 ? std::atoi(argv[1]) : 40;
  const double delta = 3.0, support = 3.0;
  pd::Scene s;
  s.dim = 2, s.h = 1.0;
  s.lo = {-0.5, -0.5, 0}, s.hi = {n - 0.5, n - 0.5, 0};
  s.materials.resize(1);
  const pd::Particles p = pd::discretize(s);
  const auto w = pd::abi::find_influence("const")->weight;
  Eigen::Matrix2d e;
  e << 1.0e-4, 0.4e-4, 0.4e-4, -0.3e-4;
  std::vector<double> u(p.x.size());
  for (int i = 0; i < p.size(); ++i)
    for (int r = 0; r < 2; ++r) u[2 * i + r] = e(r, 0) * p.x[2 * i] + e(r, 1) * p.x[2 * i + 1];
  const double margin = delta + support + 2.0;
  const int centre = (n / 2) * n + n / 2;
  std::printf(
      "| law | rule | bonds/particle | ghost max|f|/(|C:eps| h) | sigma error | ms per force evaluation "
      "|\n|---|---|---|---|---|---|\n");
  for (const char* law_name : {"bond_based_constant_2d", "lps_plane_strain", "silling_plane_strain",
                               "correspondence_plane_strain"}) {
    const auto& law = *pd::abi::find_law(law_name);
    const auto m = pd::IsotropicElastic::from_E_nu(1.0, 0.25);
    const auto params = pd::law_parameters(law, m, pd::PlaneAssumption::Strain, {{"stab", 1.0}});
    const Eigen::Matrix2d expected = m.lambda * e.trace() * Eigen::Matrix2d::Identity() + 2 * m.G * e;
    for (const char* rule : {"volume", "partial_linear", "gauss2", "gauss3"}) {
      const std::string r = rule;
      pd::Bonds bonds = pd::find_quadrature_bonds(
          p, delta, 1.0, r == "volume" ? pd::Quadrature::Volume : pd::Quadrature::PartialLinear, w);
      std::unique_ptr<pd::GaussPoints> gp;
      pd::AssemblerOptions o;
      o.matrix = false, o.threads = 1, o.intact = true;
      double bonds_per = static_cast<double>(bonds.bond_count()) / p.size();
      if (r.rfind("gauss", 0) == 0) {
        pd::GaussPointOptions go;
        go.per_axis = r == "gauss2" ? 2 : 3;
        go.support = support;
        gp = std::make_unique<pd::GaussPoints>(pd::build_gauss_points(p, 1.0, delta, w, go));
        o.gauss_points = gp.get();
        bonds_per = static_cast<double>(gp->bond_count()) / p.size();
      }
      const pd::FamilyAssembler a(p, bonds, law, {params}, o);
      std::vector<double> f(u.size());
      const std::clock_t c0 = std::clock();
      const int reps = 3;
      for (int k = 0; k < reps; ++k) a.internal_forces(u.data(), f.data());
      const double ms = 1000.0 * static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC / reps;
      double ghost = 0;
      for (int i = 0; i < p.size(); ++i) {
        const double x = p.x[2 * i], y = p.x[2 * i + 1];
        if (x < margin || y < margin || x > n - 1 - margin || y > n - 1 - margin) continue;
        ghost = std::max(ghost, std::hypot(f[2 * i], f[2 * i + 1]));
      }
      const std::vector<double> sigma = pd::peridynamic_stress(a, u.data());
      Eigen::Matrix2d sc;
      sc << sigma[4 * centre], sigma[4 * centre + 1], sigma[4 * centre + 2], sigma[4 * centre + 3];
      std::printf("| %s | %s | %.1f | %.2e | %.4f | %.1f |\n", law_name, rule, bonds_per,
                  ghost / expected.norm(), (sc - expected).norm() / expected.norm(), ms);
    }
  }
  return 0;
}

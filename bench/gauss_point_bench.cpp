// Cost of the Gauss-point quadrature (paper 002 §3.3; runtime/assembly/gauss_point_assembler.*)
// against the one-point rule of the same body: forces f(u), the matrix-free product K v,
// and the assembled stiffness, per particle and per bond (a bond: one kernel bond, i.e.
// a node-to-node bond for the one-point rules, a node-to-Gauss-point bond for the Gauss
// rules). 2D: an n x n lattice of spacing 1, delta = 3h, 1 thread; rules:
//   volume    the default one-point rule (bonds with |xi| <= delta)
//   linear    the one-point rule with the linear factors of eq. (2.16) (= gauss 1 per axis)
//   gauss1    1 point per axis (the node, u_g = u_j): the Gauss-point code path on the linear rule
//   gauss2    2 x 2 points per cell, MLS support 3h
// Laws: lps_plane_strain (one state) and bond_based_constant_2d (no state).
//
//   build/bin/gauss_point_bench --benchmark_filter=forces     (CPU time per call is the measure)
#include <benchmark/benchmark.h>

#include <memory>
#include <random>
#include <string>
#include <vector>

#include "assembly/assembler.hpp"
#include "discretize/discretization.hpp"
#include "discretize/gauss_points.hpp"
#include "discretize/partial_volume.hpp"
#include "material/elastic_constants.hpp"

namespace {

struct Body {
  pd::Particles particles;
  pd::Bonds bonds;
  std::unique_ptr<pd::GaussPoints> gp;
  std::unique_ptr<pd::FamilyAssembler> assembler;
  std::vector<double> u, v, out;
  double bonds_total = 0;

  Body(const std::string& law_name, const std::string& rule, int n, bool matrix) {
    pd::Scene s;
    s.dim = 2, s.h = 1.0;
    s.lo = {-0.5, -0.5, 0}, s.hi = {n - 0.5, n - 0.5, 0};
    s.materials.resize(1);
    particles = pd::discretize(s);
    const auto& law = *pd::abi::find_law(law_name);
    const auto w = pd::abi::find_influence("const")->weight;
    const double delta = 3.0;
    bonds = pd::find_quadrature_bonds(
        particles, delta, 1.0, rule == "volume" ? pd::Quadrature::Volume : pd::Quadrature::PartialLinear, w);
    pd::AssemblerOptions o;
    o.matrix = matrix;
    o.threads = 1;
    o.intact = true;
    bonds_total = bonds.bond_count();
    if (rule == "gauss1" || rule == "gauss2") {
      pd::GaussPointOptions go;
      go.per_axis = rule == "gauss1" ? 1 : 2;
      gp = std::make_unique<pd::GaussPoints>(pd::build_gauss_points(particles, 1.0, delta, w, go));
      o.gauss_points = gp.get();
      bonds_total = gp->bond_count();
    }
    const auto m =
        pd::IsotropicElastic::from_E_nu(1.0, law.has_fixed_poisson_ratio ? law.poisson_ratio : 0.3);
    const auto params = pd::law_parameters(law, m, pd::PlaneAssumption::Strain, {});
    assembler = std::make_unique<pd::FamilyAssembler>(particles, bonds, law,
                                                      std::vector<std::vector<double>>{params}, o);
    u.resize(particles.x.size()), v.resize(u.size()), out.resize(u.size());
    std::mt19937 rng(1);
    std::uniform_real_distribution<double> U(-1e-3, 1e-3);
    for (double& x : u) x = U(rng);
    for (double& x : v) x = U(rng);
  }
};

void counters(benchmark::State& state, const Body& b) {
  const double calls = static_cast<double>(state.iterations());
  state.counters["bonds_per_particle"] = b.bonds_total / b.particles.size();
  state.counters["ns_per_bond"] = benchmark::Counter(
      calls * b.bonds_total * 1e-9, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.counters["ns_per_particle"] = benchmark::Counter(
      calls * b.particles.size() * 1e-9, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void forces(benchmark::State& state, std::string law, std::string rule) {
  Body b(law, rule, static_cast<int>(state.range(0)), false);
  for (auto _ : state) {
    b.assembler->internal_forces(b.u.data(), b.out.data());
    benchmark::DoNotOptimize(b.out.data());
  }
  counters(state, b);
}

void product(benchmark::State& state, std::string law, std::string rule) {
  Body b(law, rule, static_cast<int>(state.range(0)), false);
  for (auto _ : state) {
    b.assembler->stiffness_product(b.u.data(), b.v.data(), b.out.data());
    benchmark::DoNotOptimize(b.out.data());
  }
  counters(state, b);
}

void stiffness(benchmark::State& state, std::string law, std::string rule) {
  Body b(law, rule, static_cast<int>(state.range(0)), true);
  pd::SparseMatrix K = b.assembler->make_matrix();
  for (auto _ : state) {
    b.assembler->stiffness(b.u.data(), K, b.out.data());
    benchmark::DoNotOptimize(K.valuePtr());
  }
  counters(state, b);
  state.counters["nonzeros_per_particle"] = static_cast<double>(K.nonZeros()) / b.particles.size();
}

void register_all() {
  for (const char* law : {"lps_plane_strain", "bond_based_constant_2d"})
    for (const char* rule : {"volume", "linear", "gauss1", "gauss2"}) {
      const std::string tail = std::string("/") + law + "/" + rule;
      benchmark::RegisterBenchmark(("forces" + tail).c_str(), forces, law, rule)
          ->Arg(40)
          ->Unit(benchmark::kMillisecond);
      benchmark::RegisterBenchmark(("product" + tail).c_str(), product, law, rule)
          ->Arg(40)
          ->Unit(benchmark::kMillisecond);
      benchmark::RegisterBenchmark(("stiffness" + tail).c_str(), stiffness, law, rule)
          ->Arg(24)
          ->Unit(benchmark::kMillisecond);
    }
}

}  // namespace

int main(int argc, char** argv) {
  register_all();
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}

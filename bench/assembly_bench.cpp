// Global assembly throughput: internal forces, the stiffness matrix and the matrix-free
// product K v over 2D grids, at delta/h = 1.5 and 3.5, on 1 and 2 threads (Silling's law,
// cubic influence). Counters: families per second and stiffness nonzeros per second.
//
//   build/bin/assembly_bench --benchmark_repetitions=3
#include <benchmark/benchmark.h>
#include <omp.h>

#include <map>
#include <memory>

#include "assembly/assembler.hpp"
#include "discretize/discretization.hpp"
#include "material/elastic_constants.hpp"

namespace {
struct Grid {
  pd::Scene scene;
  pd::Particles p;
  pd::Bonds b;
  std::unique_ptr<pd::FamilyAssembler> a;
  std::vector<double> u;
  Grid(int n, double ratio) {
    scene.dim = 2;
    scene.lo = {0, 0, 0};
    scene.hi = {1, 1, 0};
    scene.h = 1.0 / n;
    scene.materials.resize(1);
    p = pd::discretize(scene);
    const auto* law = pd::abi::find_law("silling_plane_strain");
    b = pd::find_bonds(p, ratio * scene.h, pd::abi::find_influence("cubic")->weight);
    const auto m = pd::IsotropicElastic::from_E_nu(1.0, 0.25);
    pd::AssemblerOptions o;
    o.intact = true;
    a = std::make_unique<pd::FamilyAssembler>(p, b, *law, std::vector<std::vector<double>>{pd::law_parameters(*law, m, pd::PlaneAssumption::Strain, {})}, o);
    u.assign(p.x.size(), 0.0);
    for (std::size_t i = 0; i < u.size(); ++i) u[i] = 1e-3 * p.x[i];
  }
};

Grid& grid(int n, double ratio) {
  static std::map<std::pair<int, double>, std::unique_ptr<Grid>> cache;
  auto& g = cache[{n, ratio}];
  if (!g) g = std::make_unique<Grid>(n, ratio);
  return *g;
}

void set_counters(benchmark::State& state, const Grid& g, bool matrix) {
  const double families = static_cast<double>(g.p.size());
  state.counters["families_per_s"] = benchmark::Counter(families, benchmark::Counter::kIsIterationInvariantRate);
  if (matrix)
    state.counters["nonzeros_per_s"] =
        benchmark::Counter(static_cast<double>(g.a->pattern().nonzeros()), benchmark::Counter::kIsIterationInvariantRate);
  state.counters["particles"] = families;
}

void BM_forces(benchmark::State& state) {
  Grid& g = grid(static_cast<int>(state.range(0)), state.range(1) / 10.0);
  omp_set_num_threads(static_cast<int>(state.range(2)));
  std::vector<double> f(g.u.size());
  for (auto _ : state) g.a->internal_forces(g.u.data(), f.data());
  set_counters(state, g, false);
}

void BM_stiffness(benchmark::State& state) {
  Grid& g = grid(static_cast<int>(state.range(0)), state.range(1) / 10.0);
  omp_set_num_threads(static_cast<int>(state.range(2)));
  pd::SparseMatrix K;
  std::vector<double> f(g.u.size());
  for (auto _ : state) g.a->stiffness(g.u.data(), K, f.data());
  set_counters(state, g, true);
}

void BM_matrix_free_product(benchmark::State& state) {
  Grid& g = grid(static_cast<int>(state.range(0)), state.range(1) / 10.0);
  omp_set_num_threads(static_cast<int>(state.range(2)));
  std::vector<double> out(g.u.size());
  for (auto _ : state) g.a->stiffness_product(g.u.data(), g.u.data(), out.data());
  set_counters(state, g, false);
}

// Args: particles along x, 10 * delta/h, threads.
#define PD_GRID_ARGS ArgsProduct({{100, 200}, {15, 35}, {1, 2}})->Unit(benchmark::kMillisecond)->UseRealTime()
BENCHMARK(BM_forces)->PD_GRID_ARGS;
BENCHMARK(BM_stiffness)->PD_GRID_ARGS;
BENCHMARK(BM_matrix_free_product)->PD_GRID_ARGS;
}  // namespace

BENCHMARK_MAIN();

// Global assembly throughput with pd::FamilyAssembler (runtime/assembly/assembler.hpp):
// Silling's plane-strain law, cubic influence, n x n grids of the unit square at
// delta/h = 1.5 and 3.5, on 1 and 2 threads:
//   forces             internal nodal forces f(u)
//   stiffness_product  matrix-free K(u) v from the generated tangent-vector product
//   stiffness          K(u) = -df/du and f(u) together (what a Newton step needs), written
//                      into the two-horizon pattern's precomputed slots
//   sparse_product     K v with the assembled matrix (Eigen, 1 thread), for comparison
// Counters: families/s (particles/s), nonzeros/s of K, bonds and K nonzeros per particle,
// and the peak resident memory per particle (VmHWM, reset through /proc/self/clear_refs
// before each grid is built, minus the resident memory before it):
//   peak_bytes_per_particle  of the matrix-free setup (particles, bonds, assembler) while
//                            forces and K v run; of the assembled setup (plus pattern,
//                            slots and K) while the stiffness runs.
// Names: <operation>/<n>/<10 delta/h>/<threads>. The grids are built lazily and one at a
// time (the previous one is freed first); bench/run.sh runs one grid per process.
//
//   build/bin/assembly_bench --benchmark_filter='/200/35/' --benchmark_repetitions=3
//   build/bin/assembly_bench --grids=100,200 --max_nonzeros=2e8   (which cases to register;
//   the assembled cases only for grids whose K has at most max_nonzeros entries)
//   build/bin/assembly_bench --chunk_size=256   (AssemblerOptions::chunk_size: runs of family
//   indices instead of the default tiles, to compare the visiting orders)
//   build/bin/assembly_bench --law=bond_based_conical_2d   (another 2D law; a law without
//   states gets the one-horizon pattern)
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "assembly/assembler.hpp"
#include "discretize/discretization.hpp"
#include "material/elastic_constants.hpp"

namespace {

int g_chunk_size = 0;                        // --chunk_size
std::string g_law = "silling_plane_strain";  // --law

// Resident set size and its peak, bytes (/proc/self/status).
long status_kb(const char* key) {
  std::ifstream in("/proc/self/status");
  std::string line;
  const std::size_t n = std::strlen(key);
  while (std::getline(in, line))
    if (line.compare(0, n, key) == 0) return std::atol(line.c_str() + n + 1);
  return -1;
}
double rss_bytes() { return 1024.0 * static_cast<double>(status_kb("VmRSS")); }
double peak_rss_bytes() { return 1024.0 * static_cast<double>(status_kb("VmHWM")); }
// Resets VmHWM to the current RSS (Linux >= 4.0); false when not permitted.
bool reset_peak() {
  std::ofstream out("/proc/self/clear_refs");
  out << "5";
  out.flush();
  return static_cast<bool>(out);
}

struct Grid {
  int n;
  int ratio10;
  bool matrix;
  double rss_before = 0;  // resident bytes before this grid was built
  bool peak_reset = false;
  pd::Scene scene;
  pd::Particles p;
  pd::Bonds b;
  std::unique_ptr<pd::FamilyAssembler> a;
  pd::SparseMatrix K;
  std::vector<double> u, v, out;

  Grid(int n_, int ratio10_, bool matrix_) : n(n_), ratio10(ratio10_), matrix(matrix_) {
    peak_reset = reset_peak();
    rss_before = rss_bytes();
    scene.dim = 2;
    scene.lo = {0, 0, 0};
    scene.hi = {1, 1, 0};
    scene.h = 1.0 / n;
    scene.materials.resize(1);
    p = pd::discretize(scene);
    const auto* law = pd::abi::find_law(g_law);
    if (law == nullptr) throw std::invalid_argument("assembly_bench: no law " + g_law);
    b = pd::find_bonds(p, ratio10 / 10.0 * scene.h, pd::abi::find_influence("cubic")->weight);
    const auto m = pd::IsotropicElastic::from_E_nu(1.0, 0.25);
    pd::AssemblerOptions o;
    o.intact = true;  // no broken bond: the variant with alpha folded to 1
    o.matrix = matrix;
    o.chunk_size = g_chunk_size;
    a = std::make_unique<pd::FamilyAssembler>(
        p, b, *law,
        std::vector<std::vector<double>>{pd::law_parameters(*law, m, pd::PlaneAssumption::Strain, {})}, o);
    u.resize(p.x.size());
    v.resize(p.x.size());
    out.assign(p.x.size(), 0.0);
    for (std::size_t i = 0; i < u.size(); ++i) {
      u[i] = 1e-3 * p.x[i] * p.x[i ^ 1];  // a smooth nonuniform stretch
      v[i] = std::sin(7.0 * p.x[i] + 3.0 * static_cast<double>(i % 2));
    }
    if (matrix) {  // swap, not assign: Eigen 3.4's SparseMatrix has no move assignment (a copy doubles K)
      pd::SparseMatrix fresh = a->make_matrix();
      K.swap(fresh);
    }
  }
  // Entries of all families' dense local matrices, sum of ((L+1) dim)^2: what one
  // stiffness assembly forms and scatters.
  double local_entries() const {
    double e = 0;
    for (int q = 0; q < p.size(); ++q) e += std::pow((b.family_size(q) + 1) * p.dim, 2);
    return e;
  }
  double nonzeros() const { return matrix ? static_cast<double>(a->pattern().nonzeros()) : 0.0; }
};

Grid& grid(int n, int ratio10, bool matrix) {
  static std::unique_ptr<Grid> current;
  if (!current || current->n != n || current->ratio10 != ratio10 || current->matrix != matrix) {
    current.reset();  // free the previous grid before building the next
    current = std::make_unique<Grid>(n, ratio10, matrix);
  }
  return *current;
}

void set_counters(benchmark::State& state, const Grid& g, double nonzeros_per_iteration) {
  const double families = static_cast<double>(g.p.size());
  state.counters["families_per_s"] =
      benchmark::Counter(families, benchmark::Counter::kIsIterationInvariantRate);
  if (nonzeros_per_iteration > 0)
    state.counters["nonzeros_per_s"] =
        benchmark::Counter(nonzeros_per_iteration, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["particles"] = families;
  state.counters["bonds_per_particle"] = static_cast<double>(g.b.bond_count()) / families;
  if (g.matrix) state.counters["nonzeros_per_particle"] = g.nonzeros() / families;
  state.counters["local_entries_per_particle"] = g.local_entries() / families;
  state.counters["colours"] = g.a->colouring().colours();
  if (g.peak_reset) state.counters["peak_bytes_per_particle"] = (peak_rss_bytes() - g.rss_before) / families;
}

struct Args {
  int n, ratio10, threads;
};

void BM_forces(benchmark::State& state, Args a) {
  Grid& g = grid(a.n, a.ratio10, false);
  g.a->set_threads(a.threads);
  g.a->internal_forces(g.u.data(), g.out.data());  // warm-up (first touch, thread pool)
  for (auto _ : state) {
    g.a->internal_forces(g.u.data(), g.out.data());
    benchmark::ClobberMemory();
  }
  set_counters(state, g, 0);
}

void BM_stiffness_product(benchmark::State& state, Args a) {
  Grid& g = grid(a.n, a.ratio10, false);
  g.a->set_threads(a.threads);
  g.a->stiffness_product(g.u.data(), g.v.data(), g.out.data());  // warm-up
  for (auto _ : state) {
    g.a->stiffness_product(g.u.data(), g.v.data(), g.out.data());
    benchmark::ClobberMemory();
  }
  set_counters(state, g, 0);
}

void BM_stiffness(benchmark::State& state, Args a) {
  Grid& g = grid(a.n, a.ratio10, true);
  g.a->set_threads(a.threads);
  g.a->stiffness(g.u.data(), g.K, g.out.data());  // warm-up: the first assembly in a process is slower
  for (auto _ : state) {
    g.a->stiffness(g.u.data(), g.K, g.out.data());
    benchmark::ClobberMemory();
  }
  set_counters(state, g, g.nonzeros());
}

void BM_sparse_product(benchmark::State& state, Args a) {
  Grid& g = grid(a.n, a.ratio10, true);
  g.a->stiffness(g.u.data(), g.K, nullptr);
  Eigen::Map<const Eigen::VectorXd> v(g.v.data(), static_cast<Eigen::Index>(g.v.size()));
  Eigen::Map<Eigen::VectorXd> out(g.out.data(), static_cast<Eigen::Index>(g.out.size()));
  for (auto _ : state) {
    out.noalias() = g.K * v;
    benchmark::ClobberMemory();
  }
  set_counters(state, g, g.nonzeros());
}

std::vector<int> int_list(const std::string& s) {
  std::vector<int> v;
  std::stringstream in(s);
  std::string item;
  while (std::getline(in, item, ',')) v.push_back(std::atoi(item.c_str()));
  return v;
}

// Per grid: the matrix-free operations first, then the assembled ones (so the peak of
// the matrix-free setup is measured before the pattern exists).
void register_all(const std::vector<int>& sizes, double max_nonzeros) {
  for (int n : sizes)
    for (int r : {15, 35}) {
      auto reg = [&](const char* op, void (*fn)(benchmark::State&, Args), int threads) {
        const std::string name = std::string(op) + "/" + std::to_string(n) + "/" + std::to_string(r) + "/" +
                                 std::to_string(threads);
        benchmark::RegisterBenchmark(name.c_str(), fn, Args{n, r, threads})
            ->Unit(benchmark::kMillisecond)
            ->UseRealTime();
      };
      for (int t : {1, 2}) reg("forces", BM_forces, t);
      for (int t : {1, 2}) reg("stiffness_product", BM_stiffness_product, t);
      // The assembled cases only where K fits comfortably: its nonzeros are about
      // 4 n^2 (lattice points within two horizons), 6e8 for 1000^2 at delta/h = 3.5
      // (about 15 GB with the slots, on a shared 23 GB machine).
      int reach = 0;
      for (int i = -r / 5; i <= r / 5; ++i)
        for (int j = -r / 5; j <= r / 5; ++j) reach += 100 * (i * i + j * j) <= r * r * 4 ? 1 : 0;
      if (4.0 * n * n * reach > max_nonzeros) continue;
      for (int t : {1, 2}) reg("stiffness", BM_stiffness, t);
      reg("sparse_product", BM_sparse_product, 1);
    }
}
}  // namespace

int main(int argc, char** argv) {
  std::vector<int> sizes = {100, 200, 400, 1000};
  double max_nonzeros = 2e8;
  std::vector<char*> rest;
  for (int i = 0; i < argc; ++i) {
    if (std::strncmp(argv[i], "--grids=", 8) == 0)
      sizes = int_list(argv[i] + 8);
    else if (std::strncmp(argv[i], "--law=", 6) == 0)
      g_law = argv[i] + 6;
    else if (std::strncmp(argv[i], "--chunk_size=", 13) == 0)
      g_chunk_size = std::atoi(argv[i] + 13);
    else if (std::strncmp(argv[i], "--max_nonzeros=", 15) == 0)
      max_nonzeros = std::atof(argv[i] + 15);
    else
      rest.push_back(argv[i]);
  }
  int n = static_cast<int>(rest.size());
  register_all(sizes, max_nonzeros);
  benchmark::Initialize(&n, rest.data());
  if (benchmark::ReportUnrecognizedArguments(n, rest.data())) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}

// Kernel benchmarks: the generated residual, tangent factors, dense local tangent and
// tangent-vector product, against the tangent by forward automatic differentiation of
// a hand-written templated residual (Eigen AutoDiffScalar, as Peridigm does with Sacado
// for its elastic models) and by central finite differences of the generated residual
// (Peridigm's default for other models). Families are perturbed lattices at the
// horizon ratios of paper 000 (2D: delta/h = 1.5, 2, 3, 3.5) and 3D delta/h = 3.
//
//   build/bin/kernel_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <Eigen/Core>
#include <unsupported/Eigen/AutoDiff>

#include "verify/random_family.hpp"
#include "verify/reference_silling.hpp"

namespace {
using pd::verify::FamilyOptions;
using pd::verify::TestFamily;

TestFamily bench_family(const char* law_name, double ratio) {
  const auto* law = pd::abi::find_law(law_name);
  if (law == nullptr) throw std::runtime_error(std::string("no law ") + law_name);
  FamilyOptions o;
  o.dim = law->dim;
  o.horizon_ratio = ratio;
  o.seed = 3;
  return pd::verify::make_family(*law, o);
}

void label(benchmark::State& state, const TestFamily& f) {
  state.counters["bonds"] = f.bonds();
  state.SetLabel(f.law->name);
}

void BM_generated_residual(benchmark::State& state, const char* law, double ratio) {
  TestFamily f = bench_family(law, ratio);
  std::vector<double> forces(static_cast<std::size_t>(f.dofs()));
  for (auto _ : state) {
    f.law->intact.residual(f.view(), forces.data());
    benchmark::DoNotOptimize(forces.data());
  }
  label(state, f);
}

void BM_generated_tangent_factors(benchmark::State& state, const char* law, double ratio) {
  TestFamily f = bench_family(law, ratio);
  pd::TangentScratch scratch;
  const auto fac = scratch.view(f.dim, f.law->n_states, f.bonds());
  std::vector<double> forces(static_cast<std::size_t>(f.dofs()));
  for (auto _ : state) {
    f.law->intact.tangent(f.view(), forces.data(), fac);
    benchmark::DoNotOptimize(fac.direct);
  }
  label(state, f);
}

void BM_generated_tangent_dense(benchmark::State& state, const char* law, double ratio) {
  TestFamily f = bench_family(law, ratio);
  pd::TangentScratch scratch;
  const auto fac = scratch.view(f.dim, f.law->n_states, f.bonds());
  std::vector<double> forces(static_cast<std::size_t>(f.dofs())), M(static_cast<std::size_t>(f.dofs() * f.dofs()));
  for (auto _ : state) {
    f.law->intact.tangent(f.view(), forces.data(), fac);
    pd::form_local_matrix(f.dim, f.law->n_states, f.view(), fac, M.data());
    benchmark::DoNotOptimize(M.data());
  }
  label(state, f);
}

void BM_generated_jvp(benchmark::State& state, const char* law, double ratio) {
  TestFamily f = bench_family(law, ratio);
  std::vector<double> dy(static_cast<std::size_t>(f.dofs()), 0.1), df(dy.size());
  for (auto _ : state) {
    f.law->intact.jvp(f.view(), dy.data(), df.data());
    benchmark::DoNotOptimize(df.data());
  }
  label(state, f);
}

void BM_forward_ad_tangent_dense(benchmark::State& state, const char* law, double ratio) {
  TestFamily f = bench_family(law, ratio);
  const int n = f.dofs();
  using AD = Eigen::AutoDiffScalar<Eigen::VectorXd>;
  std::vector<AD> y(static_cast<std::size_t>(n)), forces(static_cast<std::size_t>(n));
  std::vector<double> M(static_cast<std::size_t>(n * n));
  for (auto _ : state) {
    for (int i = 0; i < n; ++i) y[i] = AD(f.y[i], n, i);
    pd::verify::silling_forces<AD>(f.dim, f.bonds(), f.xi.data(), f.w.data(), f.alpha.data(), f.V.data(), f.V0,
                                   f.params[0], f.params[1], y.data(), forces.data());
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) M[i * n + j] = forces[i].derivatives()[j];
    benchmark::DoNotOptimize(M.data());
  }
  label(state, f);
}

void BM_central_fd_tangent_dense(benchmark::State& state, const char* law, double ratio) {
  TestFamily f = bench_family(law, ratio);
  for (auto _ : state) {
    auto M = f.fd_matrix(f.law->intact, 1e-6 * f.delta);
    benchmark::DoNotOptimize(M.data());
  }
  label(state, f);
}

#define PD_KERNEL_BENCH(fn)                                                       \
  BENCHMARK_CAPTURE(fn, plane_strain_1_5, "silling_plane_strain", 1.5);           \
  BENCHMARK_CAPTURE(fn, plane_strain_2_0, "silling_plane_strain", 2.0);           \
  BENCHMARK_CAPTURE(fn, plane_strain_3_0, "silling_plane_strain", 3.0);           \
  BENCHMARK_CAPTURE(fn, plane_strain_3_5, "silling_plane_strain", 3.5);           \
  BENCHMARK_CAPTURE(fn, three_d_3_0, "silling_3d", 3.0);

PD_KERNEL_BENCH(BM_generated_residual)
PD_KERNEL_BENCH(BM_generated_tangent_factors)
PD_KERNEL_BENCH(BM_generated_tangent_dense)
PD_KERNEL_BENCH(BM_generated_jvp)
PD_KERNEL_BENCH(BM_forward_ad_tangent_dense)
PD_KERNEL_BENCH(BM_central_fd_tangent_dense)
}  // namespace

BENCHMARK_MAIN();

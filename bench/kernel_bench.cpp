// Kernel benchmarks, one family at a time, for four elastic laws (Silling, Oterkus,
// correspondence, bond-based with constant micromodulus) at the neighbour counts of a square
// lattice with delta/h = 1.5, 2, 3, 3.5 and sqrt(13) (8, 12, 28, 36, 44 bonds) in 2D and
// delta/h = 3 (122 bonds) in 3D, and for Mitchell's elastic-plastic law (a law with memory:
// the incremental residual from a committed plastic extension, on the yielding branch) at
// 2D delta/h 3.5 and 3D delta/h 3:
//   generated residual, tangent factors, tangent formed into the dense local matrix
//   by the law's generated form kernel and by the generic form_local_matrix, the pair
//   blocks of a law without states (form_pair_blocks), tangent-vector product (JVP);
//   the dense tangent by forward-mode AD of a hand-written templated residual over all
//   (L+1)*dim family dofs: Trilinos Sacado's DFad (Peridigm's approach) and SLFad
//   (fixed capacity), when the build found Sacado; Eigen's AutoDiffScalar with a heap
//   derivative vector (VectorXd) and with a fixed-capacity one (no allocation at all);
//   the dense tangent by central finite differences of the generated residual (one
//   residual pair per dof, Peridigm's default), allocation-free.
// Before timing, the AD and FD benchmarks check their matrix against the generated one
// (max |difference| / max |entry| <= 1e-8) and the reference residual against the
// generated residual; a mismatch prints the numbers and exits with status 2.
//
//   build/bin/kernel_bench --benchmark_repetitions=5 --benchmark_min_time=0.1
#include <benchmark/benchmark.h>

#include <Eigen/Core>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <unsupported/Eigen/AutoDiff>
#include <vector>
#ifdef PD_HAVE_SACADO
#include <Sacado_No_Kokkos.hpp>
#endif

#include "reference_laws.hpp"
#include "verify/random_family.hpp"

namespace {
using pd::verify::TestFamily;

enum class Ref { Silling, Oterkus, Correspondence, BondBased, ElasticPlastic };

struct Case {
  const char* law;
  Ref ref;
  double ratio;  // delta/h of the lattice
  const char* ratio_label;
};

constexpr double kTolerance = 1e-8;           // AD and FD tangents against the generated one
constexpr double kResidualTolerance = 1e-12;  // hand-written residual against the generated one
constexpr double kFdStep = 1e-5;              // central-difference step, times the lattice spacing

// A perturbed square (cubic) lattice neighbourhood: the neighbours are the lattice
// points with |index| <= delta/h, so the bond count is the lattice's (8, 12, 28, 36, 44;
// 122), then every position moves by up to 0.1 h and the family deforms by a random
// displacement gradient (5%) plus noise, as runtime/verify/random_family.hpp does.
TestFamily lattice_family(const pd::abi::LawDescriptor& law, double ratio, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const int d = law.dim;
  const double h = 1.0 + 0.2 * u(rng);
  TestFamily f;
  f.dim = d;
  f.law = &law;
  f.delta = ratio * h;
  f.V0 = std::pow(h, d);
  for (int c = 0; c < d; ++c) f.x.push_back(0.1 * h * u(rng));
  const int n = static_cast<int>(std::ceil(ratio));
  for (int i = -n; i <= n; ++i)
    for (int j = -n; j <= n; ++j)
      for (int l = (d == 3 ? -n : 0); l <= (d == 3 ? n : 0); ++l) {
        if ((i == 0 && j == 0 && l == 0) || i * i + j * j + l * l > ratio * ratio * (1 + 1e-12)) continue;
        const int idx[3] = {i, j, l};
        for (int c = 0; c < d; ++c) f.x.push_back(idx[c] * h + 0.1 * h * u(rng));
      }
  const int L = static_cast<int>(f.x.size()) / d - 1;
  f.xi.resize(static_cast<std::size_t>(L * d));
  f.Y.resize(f.xi.size());
  for (int k = 0; k < L; ++k) {
    for (int c = 0; c < d; ++c) f.xi[k * d + c] = f.x[(k + 1) * d + c] - f.x[c];
    f.w.push_back(0.2 + 0.4 * (u(rng) + 1.0));
    f.V.push_back(f.V0 * (0.8 + 0.2 * (u(rng) + 1.0)));
    f.alpha.push_back(1.0);
  }
  for (int p = 0; p < law.n_params; ++p) f.params.push_back(0.5 + 0.5 * (u(rng) + 1.0));
  double H[9];
  for (double& e : H) e = 0.05 * u(rng);
  std::vector<double> y(f.x.size());
  for (int a = 0; a <= L; ++a)
    for (int r = 0; r < d; ++r) {
      double v = f.x[a * d + r] + 0.01 * h * u(rng);
      for (int c = 0; c < d; ++c) v += H[r * 3 + c] * f.x[a * d + c];
      y[a * d + r] = v;
    }
  f.set_positions(y);
  f.update_moments(law.intact);
  return f;
}

TestFamily family(const Case& c) {
  const auto* law = pd::abi::find_law(c.law);
  if (law == nullptr) {
    std::fprintf(stderr, "kernel_bench: no law %s\n", c.law);
    std::exit(2);
  }
  TestFamily f = lattice_family(*law, c.ratio, 3);
  if (c.ref == Ref::ElasticPlastic) {
    // A step on the yielding branch from a committed plastic state: sigma_y well below the
    // family's deviatoric stress (strain ~ 5%, G ~ 0.75), and a plastic extension of up to
    // 1% of each bond's length already committed.
    f.params[2] = 0.01;
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    f.history.resize(static_cast<std::size_t>(f.bonds()));
    for (int k = 0; k < f.bonds(); ++k)
      f.history[static_cast<std::size_t>(k)] =
          0.01 * pd::bench::detail::norm(f.xi.data() + k * f.dim, f.dim) * u(rng);
    std::vector<double> forces(static_cast<std::size_t>(f.dofs()));
    pd::bench::Workspace<double> w;
    pd::bench::elastic_plastic(f.view(), f.dim, f.y.data(), forces.data(), w);
    // Clear of the yield surface, so that no central difference straddles the kink.
    if (w.yield_ratio < 1.1) {
      std::fprintf(stderr, "kernel_bench: the %s family is not yielding (||t||^2 / 2 psi0 = %.3g)\n", c.law,
                   w.yield_ratio);
      std::exit(2);
    }
  }
  return f;
}

template <class S>
void reference(Ref r, const pd::abi::Family& fam, int d, const S* y, S* f, pd::bench::Workspace<S>& w) {
  switch (r) {
    case Ref::Silling:
      return pd::bench::silling(fam, d, y, f, w);
    case Ref::Oterkus:
      return pd::bench::oterkus(fam, d, y, f, w);
    case Ref::Correspondence:
      return pd::bench::correspondence(fam, d, y, f, w);
    case Ref::BondBased:
      return pd::bench::bond_based_constant(fam, d, y, f, w);
    case Ref::ElasticPlastic:
      return pd::bench::elastic_plastic(fam, d, y, f, w);
  }
}

double rel_diff(const std::vector<double>& a, const std::vector<double>& b) {
  double diff = 0, scale = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    diff = std::max(diff, std::abs(a[i] - b[i]));
    scale = std::max(scale, std::abs(b[i]));
  }
  return diff / scale;
}

void check(const char* what, const Case& c, const TestFamily& f, double diff, double tol) {
  if (diff <= tol) return;
  std::fprintf(stderr,
               "kernel_bench: %s of %s at %d bonds differs from the generated kernel: %.3g > %.0e relative\n",
               what, c.law, f.bonds(), diff, tol);
  std::exit(2);
}

void label(benchmark::State& state, const TestFamily& f) {
  state.counters["bonds"] = f.bonds();
  state.counters["dofs"] = f.dofs();
}

// Forward AD over all family dofs: seed y, evaluate the templated residual, read the
// derivative vectors into the dense row-major matrix. AD is an Eigen AutoDiffScalar or a
// Sacado Fad; the inputs' derivative storage is sized once and reseeded in place, as a
// careful Peridigm-style user would (Peridigm builds Fad(n, i, value) per dof per call).
template <class AD>
struct ForwardAd {
  static constexpr bool kSacado = requires(AD x) { x.fastAccessDx(0); };
  Ref ref;
  const TestFamily& f;
  int n;
  std::vector<AD> y, F;
  pd::bench::Workspace<AD> w;
  ForwardAd(Ref r, const TestFamily& fam) : ref(r), f(fam), n(fam.dofs()), y(n), F(n) {
    if constexpr (kSacado)
      for (int i = 0; i < n; ++i) y[i] = AD(n, i, f.y[i]);
  }
  double value(int i) const {
    if constexpr (kSacado)
      return F[i].val();
    else
      return F[i].value();
  }
  void run(double* M) {
    for (int i = 0; i < n; ++i) {
      if constexpr (kSacado) {
        y[i].val() = f.y[i];  // the seeds stay e_i: the residual never writes its inputs
      } else {
        y[i].value() = f.y[i];
        y[i].derivatives().setZero(n);
        y[i].derivatives()[i] = 1.0;
      }
    }
    reference(ref, f.view(), f.dim, y.data(), F.data(), w);
    for (int i = 0; i < n; ++i) {
      if constexpr (kSacado) {
        // A force no dof reaches stays a constant with no derivative entries.
        if (F[i].size() == 0)
          for (int j = 0; j < n; ++j) M[i * n + j] = 0.0;
        else
          for (int j = 0; j < n; ++j) M[i * n + j] = F[i].fastAccessDx(j);
      } else {
        for (int j = 0; j < n; ++j) M[i * n + j] = F[i].derivatives()[j];
      }
    }
  }
};

// Central differences of the generated residual, perturbing the bond vectors in place
// (a center dof moves every Y_k, a neighbour dof one): 2n residual calls, no allocation.
struct CentralFd {
  const TestFamily& f;
  int n, d;
  double step;
  std::vector<double> Y, fp, fm;
  explicit CentralFd(const TestFamily& fam)
      : f(fam),
        n(fam.dofs()),
        d(fam.dim),
        step(kFdStep * std::pow(fam.V0, 1.0 / fam.dim)),
        Y(fam.Y),
        fp(n),
        fm(n) {}
  void shift(int j, double s) {
    const int a = j / d, c = j % d;
    if (a == 0)
      for (int k = 0; k < f.bonds(); ++k) Y[k * d + c] -= s;
    else
      Y[(a - 1) * d + c] += s;
  }
  void restore(int j) {
    const int a = j / d, c = j % d;
    if (a == 0)
      for (int k = 0; k < f.bonds(); ++k) Y[k * d + c] = f.Y[k * d + c];
    else
      Y[(a - 1) * d + c] = f.Y[(a - 1) * d + c];
  }
  void run(double* M) {
    pd::abi::Family fam = f.view();
    fam.Y = Y.data();
    const auto residual = f.law->intact.residual;
    const double inv = 1.0 / (2 * step);
    for (int j = 0; j < n; ++j) {
      shift(j, step);
      residual(fam, fp.data());
      restore(j);
      shift(j, -step);
      residual(fam, fm.data());
      restore(j);
      for (int i = 0; i < n; ++i) M[i * n + j] = (fp[i] - fm[i]) * inv;
    }
  }
};

void BM_generated_residual(benchmark::State& state, Case c) {
  const TestFamily f = family(c);
  std::vector<double> forces(static_cast<std::size_t>(f.dofs()));
  const pd::abi::Family fam = f.view();
  for (auto _ : state) {
    f.law->intact.residual(fam, forces.data());
    benchmark::DoNotOptimize(forces.data());
    benchmark::ClobberMemory();
  }
  label(state, f);
}

void BM_generated_tangent_factors(benchmark::State& state, Case c) {
  const TestFamily f = family(c);
  pd::TangentScratch scratch;
  const auto fac = scratch.view(f.dim, f.law->n_states, f.bonds());
  std::vector<double> forces(static_cast<std::size_t>(f.dofs()));
  const pd::abi::Family fam = f.view();
  for (auto _ : state) {
    f.law->intact.tangent(fam, forces.data(), fac);
    benchmark::DoNotOptimize(fac.direct);
    benchmark::ClobberMemory();
  }
  label(state, f);
}

// The dense local matrix from the factors: the law's generated form kernel (structural
// zeros skipped), or with `generic` runtime/local_matrix.hpp's forming for any law.
void BM_generated_tangent_dense(benchmark::State& state, Case c, bool generic) {
  const TestFamily f = family(c);
  pd::TangentScratch scratch;
  const auto fac = scratch.view(f.dim, f.law->n_states, f.bonds());
  std::vector<double> forces(static_cast<std::size_t>(f.dofs())),
      M(static_cast<std::size_t>(f.dofs() * f.dofs()));
  const pd::abi::Family fam = f.view();
  const pd::abi::KernelVariant& v = f.law->intact;
  for (auto _ : state) {
    v.tangent(fam, forces.data(), fac);
    if (generic)
      pd::form_local_matrix(f.dim, f.law->n_states, fam, fac, M.data());
    else
      pd::form_local_matrix(v, f.dim, f.law->n_states, fam, fac, M.data());
    benchmark::DoNotOptimize(M.data());
    benchmark::ClobberMemory();
  }
  label(state, f);
}

// A law without states: the L+1 pair blocks (local_matrix.hpp), all a one-horizon
// scatter needs, instead of the dense matrix.
void BM_generated_tangent_pair_blocks(benchmark::State& state, Case c) {
  const TestFamily f = family(c);
  pd::TangentScratch scratch;
  const auto fac = scratch.view(f.dim, 0, f.bonds());
  std::vector<double> forces(static_cast<std::size_t>(f.dofs())),
      B(static_cast<std::size_t>((f.bonds() + 1) * f.dim * f.dim));
  const pd::abi::Family fam = f.view();
  for (auto _ : state) {
    f.law->intact.tangent(fam, forces.data(), fac);
    pd::form_pair_blocks(f.dim, fam, fac, B.data());
    benchmark::DoNotOptimize(B.data());
    benchmark::ClobberMemory();
  }
  label(state, f);
}

void BM_generated_jvp(benchmark::State& state, Case c) {
  const TestFamily f = family(c);
  std::vector<double> dy(static_cast<std::size_t>(f.dofs())), df(dy.size());
  for (std::size_t i = 0; i < dy.size(); ++i) dy[i] = std::sin(1.0 + static_cast<double>(i));
  const pd::abi::Family fam = f.view();
  for (auto _ : state) {
    f.law->intact.jvp(fam, dy.data(), df.data());
    benchmark::DoNotOptimize(df.data());
    benchmark::ClobberMemory();
  }
  label(state, f);
}

template <class AD>
void BM_forward_ad_tangent_dense(benchmark::State& state, Case c) {
  const TestFamily f = family(c);
  const int n = f.dofs();
  ForwardAd<AD> ad(c.ref, f);
  std::vector<double> M(static_cast<std::size_t>(n * n)), forces(static_cast<std::size_t>(n));
  ad.run(M.data());
  for (int i = 0; i < n; ++i) forces[i] = ad.value(i);
  check("hand-written residual", c, f, rel_diff(forces, f.forces(f.law->intact)), kResidualTolerance);
  const double diff = rel_diff(M, f.tangent_matrix(f.law->intact));
  check("forward-AD tangent", c, f, diff, kTolerance);
  for (auto _ : state) {
    ad.run(M.data());
    benchmark::DoNotOptimize(M.data());
    benchmark::ClobberMemory();
  }
  label(state, f);
  state.counters["rel_diff"] = diff;
}

void BM_central_fd_tangent_dense(benchmark::State& state, Case c) {
  const TestFamily f = family(c);
  const int n = f.dofs();
  CentralFd fd(f);
  std::vector<double> M(static_cast<std::size_t>(n * n));
  fd.run(M.data());
  const double diff = rel_diff(M, f.tangent_matrix(f.law->intact));
  // Central differences are exact only to O(step^2): on the plastic branch the return map's
  // curvature (the third derivatives of sqrt(2 psi0) / ||t_tr||) takes the error at step
  // 1e-5 h to 2.8e-8 in 2D, above the AD check's 1e-8. FD is then checked at what it can
  // reach; rel_diff reports the error it has.
  check("central-difference tangent", c, f, diff, c.ref == Ref::ElasticPlastic ? 1e-6 : kTolerance);
  for (auto _ : state) {
    fd.run(M.data());
    benchmark::DoNotOptimize(M.data());
    benchmark::ClobberMemory();
  }
  label(state, f);
  state.counters["rel_diff"] = diff;
}

// Derivative vectors: heap (like Sacado DFad) and fixed capacity (stack, no allocation).
using EigenHeapAd = Eigen::AutoDiffScalar<Eigen::VectorXd>;
template <int Max>
using EigenFixedAd = Eigen::AutoDiffScalar<Eigen::Matrix<double, Eigen::Dynamic, 1, 0, Max, 1>>;
constexpr int kMax2d = 45 * 2, kMax3d = 123 * 3;
#ifdef PD_HAVE_SACADO
// Sacado's DFad: the derivative array on the heap, sized at run time (Peridigm's choice);
// SLFad: a fixed-capacity array inside the scalar, Sacado's allocation-free variant.
using SacadoDfad = Sacado::Fad::DFad<double>;
template <int Max>
using SacadoSlfad = Sacado::Fad::SLFad<double, Max>;
#endif

const Case kCases[] = {
    {"silling_plane_strain", Ref::Silling, 1.5, "1.5"},
    {"silling_plane_strain", Ref::Silling, 2.0, "2"},
    {"silling_plane_strain", Ref::Silling, 3.0, "3"},
    {"silling_plane_strain", Ref::Silling, 3.5, "3.5"},
    {"silling_plane_strain", Ref::Silling, 3.6056, "sqrt13"},
    {"oterkus_plane_strain", Ref::Oterkus, 1.5, "1.5"},
    {"oterkus_plane_strain", Ref::Oterkus, 2.0, "2"},
    {"oterkus_plane_strain", Ref::Oterkus, 3.0, "3"},
    {"oterkus_plane_strain", Ref::Oterkus, 3.5, "3.5"},
    {"oterkus_plane_strain", Ref::Oterkus, 3.6056, "sqrt13"},
    {"correspondence_plane_strain", Ref::Correspondence, 1.5, "1.5"},
    {"correspondence_plane_strain", Ref::Correspondence, 2.0, "2"},
    {"correspondence_plane_strain", Ref::Correspondence, 3.0, "3"},
    {"correspondence_plane_strain", Ref::Correspondence, 3.5, "3.5"},
    {"correspondence_plane_strain", Ref::Correspondence, 3.6056, "sqrt13"},
    {"bond_based_constant_2d", Ref::BondBased, 1.5, "1.5"},
    {"bond_based_constant_2d", Ref::BondBased, 2.0, "2"},
    {"bond_based_constant_2d", Ref::BondBased, 3.0, "3"},
    {"bond_based_constant_2d", Ref::BondBased, 3.5, "3.5"},
    {"bond_based_constant_2d", Ref::BondBased, 3.6056, "sqrt13"},
    {"silling_3d", Ref::Silling, 3.0, "3"},
    {"correspondence_3d", Ref::Correspondence, 3.0, "3"},
    {"bond_based_constant_3d", Ref::BondBased, 3.0, "3"},
    {"elastic_plastic_plane_strain", Ref::ElasticPlastic, 3.5, "3.5"},
    {"elastic_plastic_3d", Ref::ElasticPlastic, 3.0, "3"},
};

// Names: <kind>/<law>/<delta/h>; the cases of one family run back to back, so the
// ratios of a row come from measurements minutes apart at most.
void register_all() {
  for (const Case& c : kCases) {
    const std::string suffix = std::string("/") + c.law + "/" + c.ratio_label;
    const bool three_d = pd::abi::find_law(c.law) && pd::abi::find_law(c.law)->dim == 3;
    benchmark::RegisterBenchmark(("generated_residual" + suffix).c_str(), BM_generated_residual, c);
    benchmark::RegisterBenchmark(("generated_tangent_factors" + suffix).c_str(), BM_generated_tangent_factors,
                                 c);
    benchmark::RegisterBenchmark(("generated_tangent_dense" + suffix).c_str(), BM_generated_tangent_dense, c,
                                 false);
    benchmark::RegisterBenchmark(("generic_form_tangent_dense" + suffix).c_str(), BM_generated_tangent_dense,
                                 c, true);
    if (pd::abi::find_law(c.law) && pd::abi::find_law(c.law)->n_states == 0)
      benchmark::RegisterBenchmark(("generated_tangent_pair_blocks" + suffix).c_str(),
                                   BM_generated_tangent_pair_blocks, c);
    benchmark::RegisterBenchmark(("generated_jvp" + suffix).c_str(), BM_generated_jvp, c);
    benchmark::RegisterBenchmark(("forward_ad_tangent_dense" + suffix).c_str(),
                                 BM_forward_ad_tangent_dense<EigenHeapAd>, c);
    benchmark::RegisterBenchmark(("forward_ad_fixed_tangent_dense" + suffix).c_str(),
                                 three_d ? BM_forward_ad_tangent_dense<EigenFixedAd<kMax3d>>
                                         : BM_forward_ad_tangent_dense<EigenFixedAd<kMax2d>>,
                                 c);
#ifdef PD_HAVE_SACADO
    benchmark::RegisterBenchmark(("sacado_dfad_tangent_dense" + suffix).c_str(),
                                 BM_forward_ad_tangent_dense<SacadoDfad>, c);
    benchmark::RegisterBenchmark(("sacado_slfad_tangent_dense" + suffix).c_str(),
                                 three_d ? BM_forward_ad_tangent_dense<SacadoSlfad<kMax3d>>
                                         : BM_forward_ad_tangent_dense<SacadoSlfad<kMax2d>>,
                                 c);
#endif
    benchmark::RegisterBenchmark(("central_fd_tangent_dense" + suffix).c_str(), BM_central_fd_tangent_dense,
                                 c);
  }
}
}  // namespace

int main(int argc, char** argv) {
  register_all();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}

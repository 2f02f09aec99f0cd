// Family loop, colour by colour; the residual, tangent, product and diagonal bodies.
#include "assembly/assembler.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "assembly/moments.hpp"
#include "assembly/peridynamic_stress.hpp"
#include "assembly/scatter.hpp"
#include "local_matrix.hpp"

namespace pd {

namespace {
// Per-thread working set, sized once for the largest family.
struct ThreadScratch {
  FamilyGather gather;
  TangentScratch tangent;
  abi::TangentFactors factors;
  std::vector<int> strides;  // column_stride of each local particle, for the scatter
  ThreadScratch(const FamilyInputs& in, int n_states)
      : gather(in),
        factors(tangent.view(in.dim(), n_states, gather.max_bonds())),
        strides(static_cast<std::size_t>(gather.max_bonds()) + 1) {}
};

// True when all n values are finite: 0*x is 0 for finite x and NaN for NaN or Inf, so
// one branch-free pass decides. Eight independent sums: with one, the additions form a
// dependency chain the compiler may not reorder (no -ffast-math) and the check cost 22%
// of the stiffness assembly, twice the forming of the matrix it checks.
bool all_finite(const double* v, std::size_t n) {
  double s[8] = {};
  std::size_t i = 0;
  for (; i + 8 <= n; i += 8)
    for (int j = 0; j < 8; ++j) s[j] += v[i + j] * 0.0;
  for (; i < n; ++i) s[0] += v[i] * 0.0;
  return ((s[0] + s[1]) + (s[2] + s[3])) + ((s[4] + s[5]) + (s[6] + s[7])) == 0.0;
}
}  // namespace

FamilyAssembler::FamilyAssembler(const Particles& particles, const Bonds& bonds,
                                 const abi::LawDescriptor& law, std::vector<std::vector<double>> params,
                                 AssemblerOptions options)
    : law_(law),
      variant_(options.intact ? law.intact : law.damaged),
      options_(options),
      colouring_(particles, bonds, options.chunk_size) {
  if (options.gauss_points)
    throw std::logic_error("assembler: Gauss points have their own operator (make_force_operator)");
  pair_jump_ = check_law_inputs(particles, law, params, "assembler");
  if (bonds.dim != particles.dim)
    throw std::invalid_argument(std::string("assembler: law ") + law.name + " is " + std::to_string(law.dim) +
                                "D, the body is " + std::to_string(particles.dim) + "D");
  if (bonds.particle_count() != particles.size())
    throw std::invalid_argument("assembler: bonds and particles differ in count");
  inputs_.particles = &particles;
  inputs_.bonds = &bonds;
  inputs_.params = std::move(params);
  inputs_.scratch_per_bond = law.scratch_per_bond;
  inputs_.collocation = options.collocation;
  inputs_.history = options.history;
  inputs_.n_history = law.n_history;
  inputs_.particle_history = options.particle_history;
  inputs_.n_particle_history = law.n_particle_history;
  inputs_.time_step = options.time_step;
  inputs_.cache_max_bonds();
  update_moments();
  const Coupling coupling = options.coupling.value_or(coupling_of_law(law.n_states));
  if (coupling == Coupling::pairwise && law.n_states > 0)
    throw std::invalid_argument(std::string("assembler: law ") + law.name +
                                " has states; its tangent couples every two " +
                                "particles of a family, not only the pairs of the pairwise pattern");
  if (options_.matrix) pattern_ = std::make_unique<SparsityPattern>(bonds, particles.dim, coupling);
}

void FamilyAssembler::update_moments() { compute_moments(inputs_, law_, variant_); }

const SparsityPattern& FamilyAssembler::pattern() const {
  if (!pattern_)
    throw std::logic_error("assembler: built without a matrix pattern (AssemblerOptions::matrix = false)");
  return *pattern_;
}

std::vector<double> FamilyAssembler::stiffness_row_sums(const double* u) const {
  std::unique_ptr<FamilyAssembler> with_pattern;
  if (!pattern_) {
    AssemblerOptions o = options_;
    o.matrix = true;
    with_pattern =
        std::make_unique<FamilyAssembler>(*inputs_.particles, *inputs_.bonds, law_, inputs_.params, o);
  }
  const FamilyAssembler& a = with_pattern ? *with_pattern : *this;
  SparseMatrix K = a.make_matrix();
  a.stiffness(u, K);
  std::vector<double> s(static_cast<std::size_t>(K.rows()), 0.0);
  // Column-major storage: add |K_rc| of each column to its rows.
  for (Eigen::Index c = 0; c < K.outerSize(); ++c)
    for (SparseMatrix::InnerIterator it(K, c); it; ++it)
      s[static_cast<std::size_t>(it.row())] += std::fabs(it.value());
  return s;
}

std::vector<double> FamilyAssembler::stresses(const double* u) const { return peridynamic_stress(*this, u); }

double FamilyAssembler::longest_bond() const {
  const std::vector<double>& length = inputs_.bonds->length;
  return length.empty() ? 0.0 : *std::max_element(length.begin(), length.end());
}

int FamilyAssembler::thread_count() const {
  // An explicit count is obeyed. Otherwise: one thread on small bodies. Each colour ends
  // with a barrier; on a small body the colours hold too little work to pay for it, and
  // when another process holds the second core every barrier waits for a descheduled
  // thread: the 40^2 crack's Jacobi-CG solve (148 products) took 11.4 s on 2 threads
  // beside a build and 0.25 s on 1. Below this many bonds per call, one thread.
  constexpr int kMinBondsForThreads = 200000;
  if (options_.threads > 0) return options_.threads;
  return inputs_.bonds->bond_count() >= kMinBondsForThreads ? omp_get_max_threads() : 1;
}

template <class Body>
void FamilyAssembler::for_each_family(const char* stage, Body&& body) const {
  int bad = -1;
  std::string bad_stage;
#pragma omp parallel num_threads(thread_count())
  {
    ThreadScratch s(inputs_, law_.n_states);
    for (int c = 0; c < colouring_.colours(); ++c) {
      // The implicit barrier at the end of the loop separates the colours.
#pragma omp for schedule(dynamic, 1)
      for (int i = colouring_.colour_start(c); i < colouring_.colour_start(c + 1); ++i) {
        const int chunk = colouring_.chunk_id(i);
        for (int j = colouring_.chunk_begin(chunk); j < colouring_.chunk_end(chunk); ++j)
          if (const int p = colouring_.family(j); const char* failed = body(s, p)) {
#pragma omp critical(pd_assembly_error)
            if (bad < 0 || p < bad) bad = p, bad_stage = failed;
          }
      }
    }
  }
  if (bad >= 0)
    throw std::runtime_error(std::string(stage) + ": non-finite value (NaN or Inf) from the " + bad_stage +
                             " of law " + law_.name + " at particle " + std::to_string(bad));
}

void FamilyAssembler::assemble(const double* u, double* forces, SparseMatrix* K) const {
  const int d = inputs_.dim(), S = law_.n_states;
  const std::size_t N = static_cast<std::size_t>(dofs());
  if (forces) std::fill(forces, forces + N, 0.0);
  double* values = nullptr;
  if (K) {
    const SparsityPattern& pat = pattern();
    if (K->rows() != static_cast<Eigen::Index>(N) || K->nonZeros() != pat.nonzeros() || !K->isCompressed())
      *K = pat.matrix();
    values = K->valuePtr();
    // Zeroed by the assembly's threads: one thread wrote K's 0.8 GB at 400^2, delta/h 3.5
    // at about a tenth of the whole assembly's time.
    const std::ptrdiff_t nz = K->nonZeros();
#pragma omp parallel for schedule(static) num_threads(thread_count())
    for (std::ptrdiff_t i = 0; i < nz; ++i) values[i] = 0.0;
  }
  if (!forces && !K) return;
  const SparsityPattern* pat = K ? pattern_.get() : nullptr;
  for_each_family(K ? "stiffness assembly" : "force assembly", [&](ThreadScratch& s, int p) -> const char* {
    const abi::Family fam = s.gather.gather(p, u);
    if (!has_intact_bond(fam)) return nullptr;  // cut free: no force, no stiffness
    const int L = fam.n_bonds, m = (L + 1) * d;
    double* f_loc = forces ? s.gather.local_vector() : nullptr;
    if (K) {
      variant_.tangent(fam, f_loc, s.factors);
      double* M = s.gather.local_matrix();
      int* strides = s.strides.data();
      for (int a = 0; a <= L; ++a) strides[a] = pat->column_stride(s.gather.particle(p, a));
      const int* slots = pat->family_slots(p).data();
      if (options_.collocation) {
        // Row scales may be large: check the scaled matrix itself.
        form_local_matrix(variant_, d, S, fam, s.factors, M);
        scale_neighbour_rows(*options_.collocation, *inputs_.bonds, p, m, M);
        if (!all_finite(M, static_cast<std::size_t>(m) * m)) return "tangent";
        scatter_family(d, pat->coupling(), M, L, slots, strides, values);
      } else {
        // The O(L) check on the factors bounds every entry of the matrix formed from them.
        if (!factors_finite(d, S, fam, s.factors)) return "tangent";
        if (S == 0 && pat->coupling() == Coupling::pairwise) {
          form_pair_blocks(d, fam, s.factors, M);  // (L+1) d x d blocks, not the dense matrix
          scatter_pair_blocks(d, M, L, slots, strides, values);
        } else {
          form_local_matrix(variant_, d, S, fam, s.factors, M);
          scatter_family(d, pat->coupling(), M, L, slots, strides, values);
        }
      }
    } else {
      variant_.residual(fam, f_loc);
    }
    if (f_loc && options_.collocation)
      scale_neighbour_rows(*options_.collocation, *inputs_.bonds, p, 1, f_loc);
    if (f_loc) {
      if (!all_finite(f_loc, static_cast<std::size_t>(m))) return "residual";
      for (int a = 0; a <= L; ++a) {
        double* f = forces + static_cast<std::ptrdiff_t>(s.gather.particle(p, a)) * d;
        for (int c = 0; c < d; ++c) f[c] += f_loc[a * d + c];
      }
    }
    return nullptr;
  });
}

Eigen::MatrixXd FamilyAssembler::parameter_sensitivities(const double* u) const {
  const int d = inputs_.dim(), np = law_.n_params;
  const auto n_materials = static_cast<int>(inputs_.params.size());
  if (!variant_.sensitivity)
    throw std::invalid_argument("parameter sensitivities: law " + std::string(law_.name) +
                                " has no sensitivity kernel");
  if (pair_jump_)
    throw std::invalid_argument("parameter sensitivities: law " + std::string(law_.name) +
                                " reads pair means of its parameters and the body's materials differ; "
                                "the sensitivity kernel holds for one material per family only");
  if (surface_corrected())
    throw std::invalid_argument(
        "parameter sensitivities: domain.surface_correction computes its bond factors from the "
        "material's parameters, which the sensitivities do not differentiate; run without it");
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(dofs(), static_cast<Eigen::Index>(n_materials) * np);
  // Families of one colour share no particle, so the scatter into out needs no lock.
  for_each_family("parameter sensitivities", [&](ThreadScratch& s, int p) -> const char* {
    const abi::Family fam = s.gather.gather(p, u);
    if (!has_intact_bond(fam)) return nullptr;
    const int L = fam.n_bonds, m = (L + 1) * d;
    thread_local std::vector<double> local;
    local.resize(static_cast<std::size_t>(m) * np);
    variant_.sensitivity(fam, local.data());
    if (!all_finite(local.data(), local.size())) return "sensitivity";
    const int material = inputs_.particles->material[static_cast<std::size_t>(p)];
    for (int i = 0; i < np; ++i) {
      double* column = local.data() + static_cast<std::ptrdiff_t>(i) * m;
      if (options_.collocation) scale_neighbour_rows(*options_.collocation, *inputs_.bonds, p, 1, column);
      double* target = out.col(static_cast<Eigen::Index>(material) * np + i).data();
      for (int a = 0; a <= L; ++a) {
        double* f = target + static_cast<std::ptrdiff_t>(s.gather.particle(p, a)) * d;
        for (int c = 0; c < d; ++c) f[c] += column[a * d + c];
      }
    }
    return nullptr;
  });
  return out;
}

void FamilyAssembler::stiffness_product(const double* u, const double* v, double* Kv) const {
  const int d = inputs_.dim();
  std::fill(Kv, Kv + dofs(), 0.0);
  for_each_family("matrix-free product", [&](ThreadScratch& s, int p) -> const char* {
    const abi::Family fam = s.gather.gather(p, u);
    if (!has_intact_bond(fam)) return nullptr;
    const int L = fam.n_bonds;
    double* df = s.gather.local_vector();
    variant_.jvp(fam, s.gather.gather_local(p, v), df);
    if (options_.collocation) scale_neighbour_rows(*options_.collocation, *inputs_.bonds, p, 1, df);
    if (!all_finite(df, static_cast<std::size_t>((L + 1) * d))) return "tangent-vector product";
    for (int a = 0; a <= L; ++a) {
      double* out = Kv + static_cast<std::ptrdiff_t>(s.gather.particle(p, a)) * d;
      for (int c = 0; c < d; ++c) out[c] -= df[a * d + c];
    }
    return nullptr;
  });
}

void FamilyAssembler::stiffness_diagonal(const double* u, double* diag) const {
  const int d = inputs_.dim(), S = law_.n_states, dd = d * d;
  std::fill(diag, diag + dofs(), 0.0);
  for_each_family("stiffness diagonal", [&](ThreadScratch& s, int p) -> const char* {
    const abi::Family fam = s.gather.gather(p, u);
    if (!has_intact_bond(fam)) return nullptr;
    const int L = fam.n_bonds;
    const abi::TangentFactors& fac = s.factors;
    variant_.tangent(fam, nullptr, fac);
    // With T_ik = delta_ik direct_i + sum_s left_i[s] (x) right_k[s] and c_i = V0 V_i
    // (local_matrix.hpp): K_{i+1,i+1} = c_i T_ii and K_00 = sum_i c_i sum_k T_ik, so
    // only the sums over k of right_k[s] are needed, not the O(L^2) block.
    double right_sum[3 * 16] = {};
    const int S_used = std::min(S, 16);
    for (int k = 0; k < L; ++k)
      for (int a = 0; a < S_used * d; ++a) right_sum[a] += fac.right[k * S * d + a];
    double center[3] = {0, 0, 0};
    for (int i = 0; i < L; ++i) {
      const double c = fam.V0 * fam.V[i];
      // Collocation scales neighbour i's rows (collocation.hpp); the center's stay.
      const double own_scale =
          options_.collocation ? options_.collocation->row_scale[inputs_.bonds->offsets[p] + i] : 1.0;
      double* out = diag + static_cast<std::ptrdiff_t>(s.gather.particle(p, i + 1)) * d;
      for (int r = 0; r < d; ++r) {
        double own = fac.direct[i * dd + r * d + r], row_sum = own;
        for (int st = 0; st < S; ++st) {
          const double l = fac.left[(i * S + st) * d + r];
          own += l * fac.right[(i * S + st) * d + r];
          double rs = 0;
          if (st < 16) {
            rs = right_sum[st * d + r];
          } else {
            for (int k = 0; k < L; ++k) rs += fac.right[(k * S + st) * d + r];
          }
          row_sum += l * rs;
        }
        out[r] += own_scale * c * own;
        center[r] += c * row_sum;
      }
    }
    for (int r = 0; r < d; ++r) {
      if (!std::isfinite(center[r])) return "tangent (diagonal)";
      diag[static_cast<std::ptrdiff_t>(p) * d + r] += center[r];
    }
    return nullptr;
  });
}

std::vector<double> FamilyAssembler::particle_outputs(const double* u) const {
  const int n = inputs_.size(), no = law_.n_outputs;
  std::vector<double> out(static_cast<std::size_t>(n) * no, 0.0);
  if (no == 0 || variant_.outputs == nullptr) return out;
    // Each particle writes only its own slice: no colouring needed.
#pragma omp parallel num_threads(thread_count())
  {
    FamilyGather g(inputs_);
#pragma omp for schedule(static)
    for (int p = 0; p < n; ++p) {
      const abi::Family fam = g.gather(p, u);
      if (has_intact_bond(fam)) variant_.outputs(fam, out.data() + static_cast<std::ptrdiff_t>(p) * no);
    }
  }
  return out;
}

}  // namespace pd

namespace pd {

namespace {
// The committed values, or the law's initial ones where none are given: [count * n].
std::vector<double> committed_or_initial(const double* committed, std::size_t count, int n,
                                         const double* initial) {
  std::vector<double> out(count * static_cast<std::size_t>(n));
  for (std::size_t j = 0; j < count; ++j)
    for (int i = 0; i < n; ++i) out[j * n + i] = committed ? committed[j * n + i] : initial[i];
  return out;
}

bool all_finite(const double* v, int n) {
  for (int j = 0; j < n; ++j)
    if (!std::isfinite(v[j])) return false;
  return true;
}
}  // namespace

LawHistory FamilyAssembler::updated_history(const double* u) const {
  const int n = inputs_.size(), nh = law_.n_history, np = law_.n_particle_history;
  const Bonds& B = *inputs_.bonds;
  LawHistory out;
  if (!abi::has_history(law_)) return out;
  out.bond = committed_or_initial(inputs_.history, B.neighbor.size(), nh, law_.history_initial);
  out.particle = committed_or_initial(inputs_.particle_history, static_cast<std::size_t>(n), np,
                                      law_.particle_history_initial);
  int first_bad = -1;
  // Each family writes only its own bonds' slice: no colouring needed.
#pragma omp parallel num_threads(thread_count())
  {
    FamilyGather g(inputs_);
#pragma omp for schedule(static)
    for (int p = 0; p < n; ++p) {
      const abi::Family fam = g.gather(p, u);
      if (!has_intact_bond(fam)) continue;
      double* bond_slice = out.bond.data() + static_cast<std::ptrdiff_t>(B.offsets[p]) * nh;
      double* particle_slice = out.particle.data() + static_cast<std::ptrdiff_t>(p) * np;
      variant_.update(fam, nh > 0 ? bond_slice : nullptr, np > 0 ? particle_slice : nullptr);
      if (!all_finite(bond_slice, fam.n_bonds * nh) || !all_finite(particle_slice, np)) {
#pragma omp critical(pd_history_nan)
        if (first_bad < 0 || p < first_bad) first_bad = p;
      }
    }
  }
  if (first_bad >= 0)
    throw std::runtime_error(std::string("history update: law ") + law_.name +
                             " gave a non-finite value in the family of particle " +
                             std::to_string(first_bad));
  return out;
}

double FamilyAssembler::strain_energy(const double* u) const {
  if (variant_.energy == nullptr)
    throw std::logic_error(std::string("law ") + law_.name + " has no energy kernel");
  if (!symmetric())
    throw std::logic_error("collocation assembly has no strain energy (its forces are not a gradient)");
  const int n = inputs_.size();
  std::vector<double> e(static_cast<std::size_t>(n), 0.0);
#pragma omp parallel num_threads(thread_count())
  {
    FamilyGather g(inputs_);
#pragma omp for schedule(static)
    for (int p = 0; p < n; ++p) {
      const abi::Family fam = g.gather(p, u);
      e[p] = has_intact_bond(fam) ? fam.V0 * variant_.energy(fam) : 0.0;
    }
  }
  // Summed in particle order: the same value for any thread count.
  double total = 0;
  for (double v : e) total += v;
  return total;
}

}  // namespace pd

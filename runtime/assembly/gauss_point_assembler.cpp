// Gauss-point families: gather, forces P^T f, tangent P^T M P, product P^T jvp(P v).
#include "assembly/gauss_point_assembler.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "assembly/scatter.hpp"
#include "local_matrix.hpp"
#include "post/peridynamic_stress.hpp"

namespace pd {

namespace {
bool finite(const double* v, std::size_t n) {
  double s = 0.0;
  for (std::size_t i = 0; i < n; ++i) s += v[i] * 0.0;
  return s == 0.0;
}

// The node sets of the families: the nodes in the MLS support of any of p's points,
// without p, ascending.
Bonds node_reach(const Particles& P, const GaussPoints& gp) {
  Bonds r;
  r.dim = P.dim;
  r.offsets.assign(1, 0);
  std::vector<char> seen(static_cast<std::size_t>(P.size()), 0);
  std::vector<int> list;
  for (int p = 0; p < P.size(); ++p) {
    list.clear();
    for (int b = gp.offsets[p]; b < gp.offsets[p + 1]; ++b) {
      const int g = gp.point[b];
      for (int e = gp.phi_start[g]; e < gp.phi_start[g + 1]; ++e) {
        const int a = gp.phi_node[e];
        if (a != p && !seen[a]) seen[a] = 1, list.push_back(a);
      }
    }
    std::sort(list.begin(), list.end());
    for (int a : list) seen[a] = 0;
    r.neighbor.insert(r.neighbor.end(), list.begin(), list.end());
    r.offsets.push_back(static_cast<int>(r.neighbor.size()));
  }
  return r;
}
}  // namespace

// One family's kernel inputs and, on request, its map P to the local nodes.
class GaussPointAssembler::Gather {
 public:
  explicit Gather(const GaussPointAssembler& a) : a_(a) {
    const int d = a.particles_->dim;
    int L = 0;
    for (int p = 0; p < a.particles_->size(); ++p) L = std::max(L, a.gp_->family_size(p));
    const auto Ld = static_cast<std::size_t>(L) * d;
    xi_.resize(Ld), Y_.resize(Ld), w_.resize(L), alpha_.assign(L, 1.0), V_.resize(L);
    scratch_.resize(static_cast<std::size_t>(L) * a.law_.scratch_per_bond);
    local_.resize(Ld + d), local2_.resize(Ld + d);
    factors_ = tangent_.view(d, a.law_.n_states, L);
    mark_.assign(static_cast<std::size_t>(a.particles_->size()), -1);
  }

  // Family of p; u (nodal) and ug (points, gauss_point_displacements) both null or both set.
  abi::Family family(int p, const double* u, const double* ug) {
    const GaussPoints& gp = *a_.gp_;
    const Particles& P = *a_.particles_;
    const int d = P.dim, b0 = gp.offsets[p], L = gp.family_size(p);
    const double* xp = P.position(p);
    const double delta = gp.delta[p];
    for (int k = 0; k < L; ++k) {
      const int g = gp.point[b0 + k];
      double r2 = 0.0;
      for (int c = 0; c < d; ++c) {
        const double x = gp.x[static_cast<std::size_t>(g) * d + c] - xp[c];
        xi_[k * d + c] = x;
        r2 += x * x;
        // Y = xi + (u_g - u_p): the small difference first, as FamilyGather does.
        Y_[k * d + c] = u ? x + (ug[static_cast<std::size_t>(g) * d + c] - u[static_cast<std::size_t>(p) * d + c]) : x;
      }
      w_[k] = gp.influence(std::sqrt(r2), delta);
      V_[k] = gp.beta[b0 + k] * gp.volume[g];
    }
    abi::Family f;
    f.n_bonds = L;
    f.xi = xi_.data();
    f.Y = Y_.data();
    f.w = w_.data();
    f.alpha = alpha_.data();
    f.V = V_.data();
    f.V0 = P.volume[p];
    f.delta = delta;
    f.params = a_.params_[static_cast<std::size_t>(P.material[p])].data();
    f.moments = a_.law_.n_moments > 0 && !a_.moments_.empty()
                    ? a_.moments_.data() + static_cast<std::ptrdiff_t>(p) * a_.law_.n_moments
                    : nullptr;
    f.scratch = scratch_.data();
    return f;
  }

  // The local nodes of p (p, then reach_bonds ascending) and, per bond k, the entries
  // (local node, phi) of row k+1 of P: entry_start_[k] .. entry_start_[k+1].
  void map(int p) {
    const GaussPoints& gp = *a_.gp_;
    const Bonds& R = a_.reach_bonds();
    nodes_.assign(1, p);
    nodes_.insert(nodes_.end(), R.neighbor.begin() + R.offsets[p], R.neighbor.begin() + R.offsets[p + 1]);
    for (int a = 0; a < static_cast<int>(nodes_.size()); ++a) mark_[nodes_[a]] = a;
    entry_start_.assign(1, 0);
    entry_node_.clear(), entry_phi_.clear();
    for (int b = gp.offsets[p]; b < gp.offsets[p + 1]; ++b) {
      const int g = gp.point[b];
      for (int e = gp.phi_start[g]; e < gp.phi_start[g + 1]; ++e)
        entry_node_.push_back(mark_[gp.phi_node[e]]), entry_phi_.push_back(gp.phi[e]);
      entry_start_.push_back(static_cast<int>(entry_node_.size()));
    }
    for (int a : nodes_) mark_[a] = -1;
  }

  // K_nodes = P^T M P for the mapped family (map(p) first); M is (L+1)d square.
  void nodal_matrix(int d, int L, const double* M) {
    const int m = (L + 1) * d, nl = static_cast<int>(nodes_.size()), nd = nl * d;
    MP_.assign(static_cast<std::size_t>(m) * nd, 0.0);
    for (int row = 0; row < m; ++row) {
      const double* Mr = M + static_cast<std::ptrdiff_t>(row) * m;
      double* out = MP_.data() + static_cast<std::ptrdiff_t>(row) * nd;
      for (int q = 0; q < d; ++q) out[q] += Mr[q];  // P[0][0] = 1
      for (int k = 0; k < L; ++k)
        for (int e = entry_start_[k]; e < entry_start_[k + 1]; ++e) {
          const double phi = entry_phi_[e];
          double* o = out + entry_node_[e] * d;
          for (int q = 0; q < d; ++q) o[q] += phi * Mr[(k + 1) * d + q];
        }
    }
    KN_.assign(static_cast<std::size_t>(nd) * nd, 0.0);
    auto add_rows = [&](int a, int i, double phi) {  // rows (a, r) += phi * MP rows (i, r)
      for (int r = 0; r < d; ++r) {
        const double* src = MP_.data() + static_cast<std::ptrdiff_t>(i * d + r) * nd;
        double* dst = KN_.data() + static_cast<std::ptrdiff_t>(a * d + r) * nd;
        for (int col = 0; col < nd; ++col) dst[col] += phi * src[col];
      }
    };
    add_rows(0, 0, 1.0);
    for (int k = 0; k < L; ++k)
      for (int e = entry_start_[k]; e < entry_start_[k + 1]; ++e) add_rows(entry_node_[e], k + 1, entry_phi_[e]);
  }

  double* local() { return local_.data(); }
  double* local2() { return local2_.data(); }
  double* matrix(int m) {
    M_.resize(static_cast<std::size_t>(m) * m);
    return M_.data();
  }
  const abi::TangentFactors& factors() const { return factors_; }
  const std::vector<int>& nodes() const { return nodes_; }
  const double* nodal() const { return KN_.data(); }

 private:
  const GaussPointAssembler& a_;
  std::vector<double> xi_, Y_, w_, alpha_, V_, scratch_, local_, local2_, M_, MP_, KN_;
  TangentScratch tangent_;
  abi::TangentFactors factors_;
  std::vector<int> mark_, nodes_, entry_start_, entry_node_;
  std::vector<double> entry_phi_;
};

}  // namespace pd

namespace pd {

GaussPointAssembler::GaussPointAssembler(const Particles& particles, const GaussPoints& gp, const abi::LawDescriptor& law,
                                         const abi::KernelVariant& variant, std::vector<std::vector<double>> params,
                                         bool matrix)
    : particles_(&particles), gp_(&gp), law_(law), variant_(variant), params_(std::move(params)) {
  if (gp.dim != particles.dim || gp.particle_count() != particles.size())
    throw std::invalid_argument("Gauss-point assembler: the Gauss points were built for another body");
  update_moments();
  if (matrix) pattern_ = std::make_unique<SparsityPattern>(reach_bonds(), particles.dim, Coupling::family);
}

const Bonds& GaussPointAssembler::reach_bonds() const {
  std::call_once(reach_once_, [&] { reach_ = node_reach(*particles_, *gp_); });
  return reach_;
}

const SparsityPattern& GaussPointAssembler::pattern() const {
  if (!pattern_) throw std::logic_error("Gauss-point assembler: built without a matrix pattern");
  return *pattern_;
}

template <class Body>
void GaussPointAssembler::for_each_family(const char* stage, Body&& body) const {
  Gather g(*this);
  for (int p = 0; p < particles_->size(); ++p)
    if (const char* failed = body(g, p))
      throw std::runtime_error(std::string(stage) + ": non-finite value (NaN or Inf) from the " + failed + " of law " +
                               law_.name + " at particle " + std::to_string(p) + " (Gauss-point quadrature)");
}

void GaussPointAssembler::update_moments() {
  const int nm = law_.n_moments;
  moments_.clear();
  if (nm == 0) return;
  if (variant_.moments == nullptr) throw std::invalid_argument(std::string("law ") + law_.name + " has no moments kernel");
  std::vector<double> m(static_cast<std::size_t>(particles_->size()) * nm);
  for_each_family("moments", [&](Gather& g, int p) -> const char* {
    double* out = m.data() + static_cast<std::ptrdiff_t>(p) * nm;
    variant_.moments(g.family(p, nullptr, nullptr), out);
    return finite(out, static_cast<std::size_t>(nm)) ? nullptr : "moments kernel";
  });
  moments_ = std::move(m);
}

void GaussPointAssembler::assemble(const double* u, double* forces, SparseMatrix* K) const {
  const int d = particles_->dim, S = law_.n_states;
  const auto N = static_cast<std::size_t>(dofs());
  if (forces) std::fill(forces, forces + N, 0.0);
  if (!forces && !K) return;
  double* values = nullptr;
  if (K) {
    if (K->rows() != static_cast<Eigen::Index>(N) || K->nonZeros() != pattern().nonzeros() || !K->isCompressed())
      *K = pattern().matrix();
    values = K->valuePtr();
    std::fill(values, values + K->nonZeros(), 0.0);
  }
  std::vector<double> ug;
  if (u) {
    ug.resize(static_cast<std::size_t>(gp_->points()) * d);
    gauss_point_displacements(*gp_, u, ug.data());
  }
  std::vector<int> strides;
  for_each_family(K ? "stiffness assembly (Gauss points)" : "force assembly (Gauss points)",
                  [&](Gather& g, int p) -> const char* {
                    const abi::Family fam = g.family(p, u, u ? ug.data() : nullptr);
                    const int L = fam.n_bonds, m = (L + 1) * d;
                    double* f_loc = forces ? g.local() : nullptr;
                    if (K) {
                      variant_.tangent(fam, f_loc, g.factors());
                      if (!factors_finite(d, S, fam, g.factors())) return "tangent";
                      double* M = g.matrix(m);
                      form_local_matrix(variant_, d, S, fam, g.factors(), M);
                      g.map(p);
                      g.nodal_matrix(d, L, M);
                      const std::vector<int>& nodes = g.nodes();
                      strides.resize(nodes.size());
                      for (std::size_t a = 0; a < nodes.size(); ++a) strides[a] = pattern_->column_stride(nodes[a]);
                      scatter_family(d, Coupling::family, g.nodal(), static_cast<int>(nodes.size()) - 1,
                                     pattern_->family_slots(p).data(), strides.data(), values);
                    } else {
                      variant_.residual(fam, f_loc);
                    }
                    if (!f_loc) return nullptr;
                    if (!finite(f_loc, static_cast<std::size_t>(m))) return "residual";
                    // f_nodes = P^T f_loc: the center's row to p, each point's to its MLS nodes.
                    for (int c = 0; c < d; ++c) forces[static_cast<std::ptrdiff_t>(p) * d + c] += f_loc[c];
                    for (int k = 0; k < L; ++k) {
                      const int pt = gp_->point[gp_->offsets[p] + k];
                      for (int e = gp_->phi_start[pt]; e < gp_->phi_start[pt + 1]; ++e) {
                        double* f = forces + static_cast<std::ptrdiff_t>(gp_->phi_node[e]) * d;
                        for (int c = 0; c < d; ++c) f[c] += gp_->phi[e] * f_loc[(k + 1) * d + c];
                      }
                    }
                    return nullptr;
                  });
}

void GaussPointAssembler::stiffness_product(const double* u, const double* v, double* Kv) const {
  const int d = particles_->dim;
  std::fill(Kv, Kv + dofs(), 0.0);
  const auto Gd = static_cast<std::size_t>(gp_->points()) * d;
  std::vector<double> ug(Gd), vg(Gd);
  if (u) gauss_point_displacements(*gp_, u, ug.data());
  gauss_point_displacements(*gp_, v, vg.data());
  for_each_family("matrix-free product (Gauss points)", [&](Gather& g, int p) -> const char* {
    const abi::Family fam = g.family(p, u, u ? ug.data() : nullptr);
    const int L = fam.n_bonds;
    // dy_loc = P v: the center's v_p, each point's MLS value.
    double* dy = g.local2();
    for (int c = 0; c < d; ++c) dy[c] = v[static_cast<std::ptrdiff_t>(p) * d + c];
    for (int k = 0; k < L; ++k) {
      const int pt = gp_->point[gp_->offsets[p] + k];
      for (int c = 0; c < d; ++c) dy[(k + 1) * d + c] = vg[static_cast<std::size_t>(pt) * d + c];
    }
    double* df = g.local();
    variant_.jvp(fam, dy, df);
    if (!finite(df, static_cast<std::size_t>((L + 1) * d))) return "tangent-vector product";
    // K v = -P^T df.
    for (int c = 0; c < d; ++c) Kv[static_cast<std::ptrdiff_t>(p) * d + c] -= df[c];
    for (int k = 0; k < L; ++k) {
      const int pt = gp_->point[gp_->offsets[p] + k];
      for (int e = gp_->phi_start[pt]; e < gp_->phi_start[pt + 1]; ++e) {
        double* out = Kv + static_cast<std::ptrdiff_t>(gp_->phi_node[e]) * d;
        for (int c = 0; c < d; ++c) out[c] -= gp_->phi[e] * df[(k + 1) * d + c];
      }
    }
    return nullptr;
  });
}

void GaussPointAssembler::stiffness_diagonal(const double* u, double* diag) const {
  // The diagonal of P^T M P needs M and the map: O(L^2) per family, as for the matrix.
  const int d = particles_->dim, S = law_.n_states;
  std::fill(diag, diag + dofs(), 0.0);
  std::vector<double> ug;
  if (u) {
    ug.resize(static_cast<std::size_t>(gp_->points()) * d);
    gauss_point_displacements(*gp_, u, ug.data());
  }
  for_each_family("stiffness diagonal (Gauss points)", [&](Gather& g, int p) -> const char* {
    const abi::Family fam = g.family(p, u, u ? ug.data() : nullptr);
    const int L = fam.n_bonds, m = (L + 1) * d;
    variant_.tangent(fam, nullptr, g.factors());
    if (!factors_finite(d, S, fam, g.factors())) return "tangent (diagonal)";
    double* M = g.matrix(m);
    form_local_matrix(variant_, d, S, fam, g.factors(), M);
    g.map(p);
    g.nodal_matrix(d, L, M);
    const std::vector<int>& nodes = g.nodes();
    const std::size_t nd = nodes.size() * d;
    for (std::size_t a = 0; a < nodes.size(); ++a)
      for (int r = 0; r < d; ++r) diag[static_cast<std::ptrdiff_t>(nodes[a]) * d + r] -= g.nodal()[(a * d + r) * nd + a * d + r];
    return nullptr;
  });
}

double GaussPointAssembler::strain_energy(const double* u) const {
  if (variant_.energy == nullptr) throw std::logic_error(std::string("law ") + law_.name + " has no energy kernel");
  std::vector<double> ug;
  if (u) {
    ug.resize(static_cast<std::size_t>(gp_->points()) * particles_->dim);
    gauss_point_displacements(*gp_, u, ug.data());
  }
  double total = 0.0;
  for_each_family("strain energy (Gauss points)", [&](Gather& g, int p) -> const char* {
    const abi::Family fam = g.family(p, u, u ? ug.data() : nullptr);
    total += fam.V0 * variant_.energy(fam);
    return nullptr;
  });
  return total;
}

double GaussPointAssembler::family_energy_density(int p, const double* u) const {
  if (variant_.energy == nullptr) throw std::logic_error(std::string("law ") + law_.name + " has no energy kernel");
  std::vector<double> ug;
  if (u) {
    ug.resize(static_cast<std::size_t>(gp_->points()) * particles_->dim);
    gauss_point_displacements(*gp_, u, ug.data());
  }
  Gather g(*this);
  return variant_.energy(g.family(p, u, u ? ug.data() : nullptr));
}

std::vector<double> GaussPointAssembler::particle_outputs(const double* u) const {
  const int n = particles_->size(), no = law_.n_outputs;
  std::vector<double> out(static_cast<std::size_t>(n) * no, 0.0);
  if (no == 0 || variant_.outputs == nullptr) return out;
  std::vector<double> ug;
  if (u) {
    ug.resize(static_cast<std::size_t>(gp_->points()) * particles_->dim);
    gauss_point_displacements(*gp_, u, ug.data());
  }
  for_each_family("outputs (Gauss points)", [&](Gather& g, int p) -> const char* {
    variant_.outputs(g.family(p, u, u ? ug.data() : nullptr), out.data() + static_cast<std::ptrdiff_t>(p) * no);
    return nullptr;
  });
  return out;
}

std::vector<double> GaussPointAssembler::family_stresses(const double* u) const {
  const int n = particles_->size(), d = particles_->dim;
  std::vector<double> sigma(static_cast<std::size_t>(n) * d * d, 0.0);
  std::vector<double> ug;
  if (u) {
    ug.resize(static_cast<std::size_t>(gp_->points()) * d);
    gauss_point_displacements(*gp_, u, ug.data());
  }
  for_each_family("stress (Gauss points)", [&](Gather& g, int p) -> const char* {
    double* s = sigma.data() + static_cast<std::ptrdiff_t>(p) * d * d;
    family_stress(variant_.residual, g.family(p, u, u ? ug.data() : nullptr), d, g.local(), s);
    return finite(s, static_cast<std::size_t>(d) * d) ? nullptr : "stress";
  });
  return sigma;
}

}  // namespace pd

// Gauss-point families: gather, forces P^T f, tangent P^T M P, product P^T jvp(P v).
#include "assembly/gauss_point_assembler.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "assembly/peridynamic_stress.hpp"
#include "assembly/scatter.hpp"
#include "local_matrix.hpp"

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
        Y_[k * d + c] =
            u ? x + (ug[static_cast<std::size_t>(g) * d + c] - u[static_cast<std::size_t>(p) * d + c]) : x;
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
    // A Gauss point has the material of the particle whose cell holds it.
    f.nbr_params = neighbour_params(
        a_.params_, P.material[p], L, [&](int k) { return P.material[gp.cell[gp.point[b0 + k]]]; },
        nbr_params_);
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

  // The nodal tangent d f_nodes / d u of the mapped family (map(p) first), from the
  // factored tangent without forming the (L+1)d local matrix M. With Y_i = B_i u_loc
  // (B_i = P[i+1] - P[0]: the point's MLS row minus the center), c_i = V0 V_i and
  // T_ik = delta_ik D_i + sum_s l_i[s] (x) r_k[s] (kernel_abi.hpp), f_nodes = P^T f_loc =
  // -sum_i c_i B_i^T t_i, so
  //   d f_nodes / d u = -sum_i c_i B_i^T D_i B_i - sum_s a_s (x) b_s,
  //   a_s = sum_i c_i B_i^T l_i[s],  b_s = sum_k B_k^T r_k[s]:
  // the same matrix as P^T M P, in O(L n_phi^2 d^2 + n_loc^2 d^2 S) instead of O(L^2 d^2 n_phi).
  void nodal_matrix(int d, int S, const abi::Family& fam, const abi::TangentFactors& fac) {
    const int L = fam.n_bonds, nl = static_cast<int>(nodes_.size()), nd = nl * d, dd = d * d;
    KN_.assign(static_cast<std::size_t>(nd) * nd, 0.0);
    ab_.assign(static_cast<std::size_t>(2) * S * nd, 0.0);
    for (int i = 0; i < L; ++i) {
      const double c = fam.V0 * fam.V[i];
      // B_i's entries: the point's (node, phi) and the center's (0, -1).
      row_node_.assign(entry_node_.begin() + entry_start_[i], entry_node_.begin() + entry_start_[i + 1]);
      row_phi_.assign(entry_phi_.begin() + entry_start_[i], entry_phi_.begin() + entry_start_[i + 1]);
      row_node_.push_back(0), row_phi_.push_back(-1.0);
      const double* D = fac.direct + static_cast<std::ptrdiff_t>(i) * dd;
      const int n = static_cast<int>(row_node_.size());
      for (int x = 0; x < n; ++x) {
        const double cx = c * row_phi_[x];
        for (int y = 0; y < n; ++y) {
          const double w = cx * row_phi_[y];
          for (int r = 0; r < d; ++r) {
            double* out =
                KN_.data() + static_cast<std::ptrdiff_t>(row_node_[x] * d + r) * nd + row_node_[y] * d;
            for (int q = 0; q < d; ++q) out[q] -= w * D[r * d + q];
          }
        }
        for (int st = 0; st < S; ++st) {
          double* a = ab_.data() + static_cast<std::ptrdiff_t>(st) * nd + row_node_[x] * d;
          double* b = ab_.data() + static_cast<std::ptrdiff_t>(S + st) * nd + row_node_[x] * d;
          const double* l = fac.left + static_cast<std::ptrdiff_t>(i * S + st) * d;
          const double* rr = fac.right + static_cast<std::ptrdiff_t>(i * S + st) * d;
          for (int r = 0; r < d; ++r) a[r] += cx * l[r], b[r] += row_phi_[x] * rr[r];
        }
      }
    }
    for (int st = 0; st < S; ++st) {
      const double* a = ab_.data() + static_cast<std::ptrdiff_t>(st) * nd;
      const double* b = ab_.data() + static_cast<std::ptrdiff_t>(S + st) * nd;
      for (int row = 0; row < nd; ++row) {
        if (a[row] == 0.0) continue;
        double* out = KN_.data() + static_cast<std::ptrdiff_t>(row) * nd;
        for (int col = 0; col < nd; ++col) out[col] -= a[row] * b[col];
      }
    }
  }

  // rows += the row sums of |c_i| |B_i|^T |D_i| |B_i| + |a_s| |b_s|^T of the mapped family
  // (map(p) first): an entrywise bound on |P^T M P| (nodal_matrix's factors; the center's
  // -1 and the point's own phi at node 0, when p is in the support, are counted apart,
  // which only enlarges the bound).
  void add_row_sum_bound(int d, int S, const abi::Family& fam, const abi::TangentFactors& fac, double* rows) {
    const int L = fam.n_bonds, nd = static_cast<int>(nodes_.size()) * d, dd = d * d;
    ab_.assign(static_cast<std::size_t>(2) * S * nd, 0.0);
    for (int i = 0; i < L; ++i) {
      const double c = fam.V0 * fam.V[i];
      double phisum = 1.0;  // the center's |-1|
      for (int e = entry_start_[i]; e < entry_start_[i + 1]; ++e) phisum += std::fabs(entry_phi_[e]);
      const double* D = fac.direct + static_cast<std::ptrdiff_t>(i) * dd;
      double dr[3] = {0, 0, 0};
      for (int r = 0; r < d; ++r)
        for (int q = 0; q < d; ++q) dr[r] += std::fabs(D[r * d + q]);
      auto entry = [&](int node, double phi) {
        const double scale = std::fabs(c * phi) * phisum;
        double* out = rows + static_cast<std::ptrdiff_t>(nodes_[node]) * d;
        for (int r = 0; r < d; ++r) out[r] += scale * dr[r];
        for (int st = 0; st < S; ++st) {
          double* a = ab_.data() + static_cast<std::ptrdiff_t>(st) * nd + node * d;
          double* b = ab_.data() + static_cast<std::ptrdiff_t>(S + st) * nd + node * d;
          const double* l = fac.left + static_cast<std::ptrdiff_t>(i * S + st) * d;
          const double* rr = fac.right + static_cast<std::ptrdiff_t>(i * S + st) * d;
          for (int r = 0; r < d; ++r) a[r] += c * phi * l[r], b[r] += phi * rr[r];
        }
      };
      for (int e = entry_start_[i]; e < entry_start_[i + 1]; ++e) entry(entry_node_[e], entry_phi_[e]);
      entry(0, -1.0);
    }
    for (int st = 0; st < S; ++st) {
      const double* a = ab_.data() + static_cast<std::ptrdiff_t>(st) * nd;
      const double* b = ab_.data() + static_cast<std::ptrdiff_t>(S + st) * nd;
      double bsum = 0.0;
      for (int col = 0; col < nd; ++col) bsum += std::fabs(b[col]);
      for (int row = 0; row < nd; ++row)
        rows[static_cast<std::ptrdiff_t>(nodes_[row / d]) * d + row % d] += std::fabs(a[row]) * bsum;
    }
  }

  double* local() { return local_.data(); }
  double* local2() { return local2_.data(); }
  const abi::TangentFactors& factors() const { return factors_; }
  const std::vector<int>& nodes() const { return nodes_; }
  const double* nodal() const { return KN_.data(); }

 private:
  const GaussPointAssembler& a_;
  std::vector<double> xi_, Y_, w_, alpha_, V_, scratch_, local_, local2_, KN_, ab_, row_phi_, nbr_params_;
  std::vector<int> row_node_;
  TangentScratch tangent_;
  abi::TangentFactors factors_;
  std::vector<int> mark_, nodes_, entry_start_, entry_node_;
  std::vector<double> entry_phi_;
};

}  // namespace pd

namespace pd {

GaussPointAssembler::GaussPointAssembler(const Particles& particles, const GaussPoints& gp,
                                         const abi::LawDescriptor& law, const abi::KernelVariant& variant,
                                         std::vector<std::vector<double>> params, bool matrix, int threads)
    : particles_(&particles),
      gp_(&gp),
      law_(law),
      variant_(variant),
      params_(std::move(params)),
      threads_(threads) {
  pair_jump_ = check_law_inputs(particles, law, params_, "Gauss-point assembler");
  if (gp.dim != particles.dim || gp.particle_count() != particles.size())
    throw std::invalid_argument("Gauss-point assembler: the Gauss points were built for another body");
  // Conflicts for the colouring: family p "holds" the cells of its points (two families
  // sharing a point share its cell); delta: the farthest point, so the tiles are two
  // reaches wide.
  {
    Bonds cells;
    cells.dim = particles.dim;
    cells.offsets.assign(1, 0);
    cells.delta.assign(static_cast<std::size_t>(particles.size()), 0.0);
    std::vector<int> seen(static_cast<std::size_t>(particles.size()), -1);
    for (int p = 0; p < particles.size(); ++p) {
      const double* xp = particles.position(p);
      for (int b = gp.offsets[p]; b < gp.offsets[p + 1]; ++b) {
        const int g = gp.point[b], c = gp.cell[g];
        double r2 = 0.0;
        for (int k = 0; k < gp.dim; ++k)
          r2 += (gp.x[static_cast<std::size_t>(g) * gp.dim + k] - xp[k]) *
                (gp.x[static_cast<std::size_t>(g) * gp.dim + k] - xp[k]);
        cells.delta[p] = std::max(cells.delta[p], std::sqrt(r2));
        if (c != p && seen[c] != p) seen[c] = p, cells.neighbor.push_back(c);
      }
      cells.offsets.push_back(static_cast<int>(cells.neighbor.size()));
    }
    colouring_ = std::make_unique<FamilyColouring>(particles, cells);
  }
  // The transpose of the MLS map, entries ascending per node (a counting sort).
  node_entry_start_.assign(static_cast<std::size_t>(particles.size()) + 1, 0);
  for (int a : gp.phi_node) ++node_entry_start_[a + 1];
  for (int a = 0; a < particles.size(); ++a) node_entry_start_[a + 1] += node_entry_start_[a];
  node_entry_.resize(gp.phi_node.size());
  {
    std::vector<int> fill(node_entry_start_.begin(), node_entry_start_.end() - 1);
    for (int e = 0; e < static_cast<int>(gp.phi_node.size()); ++e) node_entry_[fill[gp.phi_node[e]]++] = e;
  }
  entry_point_.resize(gp.phi_node.size());
  for (int g = 0; g < gp.points(); ++g)
    for (int e = gp.phi_start[g]; e < gp.phi_start[g + 1]; ++e) entry_point_[e] = g;
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
      throw std::runtime_error(std::string(stage) + ": non-finite value (NaN or Inf) from the " + failed +
                               " of law " + law_.name + " at particle " + std::to_string(p) +
                               " (Gauss-point quadrature)");
}

double GaussPointAssembler::longest_bond() const {
  const std::vector<double>& delta = gp_->delta;
  return delta.empty() ? 0.0 : *std::max_element(delta.begin(), delta.end());
}

int GaussPointAssembler::thread_count() const { return threads_ > 0 ? threads_ : omp_get_max_threads(); }

template <class Body>
void GaussPointAssembler::for_each_family_coloured(const char* stage, Body&& body) const {
  const FamilyColouring& col = *colouring_;
  std::string error;
#pragma omp parallel num_threads(thread_count())
  {
    Gather g(*this);
    for (int c = 0; c < col.colours(); ++c) {
      // The implicit barrier at the end of the loop separates the colours.
#pragma omp for schedule(dynamic, 1)
      for (int i = col.colour_start(c); i < col.colour_start(c + 1); ++i) {
        const int chunk = col.chunk_id(i);
        for (int j = col.chunk_begin(chunk); j < col.chunk_end(chunk); ++j)
          if (const int p = col.family(j); const char* failed = body(g, p)) {
#pragma omp critical(pd_gauss_assembly_error)
            if (error.empty())
              error = std::string(stage) + ": non-finite value (NaN or Inf) from the " + failed + " of law " +
                      law_.name + " at particle " + std::to_string(p) + " (Gauss-point quadrature)";
          }
      }
    }
  }
  if (!error.empty()) throw std::runtime_error(error);
}

// ug = P u per point: each point writes its own row.
void GaussPointAssembler::gather_points(const double* u, double* ug) const {
  const int d = gp_->dim, G = gp_->points();
#pragma omp parallel for schedule(static) num_threads(thread_count())
  for (int g = 0; g < G; ++g) {
    double acc[3] = {0, 0, 0};
    for (int e = gp_->phi_start[g]; e < gp_->phi_start[g + 1]; ++e) {
      const double* ua = u + static_cast<std::ptrdiff_t>(gp_->phi_node[e]) * d;
      for (int c = 0; c < d; ++c) acc[c] += gp_->phi[e] * ua[c];
    }
    for (int c = 0; c < d; ++c) ug[static_cast<std::ptrdiff_t>(g) * d + c] = acc[c];
  }
}

// out[a] += scale * sum_g phi_a(x_g) per_point[g] (P^T), node by node through the
// transposed map: each node its own row, its entries in ascending order.
void GaussPointAssembler::add_mapped(const double* per_point, double scale, double* out) const {
  const int d = gp_->dim, n = particles_->size();
#pragma omp parallel for schedule(static) num_threads(thread_count())
  for (int a = 0; a < n; ++a) {
    double* o = out + static_cast<std::ptrdiff_t>(a) * d;
    for (int k = node_entry_start_[a]; k < node_entry_start_[a + 1]; ++k) {
      const int e = node_entry_[k];
      const double* v = per_point + static_cast<std::ptrdiff_t>(entry_point_[e]) * d;
      const double w = scale * gp_->phi[e];
      for (int c = 0; c < d; ++c) o[c] += w * v[c];
    }
  }
}

void GaussPointAssembler::update_moments() {
  const int nm = law_.n_moments;
  moments_.clear();
  if (nm == 0) return;
  if (variant_.moments == nullptr)
    throw std::invalid_argument(std::string("law ") + law_.name + " has no moments kernel");
  std::vector<double> m(static_cast<std::size_t>(particles_->size()) * nm);
  for_each_family_coloured("moments", [&](Gather& g, int p) -> const char* {
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
    if (K->rows() != static_cast<Eigen::Index>(N) || K->nonZeros() != pattern().nonzeros() ||
        !K->isCompressed())
      *K = pattern().matrix();
    values = K->valuePtr();
    std::fill(values, values + K->nonZeros(), 0.0);
  }
  std::vector<double> ug;
  if (u) {
    ug.resize(static_cast<std::size_t>(gp_->points()) * d);
    gather_points(u, ug.data());
  }
  std::vector<int> strides;
  std::vector<double> point_forces(forces ? static_cast<std::size_t>(gp_->points()) * d : 0, 0.0);
  auto body = [&](Gather& g, int p) -> const char* {
    const abi::Family fam = g.family(p, u, u ? ug.data() : nullptr);
    const int L = fam.n_bonds, m = (L + 1) * d;
    double* f_loc = forces ? g.local() : nullptr;
    if (K) {
      variant_.tangent(fam, f_loc, g.factors());
      if (!factors_finite(d, S, fam, g.factors())) return "tangent";
      g.map(p);
      g.nodal_matrix(d, S, fam, g.factors());
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
    // The center's row to p; each point's row summed per point, mapped below.
    for (int c = 0; c < d; ++c) forces[static_cast<std::ptrdiff_t>(p) * d + c] += f_loc[c];
    for (int k = 0; k < L; ++k) {
      double* f = point_forces.data() + static_cast<std::ptrdiff_t>(gp_->point[gp_->offsets[p] + k]) * d;
      for (int c = 0; c < d; ++c) f[c] += f_loc[(k + 1) * d + c];
    }
    return nullptr;
  };
  // The matrix scatters into the family's MLS nodes, which the colouring does not separate.
  if (K)
    for_each_family("stiffness assembly (Gauss points)", body);
  else
    for_each_family_coloured("force assembly (Gauss points)", body);
  // f_nodes = P^T f_loc, the points' rows once per point (a point is in ~30 families at
  // delta = 3h: mapping each bond's row to the ~28 MLS nodes instead cost 4x the kernels).
  if (forces) add_mapped(point_forces.data(), 1.0, forces);
}

void GaussPointAssembler::stiffness_product(const double* u, const double* v, double* Kv) const {
  const int d = particles_->dim;
  std::fill(Kv, Kv + dofs(), 0.0);
  const auto Gd = static_cast<std::size_t>(gp_->points()) * d;
  std::vector<double> ug(Gd), vg(Gd);
  if (u) gather_points(u, ug.data());
  gather_points(v, vg.data());
  std::vector<double> point_df(Gd, 0.0);
  for_each_family_coloured("matrix-free product (Gauss points)", [&](Gather& g, int p) -> const char* {
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
    // K v = -P^T df: the center's row now, the points' rows summed per point and mapped below.
    for (int c = 0; c < d; ++c) Kv[static_cast<std::ptrdiff_t>(p) * d + c] -= df[c];
    for (int k = 0; k < L; ++k) {
      double* out = point_df.data() + static_cast<std::ptrdiff_t>(gp_->point[gp_->offsets[p] + k]) * d;
      for (int c = 0; c < d; ++c) out[c] += df[(k + 1) * d + c];
    }
    return nullptr;
  });
  add_mapped(point_df.data(), -1.0, Kv);
}

void GaussPointAssembler::collocation_forces(const double* u, double* forces) const {
  if (law_.n_states != 0)
    throw std::invalid_argument(
        std::string("collocation form (eq. 3.15): law ") + law_.name +
        " is state-based; its force state needs the Gauss point's own family, which does not exist");
  const int d = particles_->dim;
  std::fill(forces, forces + dofs(), 0.0);
  std::vector<double> ug;
  if (u) {
    ug.resize(static_cast<std::size_t>(gp_->points()) * d);
    gather_points(u, ug.data());
  }
  for_each_family_coloured("collocation forces (Gauss points)", [&](Gather& g, int p) -> const char* {
    const abi::Family fam = g.family(p, u, u ? ug.data() : nullptr);
    double* f_loc = g.local();
    variant_.residual(fam, f_loc);
    if (!finite(f_loc, static_cast<std::size_t>(d))) return "residual";
    for (int c = 0; c < d; ++c) forces[static_cast<std::ptrdiff_t>(p) * d + c] = 2.0 * f_loc[c];
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
    gather_points(u, ug.data());
  }
  for_each_family("stiffness diagonal (Gauss points)", [&](Gather& g, int p) -> const char* {
    const abi::Family fam = g.family(p, u, u ? ug.data() : nullptr);
    variant_.tangent(fam, nullptr, g.factors());
    if (!factors_finite(d, S, fam, g.factors())) return "tangent (diagonal)";
    g.map(p);
    g.nodal_matrix(d, S, fam, g.factors());
    const std::vector<int>& nodes = g.nodes();
    const std::size_t nd = nodes.size() * d;
    for (std::size_t a = 0; a < nodes.size(); ++a)
      for (int r = 0; r < d; ++r)
        diag[static_cast<std::ptrdiff_t>(nodes[a]) * d + r] -= g.nodal()[(a * d + r) * nd + a * d + r];
    return nullptr;
  });
}

std::vector<double> GaussPointAssembler::stiffness_row_sums(const double* u) const {
  const int d = particles_->dim, S = law_.n_states;
  std::vector<double> rows(static_cast<std::size_t>(dofs()), 0.0), ug;
  if (u) {
    ug.resize(static_cast<std::size_t>(gp_->points()) * d);
    gather_points(u, ug.data());
  }
  // One thread: a family adds to its MLS nodes, which the colouring does not separate.
  for_each_family("stiffness row sums (Gauss points)", [&](Gather& g, int p) -> const char* {
    const abi::Family fam = g.family(p, u, u ? ug.data() : nullptr);
    variant_.tangent(fam, nullptr, g.factors());
    if (!factors_finite(d, S, fam, g.factors())) return "tangent (row sums)";
    g.map(p);
    g.add_row_sum_bound(d, S, fam, g.factors(), rows.data());
    return nullptr;
  });
  return rows;
}

double GaussPointAssembler::strain_energy(const double* u) const {
  if (variant_.energy == nullptr)
    throw std::logic_error(std::string("law ") + law_.name + " has no energy kernel");
  std::vector<double> ug;
  if (u) {
    ug.resize(static_cast<std::size_t>(gp_->points()) * particles_->dim);
    gather_points(u, ug.data());
  }
  std::vector<double> per_family(static_cast<std::size_t>(particles_->size()));
  for_each_family_coloured("strain energy (Gauss points)", [&](Gather& g, int p) -> const char* {
    const abi::Family fam = g.family(p, u, u ? ug.data() : nullptr);
    per_family[p] = fam.V0 * variant_.energy(fam);
    return nullptr;
  });
  // Summed in particle order: the same value for any thread count.
  double total = 0.0;
  for (double e : per_family) total += e;
  return total;
}

double GaussPointAssembler::family_energy_density(int p, const double* u) const {
  if (variant_.energy == nullptr)
    throw std::logic_error(std::string("law ") + law_.name + " has no energy kernel");
  std::vector<double> ug;
  if (u) {
    ug.resize(static_cast<std::size_t>(gp_->points()) * particles_->dim);
    gather_points(u, ug.data());
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
    gather_points(u, ug.data());
  }
  for_each_family_coloured("outputs (Gauss points)", [&](Gather& g, int p) -> const char* {
    variant_.outputs(g.family(p, u, u ? ug.data() : nullptr),
                     out.data() + static_cast<std::ptrdiff_t>(p) * no);
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
    gather_points(u, ug.data());
  }
  for_each_family_coloured("stress (Gauss points)", [&](Gather& g, int p) -> const char* {
    double* s = sigma.data() + static_cast<std::ptrdiff_t>(p) * d * d;
    family_stress(variant_.residual, g.family(p, u, u ? ug.data() : nullptr), d, g.local(), s);
    return finite(s, static_cast<std::size_t>(d) * d) ? nullptr : "stress";
  });
  return sigma;
}

}  // namespace pd

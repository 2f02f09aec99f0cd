// Gauss-point families: forces P^T f, tangent P^T M P, product P^T jvp(P v), diagonal, row sums.
#include "assembly/gauss_point_assembler.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "assembly/gauss_point_gather.hpp"
#include "assembly/scatter.hpp"
#include "local_matrix.hpp"

namespace pd {

namespace {
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

double GaussPointAssembler::longest_bond() const {
  const std::vector<double>& delta = gp_->delta;
  return delta.empty() ? 0.0 : *std::max_element(delta.begin(), delta.end());
}

int GaussPointAssembler::thread_count() const { return threads_ > 0 ? threads_ : omp_get_max_threads(); }

// P u per point, or empty without u (the reference configuration).
std::vector<double> GaussPointAssembler::point_displacements(const double* u) const {
  std::vector<double> ug;
  if (u) {
    ug.resize(static_cast<std::size_t>(gp_->points()) * particles_->dim);
    gather_points(u, ug.data());
  }
  return ug;
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
  const std::vector<double> ug = point_displacements(u);
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
  const std::vector<double> ug = point_displacements(u);
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
  const std::vector<double> ug = point_displacements(u);
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
  std::vector<double> rows(static_cast<std::size_t>(dofs()), 0.0);
  const std::vector<double> ug = point_displacements(u);
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

}  // namespace pd

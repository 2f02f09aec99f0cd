// Private to gauss_point_assembler.cpp and gauss_point_outputs.cpp: GaussPointAssembler::Gather
// (one Gauss family's kernel inputs, its map P to the local nodes and the nodal tangent
// formed from the factors), the two family loops that hand a per-thread Gather to a body
// (for_each_family, for_each_family_coloured), and the finite check of kernel outputs.
#pragma once

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include "assembly/family_colouring.hpp"
#include "assembly/family_gather.hpp"
#include "assembly/gauss_point_assembler.hpp"
#include "kernel_abi.hpp"
#include "local_matrix.hpp"

namespace pd {

// True when all n values are finite (0*x is 0 for finite x, NaN for NaN or Inf).
inline bool finite(const double* v, std::size_t n) {
  double s = 0.0;
  for (std::size_t i = 0; i < n; ++i) s += v[i] * 0.0;
  return s == 0.0;
}

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

template <class Body>
void GaussPointAssembler::for_each_family(const char* stage, Body&& body) const {
  Gather g(*this);
  for (int p = 0; p < particles_->size(); ++p)
    if (const char* failed = body(g, p))
      throw std::runtime_error(std::string(stage) + ": non-finite value (NaN or Inf) from the " + failed +
                               " of law " + law_.name + " at particle " + std::to_string(p) +
                               " (Gauss-point quadrature)");
}

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

}  // namespace pd

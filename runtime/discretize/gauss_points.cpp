// Fixed Gauss points per cell, their MLS shape functions and the Gauss families.
#include "discretize/gauss_points.hpp"

#include <fmt/core.h>

#include <cmath>
#include <stdexcept>

#include "discretize/discretization.hpp"
#include "discretize/mls.hpp"

namespace pd {

void gauss_legendre(int n, double* zeta, double* weight) {
  switch (n) {
    case 1:
      zeta[0] = 0.0, weight[0] = 2.0;
      return;
    case 2:
      zeta[0] = -1.0 / std::sqrt(3.0), zeta[1] = -zeta[0], weight[0] = weight[1] = 1.0;
      return;
    case 3:
      zeta[0] = -std::sqrt(0.6), zeta[1] = 0.0, zeta[2] = std::sqrt(0.6);
      weight[0] = weight[2] = 5.0 / 9.0, weight[1] = 8.0 / 9.0;
      return;
    default:
      throw std::invalid_argument(fmt::format("Gauss points: {} per axis (1, 2 or 3)", n));
  }
}

double gauss_reduction_factor(double r, double delta, double hg) {
  if (r <= delta - 0.5 * hg) return 1.0;
  if (r <= delta + 0.5 * hg) return (delta + 0.5 * hg - r) / hg;
  return 0.0;
}

namespace {

// The offsets (h/2) zeta and the volume shares prod(w/2) of the n^dim points of a cell.
struct CellRule {
  std::vector<double> offset;  // [n^dim * dim]
  std::vector<double> share;   // [n^dim], sums to 1
  std::vector<double> hg;      // [n^dim] effective subcell size h_g (eq. 3.12)
  double max_offset = 0.0;
};

CellRule cell_rule(int dim, int n, double h) {
  double zeta[3], weight[3];
  gauss_legendre(n, zeta, weight);
  CellRule rule;
  const int count = dim == 2 ? n * n : n * n * n;
  for (int k = 0; k < count; ++k) {
    int idx[3] = {k % n, (k / n) % n, k / (n * n)};
    double share = 1.0, prod_w = 1.0, r2 = 0.0;
    for (int c = 0; c < dim; ++c) {
      const double o = 0.5 * h * zeta[idx[c]];
      rule.offset.push_back(o);
      r2 += o * o;
      share *= 0.5 * weight[idx[c]];
      prod_w *= weight[idx[c]];
    }
    rule.share.push_back(share);
    rule.hg.push_back(0.5 * h * std::pow(prod_w, 1.0 / dim));
    rule.max_offset = std::max(rule.max_offset, std::sqrt(r2));
  }
  return rule;
}
}  // namespace

std::string GaussPoints::describe() const {
  return fmt::format(
      "gauss points: {}^{} per cell (paper 002 §3.3), {} points, {} Gauss bonds, MLS support {:.4g} "
      "({:.1f} nodes per point, largest condition number {:.3g})",
      per_axis, dim, points(), bond_count(), support, mean_support_size(), max_condition);
}

GaussPoints build_gauss_points(const Particles& P, double h, double delta,
                               double (*influence)(double r, double delta),
                               const GaussPointOptions& options) {
  if (!(options.support > 0.0)) throw std::invalid_argument("Gauss points: the MLS support must be positive");
  const int d = P.dim, n = P.size();
  const CellRule rule = cell_rule(d, options.per_axis, h);
  const int per_cell = static_cast<int>(rule.share.size());
  GaussPoints gp;
  gp.dim = d;
  gp.per_axis = options.per_axis;
  gp.h = h;
  gp.support = options.support * h;
  gp.influence = influence;
  gp.x.reserve(static_cast<std::size_t>(n) * per_cell * d);
  for (int j = 0; j < n; ++j)
    for (int k = 0; k < per_cell; ++k) {
      for (int c = 0; c < d; ++c) gp.x.push_back(P.position(j)[c] + rule.offset[k * d + c]);
      gp.cell.push_back(j);
      gp.volume.push_back(P.volume[j] * rule.share[k]);
    }
  const int G = gp.points();
  // MLS: the candidates of a point of cell j are j and the nodes within r_w + the
  // largest offset of x_j. One point per axis: the point is the node, u_g = u_j.
  gp.phi_start.assign(1, 0);
  if (options.per_axis == 1) {
    for (int g = 0; g < G; ++g)
      gp.phi_node.push_back(gp.cell[g]), gp.phi.push_back(1.0), gp.phi_start.push_back(g + 1);
    gp.max_condition = 1.0;
  } else {
    const Bonds near = find_bonds(P, gp.support + rule.max_offset, influence);
    std::vector<int> candidates;
    for (int g = 0; g < G; ++g) {
      const int j = gp.cell[g];
      candidates.assign(1, j);
      for (int b = near.offsets[j]; b < near.offsets[j + 1]; ++b) candidates.push_back(near.neighbor[b]);
      const MlsShape s = mls_shape_functions(
          gp.x.data() + static_cast<std::ptrdiff_t>(g) * d, d, P.x, candidates, gp.support,
          fmt::format("Gauss point {} (cell of particle {})", g, j), options.max_condition);
      gp.phi_node.insert(gp.phi_node.end(), s.node.begin(), s.node.end());
      gp.phi.insert(gp.phi.end(), s.phi.begin(), s.phi.end());
      gp.phi_start.push_back(static_cast<int>(gp.phi_node.size()));
      gp.max_condition = std::max(gp.max_condition, s.condition);
    }
  }
  // Families: the points of the cells of the particles within reach, beta_g > 0.
  double hg_max = 0.0;
  for (double v : rule.hg) hg_max = std::max(hg_max, v);
  const Bonds cells = find_bonds(P, delta + 0.5 * hg_max + rule.max_offset, influence);
  gp.offsets.assign(1, 0);
  gp.delta.assign(static_cast<std::size_t>(n), delta);
  for (int i = 0; i < n; ++i) {
    const double* xi = P.position(i);
    for (int b = cells.offsets[i]; b < cells.offsets[i + 1]; ++b) {
      const int j = cells.neighbor[b];
      for (int k = 0; k < per_cell; ++k) {
        const int g = j * per_cell + k;
        double r2 = 0.0;
        for (int c = 0; c < d; ++c) {
          const double dx = gp.x[static_cast<std::size_t>(g) * d + c] - xi[c];
          r2 += dx * dx;
        }
        const double beta = gauss_reduction_factor(std::sqrt(r2), delta, rule.hg[k]);
        if (beta <= 0.0) continue;
        gp.point.push_back(g);
        gp.beta.push_back(beta);
      }
    }
    gp.offsets.push_back(static_cast<int>(gp.point.size()));
    if (gp.family_size(i) == 0)
      throw std::runtime_error(
          fmt::format("Gauss points: particle {} has no Gauss point within its horizon", i));
  }
  return gp;
}

void gauss_point_displacements(const GaussPoints& gp, const double* u, double* ug) {
  const int d = gp.dim, G = gp.points();
  for (int g = 0; g < G; ++g) {
    double acc[3] = {0, 0, 0};
    for (int e = gp.phi_start[g]; e < gp.phi_start[g + 1]; ++e) {
      const double* ua = u + static_cast<std::ptrdiff_t>(gp.phi_node[e]) * d;
      for (int c = 0; c < d; ++c) acc[c] += gp.phi[e] * ua[c];
    }
    for (int c = 0; c < d; ++c) ug[static_cast<std::ptrdiff_t>(g) * d + c] = acc[c];
  }
}

}  // namespace pd

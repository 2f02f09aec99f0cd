// Row scales of collocation assembly (collocation.hpp).
#include "assembly/collocation.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>

#include "discretize/obq_weights.hpp"

namespace pd {

namespace {
// Bond index of q -> p in q's family (rows are sorted by neighbour index), or -1.
int reverse_bond(const Bonds& bonds, int p, int q) {
  const auto begin = bonds.neighbor.begin() + bonds.offsets[q],
             end = bonds.neighbor.begin() + bonds.offsets[q + 1];
  const auto it = std::lower_bound(begin, end, p);
  return it != end && *it == p ? static_cast<int>(it - bonds.neighbor.begin()) : -1;
}
}  // namespace

Collocation make_collocation(const Particles& particles, const Bonds& bonds, std::vector<double> weights) {
  if (weights.size() != bonds.neighbor.size())
    throw std::invalid_argument("collocation: one weight per bond expected");
  Collocation c;
  c.row_scale.assign(weights.size(), 0.0);
  for (int p = 0; p < bonds.particle_count(); ++p)
    for (int b = bonds.offsets[p]; b < bonds.offsets[p + 1]; ++b) {
      const int q = bonds.neighbor[b], r = reverse_bond(bonds, p, q);
      const std::string name = "bond " + std::to_string(p) + " -> " + std::to_string(q);
      if (r < 0)
        throw std::invalid_argument("collocation: " + name + " has no reverse bond (horizons differ?)");
      if (weights[b] == 0.0) {
        if (weights[r] != 0.0)
          throw std::invalid_argument("collocation: " + name + " has weight 0 but its reverse does not");
        continue;  // both zero: the pair does not interact
      }
      c.row_scale[b] = particles.volume[q] * weights[r] / (particles.volume[p] * weights[b]);
    }
  // symmetric_pair_weights divides one rounded pair weight by V_p and V_q, so its scales
  // differ from 1 by a few ulps; unsymmetric OBQ weights of a perturbed cloud by ~1e-2.
  c.pair_symmetric = std::all_of(c.row_scale.begin(), c.row_scale.end(),
                                 [](double s) { return s == 0.0 || std::fabs(s - 1) <= 1e-13; });
  if (c.pair_symmetric)
    for (double& s : c.row_scale)
      if (s != 0.0) s = 1.0;
  c.weight = std::move(weights);
  return c;
}

void scale_neighbour_rows(const Collocation& c, const Bonds& bonds, int p, int row_length, double* values) {
  const int d = bonds.dim, b0 = bonds.offsets[p], L = bonds.family_size(p);
  for (int k = 0; k < L; ++k) {
    const double s = c.row_scale[b0 + k];
    double* rows = values + static_cast<std::ptrdiff_t>(k + 1) * d * row_length;
    for (int i = 0; i < d * row_length; ++i) rows[i] *= s;
  }
}

std::vector<double> symmetric_pair_weights(const Particles& particles, const Bonds& bonds,
                                           const std::vector<double>& weights) {
  std::vector<double> out(weights.size());
  for (int p = 0; p < bonds.particle_count(); ++p)
    for (int b = bonds.offsets[p]; b < bonds.offsets[p + 1]; ++b) {
      const int q = bonds.neighbor[b], r = reverse_bond(bonds, p, q);
      if (r < 0)
        throw std::invalid_argument("symmetric_pair_weights: bond " + std::to_string(p) + " -> " +
                                    std::to_string(q) + " has no reverse bond");
      out[b] =
          0.5 * (weights[b] * particles.volume[p] + weights[r] * particles.volume[q]) / particles.volume[p];
    }
  return out;
}

Collocation make_obq_collocation(const Particles& particles, const Bonds& bonds,
                                 const ReproducingSpace& space, std::string& description, const Box2* body,
                                 bool symmetric) {
  CloudWeights w = obq_weights_where_unisolvent(particles, bonds, space, body);
  description = fmt::format(
      "quadrature: obq ('{}', {} functions), collocation assembly ({})", space.name, space.terms.size(),
      symmetric ? "symmetric pair weights: symmetric stiffness" : "non-symmetric stiffness");
  if (body)
    description +=
        fmt::format("; families at the faces of [{:g}, {:g}] x [{:g}, {:g}] integrate over the cut ball",
                    body->lo[0], body->hi[0], body->lo[1], body->hi[1]);
  if (w.volume_families > 0)
    description += fmt::format("; {} families not unisolvent keep the volume quadrature (particle {} first)",
                               w.volume_families, w.first_volume_family);
  if (symmetric) {
    description +=
        "; pair weights symmetrised (V_p w_qp = V_q w_pq: momentum-conserving pair forces, a symmetric "
        "stiffness)";
    w.weights = symmetric_pair_weights(particles, bonds, w.weights);
  }
  return make_collocation(particles, bonds, std::move(w.weights));
}

}  // namespace pd

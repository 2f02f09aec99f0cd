// The nonlocal J-integral (paper 004), j_integral.hpp.
#include "post/j_integral.hpp"

#include <fmt/core.h>

#include <cmath>
#include <stdexcept>
#include <unordered_map>
#include <vector>

namespace pd {

namespace {
// Particles of a uniform 2D lattice by integer (column, row).
class Lattice {
 public:
  Lattice(const Particles& p, double h, const std::string& where) : h_(h) {
    if (p.dim != 2) throw std::runtime_error(where + ": the J-integral is implemented in 2D only");
    if (p.size() == 0) throw std::runtime_error(where + ": the body has no particles");
    ox_ = p.x[0], oy_ = p.x[1];
    for (int i = 0; i < p.size(); ++i) {
      const double fx = (p.x[2 * i] - ox_) / h, fy = (p.x[2 * i + 1] - oy_) / h;
      const long long cx = std::llround(fx), cy = std::llround(fy);
      if (std::fabs(fx - static_cast<double>(cx)) > 1e-6 || std::fabs(fy - static_cast<double>(cy)) > 1e-6)
        throw std::runtime_error(
            fmt::format("{}: the J-integral needs a uniform lattice of spacing h (central differences, the "
                        "paper's discretisation); "
                        "particle {} at ({:.9g}, {:.9g}) is off it (perturbed or non-uniform cloud)",
                        where, i, p.x[2 * i], p.x[2 * i + 1]));
      index_[key(cx, cy)] = i;
    }
  }
  int at(long long cx, long long cy) const {
    const auto it = index_.find(key(cx, cy));
    return it == index_.end() ? -1 : it->second;
  }
  long long column(double x) const { return std::llround((x - ox_) / h_); }
  long long row(double y) const { return std::llround((y - oy_) / h_); }
  double x_of(long long cx) const { return ox_ + static_cast<double>(cx) * h_; }
  double y_of(long long cy) const { return oy_ + static_cast<double>(cy) * h_; }
  // First and last lattice line in the closed interval [lo, hi] along one axis of origin o
  // (a line within 1e-6 h of an end counts as on it: the box a user types lands on
  // particle centres as often as not, and rounding must not decide their side).
  static std::pair<long long, long long> lines_inside(double lo, double hi, double o, double h) {
    return {static_cast<long long>(std::ceil((lo - o) / h - 1e-6)),
            static_cast<long long>(std::floor((hi - o) / h + 1e-6))};
  }
  double ox() const { return ox_; }
  double oy() const { return oy_; }

 private:
  static long long key(long long cx, long long cy) {
    return (cx + (1LL << 30)) * (1LL << 31) + (cy + (1LL << 30));
  }
  double h_, ox_ = 0, oy_ = 0;
  std::unordered_map<long long, int> index_;
};

// du/dx1 of particle p: central difference along its lattice row, one-sided at a gap.
std::array<double, 2> dudx1(const Lattice& lat, const Particles& p, const double* u, int i, double h) {
  const long long cx = lat.column(p.x[2 * i]), cy = lat.row(p.x[2 * i + 1]);
  const int l = lat.at(cx - 1, cy), r = lat.at(cx + 1, cy);
  const int a = l >= 0 ? l : i, b = r >= 0 ? r : i;
  const double span = (a == i ? 0.0 : h) + (b == i ? 0.0 : h);
  if (span == 0) return {0.0, 0.0};
  return {(u[2 * b] - u[2 * a]) / span, (u[2 * b + 1] - u[2 * a + 1]) / span};
}

// Marks the particles whose lattice cell lies in columns [c0, c1] and rows [r0, r1] (R), counting them.
std::vector<char> mark_inside(const Lattice& lat, const Particles& p, long long c0, long long c1,
                              long long r0, long long r1, int& count) {
  const int n = p.size();
  std::vector<char> inside(static_cast<std::size_t>(n), 0);
  for (int i = 0; i < n; ++i) {
    const long long cx = lat.column(p.x[2 * i]), cy = lat.row(p.x[2 * i + 1]);
    inside[i] = cx >= c0 && cx <= c1 && cy >= r0 && cy <= r1;
    count += inside[i];
  }
  return inside;
}

// The double sum over bonds between R and Q: the general form (first) and eq. (21) with the
// pair force (second); counts the bonds leaving R.
std::pair<double, double> bond_sums(const abi::KernelVariant& kernels, FamilyGather& gather,
                                    const Bonds& bonds, const Lattice& lat, const Particles& p,
                                    const double* u, double h, const std::vector<char>& inside,
                                    long long& crossing_bonds) {
  const int n = p.size();
  // The double sum: family i in R with neighbours in Q, and family j in Q with
  // neighbours in R. Forces of neighbour k of family q: -V_q V_k t_q<k>.
  std::vector<double> forces(static_cast<std::size_t>(gather.max_bonds() + 1) * 2);
  double general = 0, pair = 0;
  for (int q = 0; q < n; ++q) {
    bool crosses = false;
    for (int e = bonds.offsets[q]; e < bonds.offsets[q + 1] && !crosses; ++e)
      crosses = inside[bonds.neighbor[e]] != inside[q];
    if (!crosses) continue;
    const abi::Family fam = gather.gather(q, u);
    if (!has_intact_bond(fam)) continue;
    kernels.residual(fam, forces.data());
    const std::array<double, 2> dq = dudx1(lat, p, u, q, h);
    for (int e = bonds.offsets[q], k = 1; e < bonds.offsets[q + 1]; ++e, ++k) {
      const int j = bonds.neighbor[e];
      if (inside[j] == inside[q]) continue;
      const std::array<double, 2> dj = dudx1(lat, p, u, j, h);
      const double* f = forces.data() + 2 * k;  // = -V_q V_j t_q<j>
      const double tj = -(f[0] * dj[0] + f[1] * dj[1]), tq = -(f[0] * dq[0] + f[1] * dq[1]);
      // Inside q: + V V t_q<j> . du_j/dx1. Outside q (q plays j, j plays i): - V V t_q<j> . du_j/dx1.
      general += inside[q] ? tj : -tj;
      // Eq. (21) with f_ij = t_i<j> - t_j<i>: each family contributes (1/2) V V t . (du_i + du_j) / dx1.
      // (The family outside sees the bond from the other end: the same terms, negated.)
      pair += inside[q] ? (tj + tq) / 2 : -(tj + tq) / 2;
      if (inside[q]) ++crossing_bonds;
    }
  }
  return {general, pair};
}
}  // namespace

JIntegralResult j_integral(const FamilyAssembler& assembler, const double* u, double h,
                           const JContour& contour, const double* external) {
  const abi::KernelVariant& kernels = assembler.variant();
  const std::string& where = contour.where;
  if (kernels.energy == nullptr)
    throw std::runtime_error(
        fmt::format("{}: law {} has no energy kernel, and the J-integral's contour term needs the "
                    "strain-energy density W",
                    where, assembler.law().name));
  const FamilyInputs& in = assembler.inputs();
  const Particles& p = *in.particles;
  const Bonds& bonds = *in.bonds;
  const Lattice lat(p, h, where);
  const auto [c0, c1] = Lattice::lines_inside(contour.min[0], contour.max[0], lat.ox(), h);
  const auto [r0, r1] = Lattice::lines_inside(contour.min[1], contour.max[1], lat.oy(), h);
  JIntegralResult res;
  res.contour = contour;
  res.edge_min = {lat.x_of(c0) - h / 2, lat.y_of(r0) - h / 2, 0};
  res.edge_max = {lat.x_of(c1) + h / 2, lat.y_of(r1) + h / 2, 0};
  const int n = p.size();
  const std::vector<char> inside = mark_inside(lat, p, c0, c1, r0, r1, res.inside);
  if (res.inside == 0) throw std::runtime_error(where + ": the contour box holds no particle");

  FamilyGather gather(in);
  auto energy = [&](int i) {
    const abi::Family fam = gather.gather(i, u);
    return has_intact_bond(fam) ? kernels.energy(fam) : 0.0;  // a particle cut free stores no energy
  };
  // W at the contour point between lattice columns a (inside) and b (outside) of row cy:
  // the mean of the two, or the one that exists (a hole or the body's edge).
  auto edge_w = [&](long long a, long long b, long long cy) {
    const int i = lat.at(a, cy), j = lat.at(b, cy);
    if (i >= 0 && j >= 0) return (energy(i) + energy(j)) / 2;
    return i >= 0 ? energy(i) : j >= 0 ? energy(j) : 0.0;
  };
  // n1 = +1 on the right side, -1 on the left; 0 on top and bottom.
  for (long long cy = r0; cy <= r1; ++cy)
    res.contour_term += h * (edge_w(c1, c1 + 1, cy) - edge_w(c0, c0 - 1, cy));

  const auto [general, pair] = bond_sums(kernels, gather, bonds, lat, p, u, h, inside, res.crossing_bonds);
  if (external != nullptr)
    for (int i = 0; i < n; ++i)
      if (inside[i]) {
        const std::array<double, 2> di = dudx1(lat, p, u, i, h);
        res.load_term += external[2 * i] * di[0] + external[2 * i + 1] * di[1];
      }
  res.bond_term = general;
  res.J = res.contour_term - general - res.load_term;
  res.pairwise = res.contour_term - pair - res.load_term;
  if (!std::isfinite(res.J) || !std::isfinite(res.pairwise))
    throw std::runtime_error(
        fmt::format("{}: the J-integral is not finite (law {})", where, assembler.law().name));
  return res;
}

std::string j_integral_line(const JIntegralResult& r) {
  return fmt::format(
      "  J-integral (paper 004) on [{:.6g}, {:.6g}] x [{:.6g}, {:.6g}]: J = {:.9g} (contour {:.9g}, bonds "
      "{:.9g}, "
      "loads {:.9g}; pairwise eq. 21: {:.9g}; {} particles inside, {} bonds crossing)",
      r.edge_min[0], r.edge_max[0], r.edge_min[1], r.edge_max[1], r.J, r.contour_term, r.bond_term,
      r.load_term, r.pairwise, r.inside, r.crossing_bonds);
}

nlohmann::ordered_json j_integral_json(const std::vector<JIntegralResult>& results) {
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (const JIntegralResult& r : results)
    list.push_back(
        {{"contour",
          {{"min", {r.contour.min[0], r.contour.min[1]}}, {"max", {r.contour.max[0], r.contour.max[1]}}}},
         {"integrated", {{"min", {r.edge_min[0], r.edge_min[1]}}, {"max", {r.edge_max[0], r.edge_max[1]}}}},
         {"J", r.J},
         {"contour_term", r.contour_term},
         {"bond_term", r.bond_term},
         {"load_term", r.load_term},
         {"pairwise_eq21", r.pairwise},
         {"particles_inside", r.inside},
         {"crossing_bonds", r.crossing_bonds}});
  return list;
}

}  // namespace pd

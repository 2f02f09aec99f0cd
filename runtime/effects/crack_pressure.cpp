// Crack pressure: pair forces across the pressurised cracks' faces (effects/loads.hpp).
#include <fmt/core.h>

#include <cmath>

#include "discretize/discretization.hpp"
#include "effects/loads.hpp"

namespace pd {

namespace {
struct PressurePair {
  int a, b;
  double magnitude;  // p V_b / |xi|
};

class CrackPressure final : public Effect {
 public:
  CrackPressure(const Particles& p, std::vector<PressurePair> pairs) : p_(p), pairs_(std::move(pairs)) {}
  std::string name() const override { return "crack pressure"; }
  bool is_load() const override { return true; }
  std::size_t allocated_bytes() const override { return pairs_.size() * sizeof(PressurePair); }
  std::string describe() const override {
    return fmt::format("crack pressure on {} bond pairs across the crack faces", pairs_.size());
  }
  void add_forces(const double* u, double load, double* r) const override {
    const int d = p_.dim;
    for (const PressurePair& q : pairs_) {
      double Y[3], l = 0;
      deformed(u, q, Y, l);
      for (int c = 0; c < d; ++c) {
        const double f = load * q.magnitude * Y[c] / l;
        r[q.b * d + c] += f;
        r[q.a * d + c] -= f;
      }
    }
  }
  // f_b = g n with n = Y/|Y|: d f_b / d y_b = g (I - n n^T) / |Y| = G; the pair block is
  // [[G, -G], [-G, G]] and K = -dr/du takes its negative. A handful of pairs per crack:
  // the block search costs nothing next to the law's assembly.
  void add_stiffness(const double* u, double load, const SparsityPattern& pattern,
                     SparseMatrix& K) const override {
    const int d = p_.dim;
    double* v = K.valuePtr();
    for (const PressurePair& q : pairs_) {
      double G[3][3];
      pair_block(u, load, q, G);
      const int ids[2] = {q.a, q.b};
      for (int i : ids)
        for (int j : ids) {
          const int base = pattern.block_base(i, j), stride = pattern.column_stride(j);
          const double sign = i == j ? -1.0 : 1.0;
          for (int r = 0; r < d; ++r)
            for (int c = 0; c < d; ++c) v[base + c * stride + r] += sign * G[r][c];
        }
    }
  }
  void add_stiffness_product(const double* u, double load, const double* v, double* Kv) const override {
    const int d = p_.dim;
    for (const PressurePair& q : pairs_) {
      double G[3][3];
      pair_block(u, load, q, G);
      for (int r = 0; r < d; ++r)
        for (int c = 0; c < d; ++c) {
          const double dv = G[r][c] * (v[q.b * d + c] - v[q.a * d + c]);
          Kv[q.b * d + r] -= dv;
          Kv[q.a * d + r] += dv;
        }
    }
  }
  void add_stiffness_diagonal(const double* u, double load, double* diag) const override {
    const int d = p_.dim;
    for (const PressurePair& q : pairs_) {
      double G[3][3];
      pair_block(u, load, q, G);
      for (int r = 0; r < d; ++r) diag[q.b * d + r] -= G[r][r], diag[q.a * d + r] -= G[r][r];
    }
  }

 private:
  void deformed(const double* u, const PressurePair& q, double* Y, double& l) const {
    const int d = p_.dim;
    l = 0;
    for (int c = 0; c < d; ++c) {
      Y[c] = p_.x[q.b * d + c] + u[q.b * d + c] - p_.x[q.a * d + c] - u[q.a * d + c];
      l += Y[c] * Y[c];
    }
    l = std::sqrt(l);
  }
  void pair_block(const double* u, double load, const PressurePair& q, double G[3][3]) const {
    double Y[3], l = 0;
    deformed(u, q, Y, l);
    for (int r = 0; r < p_.dim; ++r)
      for (int c = 0; c < p_.dim; ++c)
        G[r][c] = load * q.magnitude * ((r == c ? 1.0 : 0.0) - Y[r] * Y[c] / (l * l)) / l;
  }
  const Particles& p_;
  std::vector<PressurePair> pairs_;
};
}  // namespace

std::unique_ptr<Effect> make_crack_pressure(const Scene& s, const Particles& p, const Bonds& bonds) {
  return make_crack_pressure(s.cracks, s.h, p, bonds);
}

std::unique_ptr<Effect> make_crack_pressure(std::span<const Crack> cracks, double h, const Particles& p,
                                            const Bonds& bonds) {
  std::vector<PressurePair> pairs;
  const int d = p.dim;
  for (const Crack& crack : cracks) {
    if (crack.pressure == 0) continue;
    // The crack's unit normal and measure (length in 2D, polygon area in 3D).
    double normal[3] = {0, 0, 0}, measure = 0;
    if (d == 2) {
      const double tx = crack.points[1][0] - crack.points[0][0], ty = crack.points[1][1] - crack.points[0][1];
      measure = std::hypot(tx, ty);
      normal[0] = -ty / measure, normal[1] = tx / measure;
    } else {
      const Point& o = crack.points[0];
      for (std::size_t i = 1; i + 1 < crack.points.size(); ++i) {
        const double u[3] = {crack.points[i][0] - o[0], crack.points[i][1] - o[1], crack.points[i][2] - o[2]};
        const double v[3] = {crack.points[i + 1][0] - o[0], crack.points[i + 1][1] - o[1],
                             crack.points[i + 1][2] - o[2]};
        normal[0] += u[1] * v[2] - u[2] * v[1], normal[1] += u[2] * v[0] - u[0] * v[2],
            normal[2] += u[0] * v[1] - u[1] * v[0];
      }
      measure = 0.5 * std::sqrt(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]);
      for (double& c : normal) c /= 2 * measure;
    }
    const std::size_t first = pairs.size();
    double normal_total = 0;
    for (int a = 0; a < p.size(); ++a)
      for (int e = bonds.offsets[a]; e < bonds.offsets[a + 1]; ++e) {
        const int b = bonds.neighbor[e];
        // Nearest neighbours only (|xi| < 1.2 h): the particles facing each other across the crack.
        if (b <= a || bonds.length[e] > 1.2 * h || !crack_crosses(crack, p.position(a), p.position(b), d))
          continue;
        const double magnitude = crack.pressure * p.volume[b] / bonds.length[e];
        double cosine = 0;
        for (int c = 0; c < d; ++c) cosine += normal[c] * bonds.xi[e * d + c] / bonds.length[e];
        normal_total += magnitude * std::fabs(cosine);
        pairs.push_back({a, b, magnitude});
      }
    // On the paper's lattice the pairs carry exactly p x measure across each face; on a
    // perturbed cloud the |xi| < 1.2 h rule picks tilted and extra pairs, so scale them to
    // keep the total normal load p x measure.
    if (normal_total > 0)
      for (std::size_t i = first; i < pairs.size(); ++i)
        pairs[i].magnitude *= crack.pressure * measure / normal_total;
  }
  if (pairs.empty()) return nullptr;
  return std::make_unique<CrackPressure>(p, std::move(pairs));
}

}  // namespace pd

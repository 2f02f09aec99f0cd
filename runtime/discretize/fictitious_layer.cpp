// The mirror map of a fictitious boundary layer as multipoint constraints.
#include "discretize/fictitious_layer.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <unordered_map>

namespace pd {

namespace {

// Finds the particle at a point (within 1e-6 of the smallest spacing): hashed cells of
// that spacing, the point's cell and its neighbours searched.
class PointLocator {
 public:
  explicit PointLocator(const Particles& p) : p_(p) {
    cell_ = std::numeric_limits<double>::max();
    for (double v : p.volume) cell_ = std::min(cell_, std::pow(v, 1.0 / p.dim));
    if (!(cell_ > 0) || !std::isfinite(cell_))
      throw std::invalid_argument("fictitious layer: particles without volume");
    for (int i = 0; i < p.size(); ++i) cells_[key(p.position(i), 0, 0, 0)].push_back(i);
  }
  int find(const double* x) const {
    const double tol = 1e-6 * cell_;
    for (int a = -1; a <= 1; ++a)
      for (int b = -1; b <= 1; ++b)
        for (int c = (p_.dim == 3 ? -1 : 0); c <= (p_.dim == 3 ? 1 : 0); ++c) {
          auto it = cells_.find(key(x, a, b, c));
          if (it == cells_.end()) continue;
          for (int i : it->second) {
            double d2 = 0;
            for (int k = 0; k < p_.dim; ++k) d2 += (p_.position(i)[k] - x[k]) * (p_.position(i)[k] - x[k]);
            if (d2 <= tol * tol) return i;
          }
        }
    return -1;
  }
  double spacing() const { return cell_; }

 private:
  long long key(const double* x, int a, int b, int c) const {
    const long long i = static_cast<long long>(std::floor(x[0] / cell_)) + a;
    const long long j = static_cast<long long>(std::floor(x[1] / cell_)) + b;
    const long long k = p_.dim == 3 ? static_cast<long long>(std::floor(x[2] / cell_)) + c : 0;
    return (i * 2000003LL + j) * 2000003LL + k;
  }
  const Particles& p_;
  double cell_;
  std::unordered_map<long long, std::vector<int>> cells_;
};

std::string where(const Particles& p, int i) {
  const double* x = p.position(i);
  return p.dim == 3 ? fmt::format("({:.6g}, {:.6g}, {:.6g})", x[0], x[1], x[2])
                    : fmt::format("({:.6g}, {:.6g})", x[0], x[1]);
}

// Adds coefficient * u[particle][component] to a tie (merging a repeated master).
void add_term(TiedDof& t, int dof, double coefficient) {
  if (coefficient == 0) return;
  for (std::size_t k = 0; k < t.masters.size(); ++k)
    if (t.masters[k] == dof) {
      t.coefficients[k] += coefficient;
      return;
    }
  t.masters.push_back(dof);
  t.coefficients.push_back(coefficient);
}

// Rejects a face normal that is not a unit vector and a traction condition the (2D) variant cannot take.
void check_layer_condition(int d, const LayerCondition& c) {
  const auto& n = c.face.normal;
  double nn = 0;
  for (int k = 0; k < d; ++k) nn += n[k] * n[k];
  if (std::abs(nn - 1) > 1e-12)
    throw std::invalid_argument("fictitious layer: the face normal must be a unit vector");
  if (c.kind == LayerCondition::Kind::traction && d != 2)
    throw std::invalid_argument(
        "fictitious layer: the traction variant (paper 003 eqs. 32-35) is two-dimensional");
  if (c.kind == LayerCondition::Kind::traction && !(c.M > 0 && c.mu > 0))
    throw std::invalid_argument("fictitious layer: the traction variant needs positive elastic constants");
}

// What the ties of every particle of one layer share.
struct LayerContext {
  const Particles& particles;
  const PointLocator& locate;
  std::span<const char> target;
  const LayerCondition& c;
  std::array<double, 3> t;  // 2D tangent of the face
};

// The target particle at the mirror image xm of layer particle f; throws naming f when there is none.
int mirror_particle(const LayerContext& L, int f, const std::array<double, 3>& xm) {
  const int d = L.particles.dim;
  const int m = L.locate.find(xm.data());
  if (m < 0 || !L.target[m])
    throw std::invalid_argument(
        fmt::format("fictitious layer: the particle at {} has no particle outside its layer at its mirror "
                    "image {}: the lattice must be "
                    "symmetric about the face and the body at least as deep as the layer",
                    where(L.particles, f),
                    d == 3 ? fmt::format("({:.6g}, {:.6g}, {:.6g})", xm[0], xm[1], xm[2])
                           : fmt::format("({:.6g}, {:.6g})", xm[0], xm[1])));
  return m;
}

// Displacement ties of layer particle f on mirror m (eqs. 29-31): odd mirror about U*(xs) where
// prescribed, even mirror elsewhere.
void add_displacement_ties(std::vector<TiedDof>& ties, const LayerContext& L, int f, int m,
                           const std::array<double, 3>& xs) {
  const int d = L.particles.dim;
  const LayerCondition& c = L.c;
  const std::array<double, 3> U = c.value ? c.value(xs.data()) : std::array<double, 3>{};
  for (int k = 0; k < d; ++k) {
    TiedDof tie{f * d + k, {}, {}, 0.0};
    if (c.prescribed[k]) {
      add_term(tie, m * d + k, -1.0);
      tie.offset = 2 * U[k];
    } else {
      add_term(tie, m * d + k, 1.0);
    }
    ties.push_back(std::move(tie));
  }
}

// Traction ties of layer particle f at distance s from the face, on mirror m at xm (eqs. 32-35).
void add_traction_ties(std::vector<TiedDof>& ties, const LayerContext& L, int f, int m, double s,
                       const std::array<double, 3>& xm) {
  const Particles& particles = L.particles;
  const LayerCondition& c = L.c;
  const int d = particles.dim;
  const auto& n = c.face.normal;
  const std::array<double, 3>& t = L.t;
  // Traction: tangential neighbours of the mirror image, one-sided where one is missing.
  const double h = std::sqrt(particles.volume[m]);
  std::array<double, 3> xp{}, xq{};
  for (int k = 0; k < 2; ++k) {
    xp[k] = xm[k] + h * t[k];
    xq[k] = xm[k] - h * t[k];
  }
  int plus = L.locate.find(xp.data()), minus = L.locate.find(xq.data());
  if (plus >= 0 && !L.target[plus]) plus = -1;
  if (minus >= 0 && !L.target[minus]) minus = -1;
  double span = 2 * h;
  if (plus < 0 && minus < 0)
    throw std::invalid_argument(
        fmt::format("fictitious layer: the mirror image {} of the particle at {} has no body "
                    "neighbour along the face (spacing {:.3g}) to take the tangential derivative from",
                    where(particles, m), where(particles, f), h));
  if (plus < 0) plus = m, span = h;
  if (minus < 0) minus = m, span = h;
  const double dist = 2 * s;  // (x_f - x) . n
  const double sn = c.traction[0] * n[0] + c.traction[1] * n[1];
  const double st = c.traction[0] * t[0] + c.traction[1] * t[1];
  for (int k = 0; k < 2; ++k) {
    TiedDof tie{f * d + k, {}, {}, dist * (n[k] * sn / c.M + t[k] * st / c.mu)};
    add_term(tie, m * d + k, 1.0);
    // eps_nn = sigma_nn / M - (lambda / M) du_t/dt; du_t/dn = 2 eps_nt - du_n/dt.
    for (int j = 0; j < 2; ++j) {
      const double dt_coefficient = -dist * (n[k] * (c.lambda / c.M) * t[j] + t[k] * n[j]) / span;
      add_term(tie, plus * d + j, dt_coefficient);
      add_term(tie, minus * d + j, -dt_coefficient);
    }
    ties.push_back(std::move(tie));
  }
}

}  // namespace

std::vector<TiedDof> fictitious_layer_ties(const Particles& particles, std::span<const int> layer,
                                           std::span<const char> target, const LayerCondition& c) {
  const int d = particles.dim;
  const auto& n = c.face.normal;
  check_layer_condition(d, c);
  const PointLocator locate(particles);
  const LayerContext L{particles, locate, target, c, {-n[1], n[0], 0.0}};
  std::vector<TiedDof> ties;
  for (int f : layer) {
    const double* xf = particles.position(f);
    double s = 0;  // signed distance from the face, positive in the layer
    for (int k = 0; k < d; ++k) s += (xf[k] - c.face.point[k]) * n[k];
    if (!(s > 0))
      throw std::invalid_argument(
          fmt::format("fictitious layer: the particle at {} is not outside the face (distance {:.3g} "
                      "along the normal)",
                      where(particles, f), s));
    std::array<double, 3> xm{}, xs{};
    for (int k = 0; k < d; ++k) {
      xm[k] = xf[k] - 2 * s * n[k];
      xs[k] = xf[k] - s * n[k];
    }
    const int m = mirror_particle(L, f, xm);
    if (c.kind == LayerCondition::Kind::displacement)
      add_displacement_ties(ties, L, f, m, xs);
    else
      add_traction_ties(ties, L, f, m, s, xm);
  }
  return ties;
}

void compose_ties(std::vector<TiedDof>& ties, int n_dofs) {
  std::vector<int> tie_of(static_cast<std::size_t>(n_dofs), -1);
  for (std::size_t i = 0; i < ties.size(); ++i) tie_of[ties[i].dof] = static_cast<int>(i);
  // Each pass replaces every tied master by its tie's terms; a chain of k layers needs k
  // passes, so more passes than ties means a cycle.
  for (std::size_t pass = 0;; ++pass) {
    bool changed = false;
    for (TiedDof& t : ties) {
      TiedDof out{t.dof, {}, {}, t.offset};
      for (std::size_t k = 0; k < t.masters.size(); ++k) {
        const int j = tie_of[t.masters[k]];
        if (j < 0) {
          add_term(out, t.masters[k], t.coefficients[k]);
          continue;
        }
        changed = true;
        const TiedDof& sub = ties[static_cast<std::size_t>(j)];
        out.offset += t.coefficients[k] * sub.offset;
        for (std::size_t q = 0; q < sub.masters.size(); ++q)
          add_term(out, sub.masters[q], t.coefficients[k] * sub.coefficients[q]);
      }
      t = std::move(out);
    }
    if (!changed) return;
    if (pass > ties.size()) throw std::invalid_argument("fictitious layers: the mirror images form a cycle");
  }
}

}  // namespace pd

// The benchmarked laws written by hand, templated on the scalar type: the residual
// that the forward-AD baselines differentiate over all family dofs (Trilinos Sacado's
// DFad, as Peridigm does for its elastic models, and Eigen's AutoDiffScalar). Intact bonds only
// (alpha = 1), like the generated `intact` kernels the benchmark compares with.
//
// Written the way a competent hand implementation would be for AD: every per-bond
// quantity is computed once and kept (Y, |Y|, ...), each bond's force is one scalar
// coefficient times Y, and all AD temporaries live in a Workspace reused across
// calls, so Eigen's lazy derivative expressions are evaluated into existing storage
// (no allocation per operation, also with a heap-allocated derivative vector).
//
// The same formulas as laws/silling.cpp, oterkus.cpp, correspondence.cpp,
// bond_based.cpp and elastic_plastic.cpp (the incremental residual of a law with memory, from
// the family's committed history), including deformed_length() = sqrt(|Y|^2 + 1e-16 |xi|^2); the
// benchmark checks residual and tangent against the generated kernels before timing.
#pragma once

#include <cmath>
#include <numbers>
#include <type_traits>
#include <vector>

#include "kernel_abi.hpp"

namespace pd::bench {

// Reused AD storage for one family size.
template <class S>
struct Workspace {
  std::vector<S> Y, len, a, b;  // [L*dim], [L], [L], [L]
  S t0, t1, t2;
  S N[9], P[9];
  double yield_ratio = 0;  // elastic_plastic: ||t_trial||^2 / (2 psi0) of the last call
  void resize(int L, int dim) {
    Y.resize(static_cast<std::size_t>(L) * dim);
    len.resize(static_cast<std::size_t>(L));
    a.resize(static_cast<std::size_t>(L));
    b.resize(static_cast<std::size_t>(L));
  }
};

namespace detail {
template <class S>
void zero(S& x, const S& like) {
  if constexpr (std::is_same_v<S, double>) {
    x = 0.0;
  } else if constexpr (requires { x.fastAccessDx(0); }) {
    x = 0.0;  // Sacado: a constant (no derivative entries); the first += sizes it, keeping its storage
  } else {
    x = like;  // Eigen: sizes the derivative vector like the seeded inputs
    x.value() = 0.0;
    x.derivatives().setZero();
  }
}

// Y_k = y_{k+1} - y_0 and |Y_k|; f zeroed (shaped like y[0]).
template <class S>
void bonds(const abi::Family& fam, int d, const S* y, S* f, Workspace<S>& w) {
  const int L = fam.n_bonds;
  w.resize(L, d);
  for (int i = 0; i < (L + 1) * d; ++i) zero(f[i], y[0]);
  for (int k = 0; k < L; ++k) {
    double r2 = 0;
    for (int c = 0; c < d; ++c) {
      const double x = fam.xi[k * d + c];
      r2 += x * x;
      w.Y[k * d + c] = y[(k + 1) * d + c] - y[c];
    }
    S& l = w.len[k];
    l = w.Y[k * d] * w.Y[k * d];
    for (int c = 1; c < d; ++c) l += w.Y[k * d + c] * w.Y[k * d + c];
    using std::sqrt;
    l = sqrt(l + 1e-16 * r2);
  }
}

// f_0 += coef_k Y_k, f_{k+1} -= coef_k Y_k.
template <class S>
void scatter(const abi::Family& fam, int d, S* f, Workspace<S>& w, const std::vector<S>& coef) {
  for (int k = 0; k < fam.n_bonds; ++k)
    for (int c = 0; c < d; ++c) {
      w.t0 = coef[k] * w.Y[k * d + c];
      f[c] += w.t0;
      f[(k + 1) * d + c] -= w.t0;
    }
}

template <class S>
double value(const S& x) {
  if constexpr (std::is_same_v<S, double>)
    return x;
  else if constexpr (requires { x.fastAccessDx(0); })
    return x.val();
  else
    return x.value();
}

inline double norm(const double* x, int d) {
  double s = 0;
  for (int c = 0; c < d; ++c) s += x[c] * x[c];
  return std::sqrt(s);
}
}  // namespace detail

// laws/silling.cpp; params K (3D bulk), G.
template <class S>
void silling(const abi::Family& fam, int d, const S* y, S* f, Workspace<S>& w) {
  const int L = fam.n_bonds;
  detail::bonds(fam, d, y, f, w);
  const double K = fam.params[0], G = fam.params[1], n = d;
  double m = 0;
  for (int k = 0; k < L; ++k) {
    const double r = detail::norm(fam.xi + k * d, d);
    m += fam.w[k] * r * r * fam.V[k];
  }
  detail::zero(w.t1, y[0]);  // theta
  for (int k = 0; k < L; ++k) {
    const double r = detail::norm(fam.xi + k * d, d);
    w.t1 += (n / m * fam.w[k] * r * fam.V[k]) * (w.len[k] - r);
  }
  const double bulk = d == 2 ? K + G / 3 : K, shear = d == 2 ? 8.0 : 15.0;
  // t = w/m [n bulk theta r + shear G (e - theta r / n)] Y/|Y|
  for (int k = 0; k < L; ++k) {
    const double r = detail::norm(fam.xi + k * d, d), c = fam.V0 * fam.V[k] * fam.w[k] / m;
    w.a[k] = (c * (n * bulk - shear * G / n) * r * w.t1 + (c * shear * G) * (w.len[k] - r)) / w.len[k];
  }
  detail::scatter(fam, d, f, w, w.a);
}

// laws/oterkus.cpp (2D); params kappa2, G.
template <class S>
void oterkus(const abi::Family& fam, int d, const S* y, S* f, Workspace<S>& w) {
  const int L = fam.n_bonds;
  detail::bonds(fam, d, y, f, w);
  const double kappa = fam.params[0], G = fam.params[1];
  double m1 = 0, m2 = 0, mx = 0;
  for (int k = 0; k < L; ++k) {
    const double* xi = fam.xi + k * d;
    const double r = detail::norm(xi, d), wv = fam.w[k] * fam.V[k];
    m1 += wv * r;
    m2 += wv * r * r;
    mx += wv * (xi[0] * xi[1]) * (xi[0] * xi[1]) / (r * r);
  }
  const double dd = 2 / m1, b = G / (2 * mx), a = (2 * kappa - b * m2) / 4;
  detail::zero(w.t1, y[0]);  // theta
  for (int k = 0; k < L; ++k) {
    const double* xi = fam.xi + k * d;
    const double r = detail::norm(xi, d);
    // cosine_k = Y.xi / (|Y| r), kept in w.b
    w.t0 = w.Y[k * d] * xi[0];
    for (int c = 1; c < d; ++c) w.t0 += w.Y[k * d + c] * xi[c];
    w.b[k] = w.t0 / (w.len[k] * r);
    w.t1 += (dd * fam.w[k] * fam.V[k]) * (w.len[k] - r) * w.b[k];
  }
  // t = 2 w (a d cosine theta + b e) Y/|Y|
  for (int k = 0; k < L; ++k) {
    const double r = detail::norm(fam.xi + k * d, d), c = 2 * fam.w[k] * fam.V0 * fam.V[k];
    w.a[k] = ((c * a * dd) * w.b[k] * w.t1 + (c * b) * (w.len[k] - r)) / w.len[k];
  }
  detail::scatter(fam, d, f, w, w.a);
}

// laws/bond_based.cpp, constant micromodulus; param kappa2 (2D) or K (3D).
template <class S>
void bond_based_constant(const abi::Family& fam, int d, const S* y, S* f, Workspace<S>& w) {
  const int L = fam.n_bonds;
  detail::bonds(fam, d, y, f, w);
  const double c = (d == 2 ? 12.0 : 18.0) * fam.params[0] / (std::numbers::pi * std::pow(fam.delta, d + 1));
  // t = c s / 2 Y/|Y|, s = (|Y| - r) / r
  for (int k = 0; k < L; ++k) {
    const double r = detail::norm(fam.xi + k * d, d), q = fam.V0 * fam.V[k] * c / (2 * r);
    w.a[k] = q * (w.len[k] - r) / w.len[k];
  }
  detail::scatter(fam, d, f, w, w.a);
}

// laws/correspondence.cpp without stabilisation; params K (3D bulk), G.
// F = N K^-1, eps = sym(F) - I, sigma = lambda tr(eps) I + 2 G eps, t_k = w sigma K^-1 xi_k.
template <class S>
void correspondence(const abi::Family& fam, int d, const S* y, S* f, Workspace<S>& w) {
  const int L = fam.n_bonds;
  detail::bonds(fam, d, y, f, w);
  const double Kb = fam.params[0], G = fam.params[1], lambda = Kb - 2 * G / 3;
  double Ks[9] = {}, Ki[9] = {};
  for (int k = 0; k < L; ++k)
    for (int i = 0; i < d; ++i)
      for (int j = 0; j < d; ++j)
        Ks[i * d + j] += fam.w[k] * fam.V[k] * fam.xi[k * d + i] * fam.xi[k * d + j];
  if (d == 2) {
    const double det = Ks[0] * Ks[3] - Ks[1] * Ks[2];
    Ki[0] = Ks[3] / det, Ki[1] = -Ks[1] / det, Ki[2] = -Ks[2] / det, Ki[3] = Ks[0] / det;
  } else {
    const double det = Ks[0] * (Ks[4] * Ks[8] - Ks[5] * Ks[7]) - Ks[1] * (Ks[3] * Ks[8] - Ks[5] * Ks[6]) +
                       Ks[2] * (Ks[3] * Ks[7] - Ks[4] * Ks[6]);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        const int j1 = (j + 1) % 3, j2 = (j + 2) % 3, i1 = (i + 1) % 3, i2 = (i + 2) % 3;
        Ki[i * 3 + j] = (Ks[j1 * 3 + i1] * Ks[j2 * 3 + i2] - Ks[j1 * 3 + i2] * Ks[j2 * 3 + i1]) / det;
      }
  }
  // N = sum w V Y (x) xi
  for (int i = 0; i < d * d; ++i) detail::zero(w.N[i], y[0]);
  for (int k = 0; k < L; ++k)
    for (int i = 0; i < d; ++i)
      for (int j = 0; j < d; ++j)
        w.N[i * d + j] += (fam.w[k] * fam.V[k] * fam.xi[k * d + j]) * w.Y[k * d + i];
  // F = N K^-1 (into P), then sigma (into N), then P = sigma K^-1.
  for (int i = 0; i < d; ++i)
    for (int j = 0; j < d; ++j) {
      w.P[i * d + j] = w.N[i * d] * Ki[j];
      for (int q = 1; q < d; ++q) w.P[i * d + j] += w.N[i * d + q] * Ki[q * d + j];
    }
  w.t1 = w.P[0];  // tr(eps) = tr(F) - d
  for (int i = 1; i < d; ++i) w.t1 += w.P[i * d + i];
  w.t1 = lambda * (w.t1 - d);
  for (int i = 0; i < d; ++i)
    for (int j = 0; j < d; ++j) {
      w.N[i * d + j] = G * (w.P[i * d + j] + w.P[j * d + i]);
      if (i == j) w.N[i * d + j] += w.t1 - 2 * G;
    }
  for (int i = 0; i < d; ++i)
    for (int j = 0; j < d; ++j) {
      w.P[i * d + j] = w.N[i * d] * Ki[j];
      for (int q = 1; q < d; ++q) w.P[i * d + j] += w.N[i * d + q] * Ki[q * d + j];
    }
  for (int k = 0; k < L; ++k) {
    const double c = fam.V0 * fam.V[k] * fam.w[k];
    for (int i = 0; i < d; ++i) {
      w.t0 = w.P[i * d] * (c * fam.xi[k * d]);
      for (int j = 1; j < d; ++j) w.t0 += w.P[i * d + j] * (c * fam.xi[k * d + j]);
      f[i] += w.t0;
      f[(k + 1) * d + i] -= w.t0;
    }
  }
}

// laws/elastic_plastic.cpp (Mitchell's elastic-perfectly-plastic law); params K (3D bulk), G,
// sigma_y; fam.history[k] the committed plastic extension e_p of bond k. The trial
// deviatoric state t_tr = alpha w (e_d - e_p) from it, the closed-form return
// s = sqrt(2 psi0 / ||t_tr||^2) on the plastic branch (1 on the elastic one), and
// t = (w / m) n kappa theta |xi| + s t_tr along Y/|Y|: the step's incremental residual.
template <class S>
void elastic_plastic(const abi::Family& fam, int d, const S* y, S* f, Workspace<S>& w) {
  const int L = fam.n_bonds;
  detail::bonds(fam, d, y, f, w);
  const double K = fam.params[0], G = fam.params[1], sigma_y = fam.params[2], n = d;
  double m = 0, q = 0;
  for (int k = 0; k < L; ++k) {
    const double r = detail::norm(fam.xi + k * d, d);
    m += fam.w[k] * r * r * fam.V[k];
    q += fam.w[k] * fam.w[k] * r * r * fam.V[k];
  }
  detail::zero(w.t1, y[0]);  // theta
  for (int k = 0; k < L; ++k) {
    const double r = detail::norm(fam.xi + k * d, d);
    w.t1 += (n / m * fam.w[k] * r * fam.V[k]) * (w.len[k] - r);
  }
  const double kappa = d == 2 ? K + G / 3 : K, c = d == 2 ? 8.0 : 15.0, alpha = c * G / m;
  const double psi0 = c * c / (d == 2 ? 48.0 : 90.0) * q * sigma_y * sigma_y / (m * m);
  detail::zero(w.t2, y[0]);  // ||t_tr||^2
  for (int k = 0; k < L; ++k) {
    const double r = detail::norm(fam.xi + k * d, d);
    w.b[k] = (alpha * fam.w[k]) * (w.len[k] - (r / n) * w.t1 - (r + fam.history[k]));
    w.t2 += fam.V[k] * (w.b[k] * w.b[k]);
  }
  w.yield_ratio = detail::value(w.t2) / (2 * psi0);
  using std::sqrt;
  if (w.yield_ratio > 1) {
    w.t0 = sqrt((2 * psi0) / w.t2);
  } else {
    detail::zero(w.t0, y[0]);
    w.t0 += 1.0;
  }
  for (int k = 0; k < L; ++k) {
    const double r = detail::norm(fam.xi + k * d, d), v = fam.V0 * fam.V[k];
    w.a[k] = ((v * fam.w[k] / m * n * kappa * r) * w.t1 + v * (w.t0 * w.b[k])) / w.len[k];
  }
  detail::scatter(fam, d, f, w, w.a);
}

}  // namespace pd::bench

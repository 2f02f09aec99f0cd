// Test-only laws conforming to the kernel ABI: bond springs (linear and geometrically
// exact) and a one-state law, with tangent factors derived by hand.
//
// Each law computes, per bond i, the force state t_i and its factors (kernel_abi.hpp):
// T_ik = delta_ik direct_i + sum_s left_i[s] (x) right_k[s]. The residual, tangent and
// tangent-vector product kernels are derived from those once, generically.
#pragma once

#include <cmath>
#include <vector>

#include "kernel_abi.hpp"

namespace pd::test {

template <int D>
double norm_of(const double* a) {
  double s = 0;
  for (int c = 0; c < D; ++c) s += a[c] * a[c];
  return std::sqrt(s);
}

// Bond spring, energy phi = c |xi| s^2 / 2 per bond (s the stretch), so t = d phi / dY.
//   exact:  s = (|Y| - |xi|)/|xi|,  t = c s e_Y,   dt/dY = c [e e^T / |xi| + s (I - e e^T) / |Y|]
//   linear: s = e_xi . (Y - xi) / |xi|, t = c s e_xi, dt/dY = c e_xi e_xi^T / |xi|
// (the linear one makes the global problem exactly linear). Parameter: c.
template <int D, bool Linear>
struct SpringLaw {
  static constexpr int n_states = 0, n_moments = 0;
  static void bonds(const abi::Family& f, bool use_alpha, double* t, double* direct, double*, double*,
                    double*) {
    const double c0 = f.params[0];
    for (int i = 0; i < f.n_bonds; ++i) {
      const double* xi = f.xi + i * D;
      const double* Y = f.Y + i * D;
      const double c = c0 * (use_alpha ? f.alpha[i] : 1.0), lx = norm_of<D>(xi), ly = norm_of<D>(Y);
      double e[D];
      double s;
      if (Linear) {
        s = 0;
        for (int k = 0; k < D; ++k) e[k] = xi[k] / lx, s += e[k] * (Y[k] - xi[k]);
        s /= lx;
      } else {
        for (int k = 0; k < D; ++k) e[k] = Y[k] / ly;
        s = (ly - lx) / lx;
      }
      for (int r = 0; r < D; ++r) {
        t[i * D + r] = c * s * e[r];
        for (int q = 0; q < D; ++q) {
          const double ee = e[r] * e[q];
          direct[(i * D + r) * D + q] = Linear ? c * ee / lx : c * (ee / lx + s * ((r == q) - ee) / ly);
        }
      }
    }
  }
  static double energy(const abi::Family& f, bool use_alpha) {
    double W = 0;
    for (int i = 0; i < f.n_bonds; ++i) {
      const double* xi = f.xi + i * D;
      const double* Y = f.Y + i * D;
      const double lx = norm_of<D>(xi);
      double s = 0;
      if (Linear) {
        for (int k = 0; k < D; ++k) s += xi[k] / lx * (Y[k] - xi[k]);
        s /= lx;
      } else {
        s = (norm_of<D>(Y) - lx) / lx;
      }
      W += 0.5 * f.params[0] * (use_alpha ? f.alpha[i] : 1.0) * lx * s * s * f.V[i];
    }
    return W;  // per unit volume of the center: E = V0 W, t_i = (1/V_i) dW/dY_i
  }
};

// One-state law. Moment m = sum a_k w_k |xi_k|^2 V_k (a_k = alpha_k), state
// theta = sum a_k w_k |xi_k| (|Y_k| - |xi_k|) V_k, energy density
//   W = A theta^2 / (2 m) + (B/2) sum a_k w_k (|Y_k| - |xi_k|)^2 V_k,
// t_i = (1/V_i) dW/dY_i = (A theta / m) a_i w_i |xi_i| e_i + B a_i w_i (|Y_i| - |xi_i|) e_i.
// Factors: left_i = dt_i/dtheta = (A/m) a_i w_i |xi_i| e_i, right_k = dtheta/dY_k =
// a_k w_k |xi_k| V_k e_k, and at fixed theta
//   direct_i = (A theta/m) a_i w_i |xi_i| P/|Y_i| + B a_i w_i [e e^T + (|Y_i|-|xi_i|) P/|Y_i|],
// P = I - e e^T. Parameters: A, B.
template <int D>
struct StateLaw {
  static constexpr int n_states = 1, n_moments = 1;
  static double moment(const abi::Family& f, bool use_alpha) {
    double m = 0;
    for (int k = 0; k < f.n_bonds; ++k) {
      const double lx = norm_of<D>(f.xi + k * D);
      m += (use_alpha ? f.alpha[k] : 1.0) * f.w[k] * lx * lx * f.V[k];
    }
    return m;
  }
  static double theta(const abi::Family& f, bool use_alpha) {
    double th = 0;
    for (int k = 0; k < f.n_bonds; ++k) {
      const double lx = norm_of<D>(f.xi + k * D), ly = norm_of<D>(f.Y + k * D);
      th += (use_alpha ? f.alpha[k] : 1.0) * f.w[k] * lx * (ly - lx) * f.V[k];
    }
    return th;
  }
  static void bonds(const abi::Family& f, bool use_alpha, double* t, double* direct, double* left,
                    double* right, double*) {
    const double A = f.params[0], B = f.params[1], m = f.moments[0], th = theta(f, use_alpha);
    for (int i = 0; i < f.n_bonds; ++i) {
      const double a = use_alpha ? f.alpha[i] : 1.0, w = f.w[i];
      const double lx = norm_of<D>(f.xi + i * D), ly = norm_of<D>(f.Y + i * D);
      double e[D];
      for (int k = 0; k < D; ++k) e[k] = f.Y[i * D + k] / ly;
      const double g = A * th / m * a * w * lx, h = B * a * w * (ly - lx);
      for (int r = 0; r < D; ++r) {
        t[i * D + r] = (g + h) * e[r];
        if (left) left[i * D + r] = A / m * a * w * lx * e[r];
        if (right) right[i * D + r] = a * w * lx * f.V[i] * e[r];
        if (direct)
          for (int q = 0; q < D; ++q) {
            const double ee = e[r] * e[q], P = (r == q) - ee;
            direct[(i * D + r) * D + q] = g * P / ly + B * a * w * ee + h * P / ly;
          }
      }
    }
  }
  static double energy(const abi::Family& f, bool use_alpha) {
    const double th = theta(f, use_alpha);
    double W = 0.5 * f.params[0] * th * th / f.moments[0];
    for (int k = 0; k < f.n_bonds; ++k) {
      const double lx = norm_of<D>(f.xi + k * D), ly = norm_of<D>(f.Y + k * D);
      W += 0.5 * f.params[1] * (use_alpha ? f.alpha[k] : 1.0) * f.w[k] * (ly - lx) * (ly - lx) * f.V[k];
    }
    return W;
  }
};

// The ABI kernels, derived from a law's per-bond force states and factors.
template <class Law, int D, bool UseAlpha>
struct Kernels {
  static constexpr int S = Law::n_states;
  struct Scratch {
    std::vector<double> t, direct, left, right;
    explicit Scratch(int L) : t(L * D), direct(L * D * D), left(L * S * D + 1), right(L * S * D + 1) {}
  };
  static void moments(const abi::Family& f, double* m) {
    if constexpr (Law::n_moments > 0) m[0] = Law::moment(f, UseAlpha);
  }
  static void scatter(const abi::Family& f, const double* t, double* forces) {
    for (int c = 0; c < D; ++c) forces[c] = 0;
    for (int i = 0; i < f.n_bonds; ++i) {
      const double cv = f.V0 * f.V[i];
      for (int c = 0; c < D; ++c) {
        forces[c] += cv * t[i * D + c];
        forces[(i + 1) * D + c] = -cv * t[i * D + c];
      }
    }
  }
  static void residual(const abi::Family& f, double* forces) {
    Scratch s(f.n_bonds);
    Law::bonds(f, UseAlpha, s.t.data(), s.direct.data(), s.left.data(), s.right.data(), nullptr);
    scatter(f, s.t.data(), forces);
  }
  static void tangent(const abi::Family& f, double* forces, const abi::TangentFactors& fac) {
    Scratch s(f.n_bonds);
    Law::bonds(f, UseAlpha, s.t.data(), fac.direct, S ? fac.left : nullptr, S ? fac.right : nullptr, nullptr);
    if (forces) scatter(f, s.t.data(), forces);
  }
  static void jvp(const abi::Family& f, const double* dy, double* df) {
    Scratch s(f.n_bonds);
    Law::bonds(f, UseAlpha, s.t.data(), s.direct.data(), s.left.data(), s.right.data(), nullptr);
    double proj[S + 1] = {};  // sum_k right_k[s] . dY_k
    for (int k = 0; k < f.n_bonds; ++k)
      for (int st = 0; st < S; ++st)
        for (int c = 0; c < D; ++c) proj[st] += s.right[(k * S + st) * D + c] * (dy[(k + 1) * D + c] - dy[c]);
    for (int c = 0; c < D; ++c) df[c] = 0;
    for (int i = 0; i < f.n_bonds; ++i) {
      const double cv = f.V0 * f.V[i];
      for (int r = 0; r < D; ++r) {
        double dt = 0;
        for (int q = 0; q < D; ++q) dt += s.direct[(i * D + r) * D + q] * (dy[(i + 1) * D + q] - dy[q]);
        for (int st = 0; st < S; ++st) dt += s.left[(i * S + st) * D + r] * proj[st];
        df[r] += cv * dt;
        df[(i + 1) * D + r] = -cv * dt;
      }
    }
  }
  static double energy(const abi::Family& f) { return Law::energy(f, UseAlpha); }
  static abi::KernelVariant variant() {
    abi::KernelVariant v;
    v.moments = &moments;
    v.residual = &residual;
    v.tangent = &tangent;
    v.jvp = &jvp;
    v.energy = &energy;
    return v;
  }
};

template <class Law, int D>
abi::LawDescriptor make_descriptor(const char* name, int n_params) {
  static const char* const names[] = {"c0", "c1"};
  abi::LawDescriptor d;
  d.name = name;
  d.summary = "test-only law";
  d.dim = D;
  d.n_params = n_params;
  d.param_names = names;
  d.n_moments = Law::n_moments;
  d.n_states = Law::n_states;
  d.damaged = Kernels<Law, D, true>::variant();
  d.intact = Kernels<Law, D, false>::variant();
  return d;
}

// Parameters: c for the springs; A, B for the state law.
inline const abi::LawDescriptor& linear_spring_2d() {
  static const abi::LawDescriptor d = make_descriptor<SpringLaw<2, true>, 2>("test_linear_spring_2d", 1);
  return d;
}
inline const abi::LawDescriptor& spring_2d() {
  static const abi::LawDescriptor d = make_descriptor<SpringLaw<2, false>, 2>("test_spring_2d", 1);
  return d;
}
inline const abi::LawDescriptor& state_law_2d() {
  static const abi::LawDescriptor d = make_descriptor<StateLaw<2>, 2>("test_state_law_2d", 2);
  return d;
}
inline const abi::LawDescriptor& state_law_3d() {
  static const abi::LawDescriptor d = make_descriptor<StateLaw<3>, 3>("test_state_law_3d", 2);
  return d;
}

}  // namespace pd::test

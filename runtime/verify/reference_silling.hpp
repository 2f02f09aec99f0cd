// Silling's dilatation law written out by hand, templated on the scalar type, from
// paper 000 eqs. (2)-(7) (energy-matched plane-strain form, papers/README.md).
// It is the independent implementation the generated kernels are tested against,
// and, instantiated with an automatic-differentiation scalar, the AD baseline that
// the kernel benchmarks compare with (as Peridigm differentiates its elastic models).
#pragma once

#include <cmath>
#include <vector>

namespace pd::verify {

// Nodal forces f[(L+1)*dim] of one family from the deformed positions y[(L+1)*dim]
// (center first). xi, w, alpha, V per bond; K = 3D bulk modulus, G shear modulus.
template <class Scalar>
void silling_forces(int dim, int L, const double* xi, const double* w, const double* alpha, const double* V,
                    double V0, double K, double G, const Scalar* y, Scalar* f) {
  using std::sqrt;
  std::vector<double> r(static_cast<std::size_t>(L));
  std::vector<Scalar> len(static_cast<std::size_t>(L));
  double m = 0;
  Scalar theta(0.0);
  for (int k = 0; k < L; ++k) {
    double r2 = 0;
    Scalar l2(0.0);
    for (int c = 0; c < dim; ++c) {
      r2 += xi[k * dim + c] * xi[k * dim + c];
      const Scalar Yc = y[(k + 1) * dim + c] - y[c];
      l2 += Yc * Yc;
    }
    r[k] = std::sqrt(r2);
    len[k] = sqrt(l2);
    m += w[k] * alpha[k] * r2 * V[k];
  }
  for (int k = 0; k < L; ++k) theta += w[k] * alpha[k] * r[k] * (len[k] - r[k]) * V[k];
  theta *= dim / m;
  for (int i = 0; i < (L + 1) * dim; ++i) f[i] = Scalar(0.0);
  const double bulk = dim == 2 ? K + G / 3 : K;  // plane-strain kappa2 = K + G/3
  const double shear = dim == 2 ? 8 * G : 15 * G;
  for (int k = 0; k < L; ++k) {
    const double wa = w[k] * alpha[k];
    const Scalar e = len[k] - r[k];
    const Scalar t = wa / m * (dim * bulk * theta * r[k] + shear * (e - theta * r[k] / dim));
    for (int c = 0; c < dim; ++c) {
      const Scalar fc = V0 * V[k] * t * (y[(k + 1) * dim + c] - y[c]) / len[k];
      f[c] += fc;
      f[(k + 1) * dim + c] -= fc;
    }
  }
}

}  // namespace pd::verify

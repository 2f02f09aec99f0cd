// Vector and matrix algebra over expressions, written out component by component.
#include "pdgen/tensor.hpp"

#include <stdexcept>

namespace pdgen {

namespace {
void check_same(int a, int b) {
  if (a != b) throw std::logic_error("tensor dimension mismatch");
}
}  // namespace

Vec operator+(const Vec& a, const Vec& b) {
  check_same(a.dim(), b.dim());
  Vec r(a.dim());
  for (int i = 0; i < a.dim(); ++i) r[i] = a[i] + b[i];
  return r;
}
Vec operator-(const Vec& a, const Vec& b) {
  check_same(a.dim(), b.dim());
  Vec r(a.dim());
  for (int i = 0; i < a.dim(); ++i) r[i] = a[i] - b[i];
  return r;
}
Vec operator-(const Vec& a) { return Expr(-1.0) * a; }
Vec operator*(Expr s, const Vec& a) {
  Vec r(a.dim());
  for (int i = 0; i < a.dim(); ++i) r[i] = s * a[i];
  return r;
}
Vec operator*(const Vec& a, Expr s) { return s * a; }
Vec operator/(const Vec& a, Expr s) { return pow(s, -1.0) * a; }
Expr dot(const Vec& a, const Vec& b) {
  check_same(a.dim(), b.dim());
  std::vector<Expr> t;
  for (int i = 0; i < a.dim(); ++i) t.push_back(a[i] * b[i]);
  return add(t);
}
Expr norm(const Vec& a) { return sqrt(dot(a, a)); }
Mat outer(const Vec& a, const Vec& b) {
  check_same(a.dim(), b.dim());
  Mat r(a.dim());
  for (int i = 0; i < a.dim(); ++i)
    for (int j = 0; j < a.dim(); ++j) r(i, j) = a[i] * b[j];
  return r;
}

Mat identity(int dim) {
  Mat r(dim);
  for (int i = 0; i < dim; ++i) r(i, i) = Expr(1.0);
  return r;
}
Mat operator+(const Mat& a, const Mat& b) {
  check_same(a.dim(), b.dim());
  Mat r(a.dim());
  for (int i = 0; i < a.dim(); ++i)
    for (int j = 0; j < a.dim(); ++j) r(i, j) = a(i, j) + b(i, j);
  return r;
}
Mat operator-(const Mat& a, const Mat& b) { return a + Expr(-1.0) * b; }
Mat operator*(Expr s, const Mat& a) {
  Mat r(a.dim());
  for (int i = 0; i < a.dim(); ++i)
    for (int j = 0; j < a.dim(); ++j) r(i, j) = s * a(i, j);
  return r;
}
Mat operator*(const Mat& a, Expr s) { return s * a; }
Mat operator*(const Mat& a, const Mat& b) {
  check_same(a.dim(), b.dim());
  const int d = a.dim();
  Mat r(d);
  for (int i = 0; i < d; ++i)
    for (int j = 0; j < d; ++j) {
      std::vector<Expr> t;
      for (int k = 0; k < d; ++k) t.push_back(a(i, k) * b(k, j));
      r(i, j) = add(t);
    }
  return r;
}
Vec operator*(const Mat& a, const Vec& v) {
  check_same(a.dim(), v.dim());
  Vec r(a.dim());
  for (int i = 0; i < a.dim(); ++i) {
    std::vector<Expr> t;
    for (int k = 0; k < a.dim(); ++k) t.push_back(a(i, k) * v[k]);
    r[i] = add(t);
  }
  return r;
}
Mat transpose(const Mat& a) {
  Mat r(a.dim());
  for (int i = 0; i < a.dim(); ++i)
    for (int j = 0; j < a.dim(); ++j) r(i, j) = a(j, i);
  return r;
}
Expr trace(const Mat& a) {
  std::vector<Expr> t;
  for (int i = 0; i < a.dim(); ++i) t.push_back(a(i, i));
  return add(t);
}
Expr det(const Mat& a) {
  if (a.dim() == 2) return a(0, 0) * a(1, 1) - a(0, 1) * a(1, 0);
  if (a.dim() == 3)
    return a(0, 0) * (a(1, 1) * a(2, 2) - a(1, 2) * a(2, 1)) -
           a(0, 1) * (a(1, 0) * a(2, 2) - a(1, 2) * a(2, 0)) +
           a(0, 2) * (a(1, 0) * a(2, 1) - a(1, 1) * a(2, 0));
  throw std::logic_error("det: dimension must be 2 or 3");
}
Mat inverse(const Mat& a) {
  const Expr inv_det = pow(det(a), -1.0);
  Mat r(a.dim());
  if (a.dim() == 2) {
    r(0, 0) = a(1, 1) * inv_det;
    r(0, 1) = -a(0, 1) * inv_det;
    r(1, 0) = -a(1, 0) * inv_det;
    r(1, 1) = a(0, 0) * inv_det;
    return r;
  }
  if (a.dim() != 3) throw std::logic_error("inverse: dimension must be 2 or 3");
  // Adjugate: cofactor (j, i) of a, with cyclic indices giving the signs.
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const int r1 = (j + 1) % 3, r2 = (j + 2) % 3, c1 = (i + 1) % 3, c2 = (i + 2) % 3;
      r(i, j) = (a(r1, c1) * a(r2, c2) - a(r1, c2) * a(r2, c1)) * inv_det;
    }
  return r;
}
Expr ddot(const Mat& a, const Mat& b) {
  check_same(a.dim(), b.dim());
  std::vector<Expr> t;
  for (int i = 0; i < a.dim(); ++i)
    for (int j = 0; j < a.dim(); ++j) t.push_back(a(i, j) * b(i, j));
  return add(t);
}

}  // namespace pdgen

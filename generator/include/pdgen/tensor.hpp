// Small vectors and matrices of expressions (dimension 2 or 3) and their algebra.
#pragma once

#include <vector>

#include "pdgen/expr.hpp"

namespace pdgen {

class Vec {
 public:
  Vec() = default;
  explicit Vec(int dim) : c_(static_cast<std::size_t>(dim)) {}
  Vec(std::initializer_list<Expr> c) : c_(c) {}
  int dim() const { return static_cast<int>(c_.size()); }
  Expr& operator[](int i) { return c_[static_cast<std::size_t>(i)]; }
  Expr operator[](int i) const { return c_[static_cast<std::size_t>(i)]; }

 private:
  std::vector<Expr> c_;
};

// Row-major dim x dim matrix.
class Mat {
 public:
  Mat() = default;
  explicit Mat(int dim) : dim_(dim), c_(static_cast<std::size_t>(dim * dim)) {}
  int dim() const { return dim_; }
  Expr& operator()(int r, int c) { return c_[static_cast<std::size_t>(r * dim_ + c)]; }
  Expr operator()(int r, int c) const { return c_[static_cast<std::size_t>(r * dim_ + c)]; }

 private:
  int dim_ = 0;
  std::vector<Expr> c_;
};

Vec operator+(const Vec& a, const Vec& b);
Vec operator-(const Vec& a, const Vec& b);
Vec operator-(const Vec& a);
Vec operator*(Expr s, const Vec& a);
Vec operator*(const Vec& a, Expr s);
Vec operator/(const Vec& a, Expr s);
Expr dot(const Vec& a, const Vec& b);
Expr norm(const Vec& a);
Mat outer(const Vec& a, const Vec& b);

Mat identity(int dim);
Mat operator+(const Mat& a, const Mat& b);
Mat operator-(const Mat& a, const Mat& b);
Mat operator*(Expr s, const Mat& a);
Mat operator*(const Mat& a, Expr s);
Mat operator*(const Mat& a, const Mat& b);
Vec operator*(const Mat& a, const Vec& v);
Mat transpose(const Mat& a);
Expr trace(const Mat& a);
Expr det(const Mat& a);
// Inverse by the adjugate; the caller guarantees det != 0 at run time.
Mat inverse(const Mat& a);
// Frobenius product A : B.
Expr ddot(const Mat& a, const Mat& b);

}  // namespace pdgen

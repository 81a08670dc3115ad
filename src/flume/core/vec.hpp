// Small fixed-size vectors and matrices for D-dimensional particle data.
// The space dimension is a compile-time parameter everywhere in flume: 2D and 3D are two
// instantiations of the same code, not two code paths.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>

namespace flume {

template <int D>
struct Vec {
  static_assert(D >= 1 && D <= 3, "flume supports 1, 2 and 3 dimensions");
  std::array<double, D> c{};

  constexpr double& operator[](int k) { return c[static_cast<std::size_t>(k)]; }
  constexpr double operator[](int k) const { return c[static_cast<std::size_t>(k)]; }

  constexpr Vec& operator+=(const Vec& o) {
    for (int k = 0; k < D; ++k)
      (*this)[k] += o[k];
    return *this;
  }
  constexpr Vec& operator-=(const Vec& o) {
    for (int k = 0; k < D; ++k)
      (*this)[k] -= o[k];
    return *this;
  }
  constexpr Vec& operator*=(double s) {
    for (int k = 0; k < D; ++k)
      (*this)[k] *= s;
    return *this;
  }
  friend constexpr Vec operator+(Vec a, const Vec& b) { return a += b; }
  friend constexpr Vec operator-(Vec a, const Vec& b) { return a -= b; }
  friend constexpr Vec operator*(Vec a, double s) { return a *= s; }
  friend constexpr Vec operator*(double s, Vec a) { return a *= s; }
  friend constexpr Vec operator-(Vec a) { return a *= -1.0; }
  friend constexpr bool operator==(const Vec&, const Vec&) = default;
};

template <int D>
constexpr double dot(const Vec<D>& a, const Vec<D>& b) {
  double s = 0.0;
  for (int k = 0; k < D; ++k)
    s += a[k] * b[k];
  return s;
}

template <int D>
constexpr double norm2(const Vec<D>& a) {
  return dot(a, a);
}

template <int D>
inline double norm(const Vec<D>& a) {
  return std::sqrt(norm2(a));
}

// Row-major D x D matrix: m(r, c).
template <int D>
struct Mat {
  std::array<double, static_cast<std::size_t>(D* D)> e{};

  constexpr double& operator()(int r, int c) { return e[static_cast<std::size_t>(r * D + c)]; }
  constexpr double operator()(int r, int c) const { return e[static_cast<std::size_t>(r * D + c)]; }

  static constexpr Mat identity() {
    Mat m;
    for (int k = 0; k < D; ++k)
      m(k, k) = 1.0;
    return m;
  }
  constexpr Mat& operator+=(const Mat& o) {
    for (std::size_t k = 0; k < e.size(); ++k)
      e[k] += o.e[k];
    return *this;
  }
  constexpr Mat& operator-=(const Mat& o) {
    for (std::size_t k = 0; k < e.size(); ++k)
      e[k] -= o.e[k];
    return *this;
  }
  constexpr Mat& operator*=(double s) {
    for (auto& x : e)
      x *= s;
    return *this;
  }
  friend constexpr Mat operator+(Mat a, const Mat& b) { return a += b; }
  friend constexpr Mat operator-(Mat a, const Mat& b) { return a -= b; }
  friend constexpr Mat operator*(Mat a, double s) { return a *= s; }
  friend constexpr Mat operator*(double s, Mat a) { return a *= s; }
  friend constexpr bool operator==(const Mat&, const Mat&) = default;
};

template <int D>
constexpr Vec<D> operator*(const Mat<D>& m, const Vec<D>& v) {
  Vec<D> r;
  for (int i = 0; i < D; ++i)
    for (int j = 0; j < D; ++j)
      r[i] += m(i, j) * v[j];
  return r;
}

template <int D>
constexpr Mat<D> operator*(const Mat<D>& a, const Mat<D>& b) {
  Mat<D> r;
  for (int i = 0; i < D; ++i)
    for (int j = 0; j < D; ++j)
      for (int k = 0; k < D; ++k)
        r(i, j) += a(i, k) * b(k, j);
  return r;
}

template <int D>
constexpr Mat<D> transpose(const Mat<D>& a) {
  Mat<D> r;
  for (int i = 0; i < D; ++i)
    for (int j = 0; j < D; ++j)
      r(i, j) = a(j, i);
  return r;
}

template <int D>
constexpr double trace(const Mat<D>& a) {
  double s = 0.0;
  for (int k = 0; k < D; ++k)
    s += a(k, k);
  return s;
}

// Outer product a (x) b: (a b^T)_{ij} = a_i b_j.
template <int D>
constexpr Mat<D> outer(const Vec<D>& a, const Vec<D>& b) {
  Mat<D> r;
  for (int i = 0; i < D; ++i)
    for (int j = 0; j < D; ++j)
      r(i, j) = a[i] * b[j];
  return r;
}

// Symmetric D x D matrix, its upper triangle stored row by row (D (D + 1) / 2 numbers): what a
// sweep accumulates for a sum of symmetric terms (x (x) x F of a radial kernel's gradient), in
// 3 numbers instead of 4 in 2D, 6 instead of 9 in 3D.
template <int D>
struct SymMat {
  static constexpr std::size_t kSize = static_cast<std::size_t>(D * (D + 1) / 2);
  std::array<double, kSize> e{};

  constexpr SymMat& operator+=(const SymMat& o) {
    for (std::size_t k = 0; k < kSize; ++k)
      e[k] += o.e[k];
    return *this;
  }
  constexpr SymMat& operator-=(const SymMat& o) {
    for (std::size_t k = 0; k < kSize; ++k)
      e[k] -= o.e[k];
    return *this;
  }
  constexpr SymMat& operator*=(double s) {
    for (auto& x : e)
      x *= s;
    return *this;
  }
  friend constexpr SymMat operator*(SymMat a, double s) { return a *= s; }
  // The full matrix.
  constexpr Mat<D> full() const {
    Mat<D> m;
    std::size_t k = 0;
    for (int r = 0; r < D; ++r)
      for (int c = r; c < D; ++c) {
        m(r, c) = e[k];
        m(c, r) = e[k++];
      }
    return m;
  }
};

// a (x) b for parallel a and b (b = a s), which is symmetric: its upper triangle a_r b_c, c >= r.
template <int D>
constexpr SymMat<D> outer_parallel(const Vec<D>& a, const Vec<D>& b) {
  SymMat<D> m;
  std::size_t k = 0;
  for (int r = 0; r < D; ++r)
    for (int c = r; c < D; ++c)
      m.e[k++] = a[r] * b[c];
  return m;
}

// Double contraction a : b.
template <int D>
constexpr double ddot(const Mat<D>& a, const Mat<D>& b) {
  double s = 0.0;
  for (std::size_t k = 0; k < a.e.size(); ++k)
    s += a.e[k] * b.e[k];
  return s;
}

// Out-of-plane (z) component of a x b in 2D; the scalar angular momentum of planar motion.
inline double cross_z(const Vec<2>& a, const Vec<2>& b) {
  return a[0] * b[1] - a[1] * b[0];
}

}  // namespace flume

namespace flume {

template <int D>
constexpr double determinant(const Mat<D>& m) {
  if constexpr (D == 1) {
    return m(0, 0);
  } else if constexpr (D == 2) {
    return m(0, 0) * m(1, 1) - m(0, 1) * m(1, 0);
  } else {
    return m(0, 0) * (m(1, 1) * m(2, 2) - m(1, 2) * m(2, 1)) -
           m(0, 1) * (m(1, 0) * m(2, 2) - m(1, 2) * m(2, 0)) +
           m(0, 2) * (m(1, 0) * m(2, 1) - m(1, 1) * m(2, 0));
  }
}

// Inverse by the adjugate; the caller checks the determinant first.
template <int D>
constexpr Mat<D> inverse(const Mat<D>& m) {
  Mat<D> r;
  const double inv_det = 1.0 / determinant(m);
  if constexpr (D == 1) {
    r(0, 0) = inv_det;
  } else if constexpr (D == 2) {
    r(0, 0) = m(1, 1) * inv_det;
    r(0, 1) = -m(0, 1) * inv_det;
    r(1, 0) = -m(1, 0) * inv_det;
    r(1, 1) = m(0, 0) * inv_det;
  } else {
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        const int i1 = (j + 1) % 3, i2 = (j + 2) % 3, j1 = (i + 1) % 3, j2 = (i + 2) % 3;
        r(i, j) = (m(i1, j1) * m(i2, j2) - m(i1, j2) * m(i2, j1)) * inv_det;
      }
  }
  return r;
}

}  // namespace flume

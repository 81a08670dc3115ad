// The smallest singular value of a small square matrix: sigma_min(M) = sqrt(lambda_min(M^T M)).
// What decides whether a correction matrix can be inverted usefully
// (corrected_velocity_gradient.hpp): unlike the determinant, it does not shrink with the dimension
// (a 2D corner and a 3D corner both have sigma_min ~ 1/2, their determinants 1/4 and 1/8), and it
// measures how close M is to the nearest singular matrix (Eckart-Young), which a determinant does
// not.
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>

#include "flume/core/vec.hpp"

namespace flume {

// The eigenvalues of a symmetric matrix A, smallest first (closed forms: the quadratic in 2D,
// the trigonometric solution of the characteristic cubic in 3D).
template <int D>
double smallest_symmetric_eigenvalue(const Mat<D>& a) {
  if constexpr (D == 1) {
    return a(0, 0);
  } else if constexpr (D == 2) {
    const double mean = 0.5 * (a(0, 0) + a(1, 1));
    const double half_diff = 0.5 * (a(0, 0) - a(1, 1));
    // sqrt(x^2 + y^2), not std::hypot: a library call per particle (3 % of a CSPH step), whose
    // guard against overflow the moment matrices (entries ~1, or ~h^2 in BL (47)) do not need;
    // an overflowing matrix gives -inf here, and so sigma_min = 0: the correction is dropped.
    return mean - std::sqrt(half_diff * half_diff + a(0, 1) * a(0, 1));
  } else {
    // A = q I + p B with q = tr A / 3 and B of unit "radius": the eigenvalues are
    // q + 2 p cos(phi + 2 pi k / 3), phi = acos(det B / 2) / 3; the smallest has k = 1.
    const double q = trace(a) / 3.0;
    const double off = a(0, 1) * a(0, 1) + a(0, 2) * a(0, 2) + a(1, 2) * a(1, 2);
    const double d0 = a(0, 0) - q, d1 = a(1, 1) - q, d2 = a(2, 2) - q;
    const double p2 = (d0 * d0 + d1 * d1 + d2 * d2 + 2.0 * off) / 6.0;
    if (p2 <= 0.0) return q;  // a multiple of the identity
    const double p = std::sqrt(p2);
    Mat<3> b = a;
    for (int k = 0; k < 3; ++k)
      b(k, k) -= q;
    b *= 1.0 / p;
    const double r = std::clamp(0.5 * determinant(b), -1.0, 1.0);
    const double phi = std::acos(r) / 3.0;
    return q + 2.0 * p * std::cos(phi + 2.0 * std::numbers::pi / 3.0);
  }
}

template <int D>
double smallest_singular_value(const Mat<D>& m) {
  return std::sqrt(std::max(0.0, smallest_symmetric_eigenvalue(transpose(m) * m)));
}

// Whether sigma_min(M) >= s, for s > 0: smallest_singular_value(M) >= s, in 2D without a square
// root. There sigma_1^2 and sigma_2^2 are the roots of t^2 - |M|_F^2 t + det(M)^2 (their sum
// |M|_F^2, their product det(M)^2), and s^2 lies at or below the smaller one exactly when the
// quadratic is >= 0 at s^2 and s^2 is at most the roots' mean |M|_F^2 / 2. The decision of every
// correction sweep's finish (corrected_velocity_gradient.hpp): M^T M and two square roots there
// were 7 % of CSPH's correction sweep (flume_bench, perf).
template <int D>
bool singular_value_at_least(const Mat<D>& m, double s) {
  if constexpr (D == 2) {
    const double f = ddot(m, m);  // |M|_F^2
    const double det = determinant(m);
    const double s2 = s * s;
    return 2.0 * s2 <= f && s2 * s2 - f * s2 + det * det >= 0.0;
  } else {
    return smallest_singular_value(m) >= s;
  }
}

}  // namespace flume

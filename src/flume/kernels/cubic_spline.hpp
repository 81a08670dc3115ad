// Cubic B-spline kernel, W (2.19)-(2.20), support 2h (W's eps is our h):
//   W(r, h) = C(n) / h^n * { 1 - 3/2 q^2 + 3/4 q^3   for 0 <= q <= 1,
//                          { 1/4 (2 - q)^3           for 1 <  q <= 2,     q = r / h,
//                          { 0                       for q > 2,
//   C(n) = 2/3, 10/(7 pi), 1/pi for n = 1, 2, 3.
// It is evaluated as the sum of truncated powers 1/4 (2 - q)_+^3 - (1 - q)_+^3, which is the
// same polynomial on q <= 1, so the inner loop has no branch on the piece.
#pragma once

#include <algorithm>
#include <numbers>
#include <string_view>

namespace flume {

template <int D>
struct CubicSpline {
  static_assert(D >= 1 && D <= 3, "flume supports 1, 2 and 3 dimensions");
  static constexpr double support = 2.0;  // radius in units of h
  static constexpr std::string_view name = "cubic_spline";
  // C(n), W (2.20).
  static constexpr double norm = D == 1   ? 2.0 / 3.0
                                 : D == 2 ? 10.0 / (7.0 * std::numbers::pi)
                                          : 1.0 / std::numbers::pi;

  // W in 1/m^D.
  static double w(double r, double h) noexcept {
    double v = 0.0, factor = 0.0;
    inside(r, h, v, factor);
    // The cut on r itself (not on the rounded q) makes W exactly 0 at r = support * h.
    return r < support * h ? v : 0.0;
  }

  // dW/dr in 1/m^(D+1).
  static double dwdr(double r, double h) noexcept {
    const double ih = 1.0 / h;
    const double q = r * ih;
    const double a = std::max(0.0, 2.0 - q);
    const double b = std::max(0.0, 1.0 - q);
    const double v = norm * inv_hd(ih) * ih * (3.0 * b * b - 0.75 * a * a);
    return r < support * h ? v : 0.0;
  }

  // (1/r) dW/dr in 1/m^(D+2), finite at r = 0 (grad W = x_ij * gradient_factor, no division by
  // r): the derivative above divided by q is -3 + 9/4 q on q < 1 and -3/4 (2 - q)^2 / q beyond.
  static double gradient_factor(double r, double h) noexcept {
    double w = 0.0, v = 0.0;
    inside(r, h, w, v);
    return r < support * h ? v : 0.0;
  }

  // W and the gradient factor together, the formulas above, without the cut: w() and
  // gradient_factor() are these cut at r = support * h; the pair loop calls this (its mask is
  // the cut, sweep.hpp), so that its vectorised loop finds q and the powers once for both.
  static void inside(double r, double h, double& w, double& factor) noexcept {
    const double ih = 1.0 / h;
    const double q = r * ih;
    const double a = std::max(0.0, 2.0 - q);
    const double b = std::max(0.0, 1.0 - q);
    w = norm * inv_hd(ih) * (0.25 * a * a * a - b * b * b);
    const double inner = -3.0 + 2.25 * q;
    const double outer = -0.75 * a * a / std::max(q, 1.0);
    factor = norm * inv_hd(ih) * ih * ih * (q < 1.0 ? inner : outer);
  }

 private:
  static constexpr double inv_hd(double ih) {
    return D == 1 ? ih : D == 2 ? ih * ih : ih * ih * ih;
  }
};

}  // namespace flume

// Quintic spline kernel, W (2.21) (Morris 1996), support 3h (W's eps is our h):
//   W(r, h) = C(n) / h^n * { (3 - q)^5 - 6 (2 - q)^5 + 15 (1 - q)^5   for 0 <= q <= 1,
//                          { (3 - q)^5 - 6 (2 - q)^5                  for 1 <  q <= 2,
//                          { (3 - q)^5                                for 2 <  q <= 3,
//                          { 0                                        for q > 3,    q = r / h.
// C(n) is the quintic's own, not the cubic's C(n) of W (2.20) (spec/errata.md):
//   C(n) = 1/120, 7/(478 pi), 1/(120 pi) for n = 1, 2, 3.
// The pieces are truncated powers (k - q)_+^5, so the inner loop has no branch on the piece.
#pragma once

#include <algorithm>
#include <numbers>
#include <string_view>

namespace flume {

template <int D>
struct QuinticSpline {
  static_assert(D >= 1 && D <= 3, "flume supports 1, 2 and 3 dimensions");
  static constexpr double support = 3.0;  // radius in units of h
  static constexpr std::string_view name = "quintic_spline";
  static constexpr double norm = D == 1   ? 1.0 / 120.0
                                 : D == 2 ? 7.0 / (478.0 * std::numbers::pi)
                                          : 1.0 / (120.0 * std::numbers::pi);

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
    const double a = std::max(0.0, 3.0 - q);
    const double b = std::max(0.0, 2.0 - q);
    const double c = std::max(0.0, 1.0 - q);
    const double a2 = a * a, b2 = b * b, c2 = c * c;
    const double v = -5.0 * norm * inv_hd(ih) * ih * (a2 * a2 - 6.0 * b2 * b2 + 15.0 * c2 * c2);
    return r < support * h ? v : 0.0;
  }

  // (1/r) dW/dr in 1/m^(D+2), finite at r = 0 (grad W = x_ij * gradient_factor, no division by
  // r). On q < 1 the bracket of dwdr is 24 q - 24 q^3 + 10 q^4 (the constants cancel), so it
  // divides by q exactly; beyond, c = 0 and q >= 1.
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
    const double a = std::max(0.0, 3.0 - q);
    const double b = std::max(0.0, 2.0 - q);
    const double c = std::max(0.0, 1.0 - q);
    const double a2 = a * a, b2 = b * b, c2 = c * c;
    w = norm * inv_hd(ih) * (a2 * a2 * a - 6.0 * b2 * b2 * b + 15.0 * c2 * c2 * c);
    const double inner = 24.0 + q * q * (-24.0 + 10.0 * q);
    const double outer = (a2 * a2 - 6.0 * b2 * b2) / std::max(q, 1.0);
    factor = -5.0 * norm * inv_hd(ih) * ih * ih * (q < 1.0 ? inner : outer);
  }

 private:
  static constexpr double inv_hd(double ih) {
    return D == 1 ? ih : D == 2 ? ih * ih : ih * ih * ih;
  }
};

}  // namespace flume

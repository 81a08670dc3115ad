// Wendland C2 kernel (Wendland 1995; Dehnen & Aly 2012), support 2h, q = r / h. Not in the
// source documents: it is the modern default because, unlike the B-splines, it does not suffer
// the pairing instability (its Fourier transform is positive).
//   2D, 3D: W(r, h) = alpha (1 - q/2)^4 (2q + 1),  alpha = 7 / (4 pi h^2), 21 / (16 pi h^3),
//   1D:     W(r, h) = 5 / (8h) (1 - q/2)^3 (3/2 q + 1)   (the C2 function of the line),
// and 0 for q > 2.
#pragma once

#include <algorithm>
#include <numbers>
#include <string_view>

namespace flume {

template <int D>
struct WendlandC2 {
  static_assert(D >= 1 && D <= 3, "flume supports 1, 2 and 3 dimensions");
  static constexpr double support = 2.0;  // radius in units of h
  static constexpr std::string_view name = "wendland_c2";
  static constexpr double norm = D == 1   ? 5.0 / 8.0
                                 : D == 2 ? 7.0 / (4.0 * std::numbers::pi)
                                          : 21.0 / (16.0 * std::numbers::pi);

  // W in 1/m^D.
  static double w(double r, double h) noexcept {
    double v = 0.0, factor = 0.0;
    inside(r, h, v, factor);
    // The cut on r itself (not on the rounded q) makes W exactly 0 at r = support * h.
    return r < support * h ? v : 0.0;
  }

  // dW/dr in 1/m^(D+1): d/dq gives -3 q (1 - q/2)^2 (1D) and -5 q (1 - q/2)^3 (2D, 3D), which is
  // r times the gradient factor below.
  static double dwdr(double r, double h) noexcept { return r * gradient_factor(r, h); }

  // (1/r) dW/dr in 1/m^(D+2), finite at r = 0, so that grad W = x_ij * gradient_factor needs no
  // division by r: -3 (1 - q/2)^2 / h^2 (1D) and -5 (1 - q/2)^3 / h^2 (2D, 3D) times norm / h^D.
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
    const double t = std::max(0.0, 1.0 - 0.5 * q);
    const double t2 = t * t;
    if constexpr (D == 1) {
      w = norm * ih * t2 * t * (1.5 * q + 1.0);
      factor = -3.0 * norm * ih * ih * ih * t2;
    } else {
      w = norm * inv_hd(ih) * t2 * t2 * (2.0 * q + 1.0);
      factor = -5.0 * norm * inv_hd(ih) * ih * ih * t2 * t;
    }
  }

 private:
  static constexpr double inv_hd(double ih) {
    return D == 1 ? ih : D == 2 ? ih * ih : ih * ih * ih;
  }
};

}  // namespace flume

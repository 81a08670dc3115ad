// Truncated Gaussian kernel: W (2.18) with its support eps = 3h and shape constant a = 1/3, so
// that exp(-|x / (a eps)|^2) = exp(-q^2), generalised to n dimensions and renormalised over the
// truncation:
//   W(r, h) = exp(-q^2) / (N_n h^n)  for r < 3h,  0 beyond,  q = r / h,
// where N_n is the exact integral of exp(-|q|^2) over the n-ball of radius 3, so the truncated
// kernel integrates to exactly 1 (W (2.18)'s 1 / (a eps sqrt(pi)) is the untruncated 1D one):
//   N_1 = sqrt(pi) erf(3),  N_2 = pi (1 - exp(-9)),  N_3 = pi^(3/2) erf(3) - 6 pi exp(-9).
// W jumps by exp(-9) / N_n (about 1e-4 of its peak) at the truncation; that is the price of a
// Gaussian with compact support.
#pragma once

#include <cmath>
#include <numbers>
#include <string_view>

namespace flume {

namespace gaussian_detail {
// std::erf and std::exp are not constexpr; these are correctly rounded (checked by the tests).
inline constexpr double kErf3 = 0.99997790950300141455862722387;
inline constexpr double kExpM9 = 1.2340980408667954949763669073e-4;
inline constexpr double kPi = std::numbers::pi;
inline constexpr double kSqrtPi = 1.7724538509055160272981674833;
// N_n, the integral of exp(-|q|^2) over the n-ball of radius 3.
inline constexpr double kN1 = kSqrtPi * kErf3;
inline constexpr double kN2 = kPi * (1.0 - kExpM9);
inline constexpr double kN3 = kPi * kSqrtPi * kErf3 - 6.0 * kPi * kExpM9;
}  // namespace gaussian_detail

template <int D>
struct Gaussian {
  static_assert(D >= 1 && D <= 3, "flume supports 1, 2 and 3 dimensions");
  static constexpr double support = 3.0;  // radius in units of h
  static constexpr std::string_view name = "gaussian";
  static constexpr double norm =  // 1 / N_n
      1.0 / (D == 1   ? gaussian_detail::kN1
             : D == 2 ? gaussian_detail::kN2
                      : gaussian_detail::kN3);

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
    const double v = -2.0 * q * norm * inv_hd(ih) * ih * std::exp(-q * q);
    return r < support * h ? v : 0.0;
  }

  // (1/r) dW/dr in 1/m^(D+2), finite at r = 0 (grad W = x_ij * gradient_factor).
  static double gradient_factor(double r, double h) noexcept {
    double w = 0.0, v = 0.0;
    inside(r, h, w, v);
    return r < support * h ? v : 0.0;
  }

  // W and the gradient factor together, the formulas above, without the cut: w() and
  // gradient_factor() are these cut at r = support * h; the pair loop calls this (its mask is
  // the cut, sweep.hpp), so that its vectorised loop finds q and the exponential once for both.
  static void inside(double r, double h, double& w, double& factor) noexcept {
    const double ih = 1.0 / h;
    const double q = r * ih;
    const double e = std::exp(-q * q);
    w = norm * inv_hd(ih) * e;
    factor = -2.0 * norm * inv_hd(ih) * ih * ih * e;
  }

 private:
  static constexpr double inv_hd(double ih) {
    return D == 1 ? ih : D == 2 ? ih * ih : ih * ih * ih;
  }
};

}  // namespace flume

// Reference solution of the moving bore (hydraulic jump), BL section 5.4, Fig 12: a layer of
// depth h0 moving at v0 toward a rigid vertical wall is brought to rest there; the still water
// of depth h behind the jump grows as the bore runs away from the wall at speed v_s (both speeds
// positive, measured in the wall's frame; v0 toward the wall, v_s away from it).
//   BL (67): v_s = -v0 + sqrt(g h (1 + h / h0) / 2)   (momentum across the jump)
//   BL (68): h / h0 = (v_s + v0) / v_s                 (mass across the jump)
// In the frame of the jump the incoming layer has speed v_s + v0 and the still water speed v_s;
// BL (67) is the classical jump relation (v_s + v0)^2 = g h (h + h0) / (2 h0) written for v_s.
//
// Solution: BL (68) gives v_s = v0 h0 / (h - h0). With d = h - h0 > 0, BL (67) becomes
//   f(d) = v0 (h0 + d) / d - sqrt(g (h0 + d) (2 h0 + d) / (2 h0)) = 0.
// For v0 > 0 the first term falls from +inf (d -> 0+) to v0 (d -> inf) and the second rises
// without bound, so f is strictly decreasing with exactly one root. It is bracketed by doubling
// and bisected until the bracket is two adjacent doubles. Working in d rather than h keeps the
// relative precision of the (small, for low Froude) jump height d, and so of v_s.
#pragma once

#include <cmath>
#include <stdexcept>

namespace flume {

struct BoreSolution {
  double h = 0.0;    // depth behind the bore (at the wall), m
  double v_s = 0.0;  // bore speed away from the wall, m/s
};

// Froude number of the incoming layer, Fr = v0 / sqrt(g h0) (BL 5.4 quotes 0.3 and 0.9).
inline double bore_froude(double h0, double v0, double g) {
  return v0 / std::sqrt(g * h0);
}

// Solves BL (67)-(68) for (h, v_s) given the layer depth h0 (m), its speed toward the wall
// v0 >= 0 (m/s) and gravity g > 0 (m/s^2). v0 = 0 gives the limit of a vanishing jump,
// h = h0 and v_s = sqrt(g h0) (a small wave). Throws std::invalid_argument otherwise.
inline BoreSolution bore_solution(double h0, double v0, double g) {
  if (!(h0 > 0.0) || !std::isfinite(h0) || !(g > 0.0) || !std::isfinite(g)) {
    throw std::invalid_argument("bore_solution: h0 and g must be positive and finite");
  }
  if (!(v0 >= 0.0) || !std::isfinite(v0)) {
    // v0 < 0 (layer moving away from the wall) has no jump with h > h0.
    throw std::invalid_argument("bore_solution: v0 must be finite and >= 0");
  }
  if (v0 == 0.0) return {h0, std::sqrt(g * h0)};

  // f(d) > 0 means d is below the root.
  const auto f = [h0, v0, g](double d) {
    return v0 * (h0 + d) / d - std::sqrt(g * (h0 + d) * (2.0 * h0 + d) / (2.0 * h0));
  };
  // Bracket [lo, hi] with f(lo) > 0 >= f(hi). lo starts at the smallest positive double, where
  // the first term is huge (f > 0 for any finite v0 > 0, g, h0 of physical size).
  double lo = 0.0;
  double hi = h0;
  while (f(hi) > 0.0) {
    lo = hi;
    hi *= 2.0;
    if (!std::isfinite(hi)) throw std::runtime_error("bore_solution: no bracket found");
  }
  if (lo == 0.0) {
    // Shrink lo toward 0 until f(lo) > 0 (reached quickly: f ~ v0 h0 / d as d -> 0).
    lo = hi;
    do {
      lo *= 0.5;
    } while (lo > 0.0 && !(f(lo) > 0.0));
    if (!(lo > 0.0)) throw std::runtime_error("bore_solution: no bracket found");
  }
  // Bisection to full double precision: stop when the midpoint is no longer strictly inside.
  for (;;) {
    const double mid = 0.5 * (lo + hi);
    if (!(mid > lo && mid < hi)) break;
    if (f(mid) > 0.0) {
      lo = mid;
    } else {
      hi = mid;
    }
  }
  // Of the two adjacent bracket ends take the one with the smaller residual.
  const double d = std::abs(f(lo)) < std::abs(f(hi)) ? lo : hi;
  return {h0 + d, v0 * h0 / d};  // v_s from BL (68)
}

}  // namespace flume

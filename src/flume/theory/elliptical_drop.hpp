// Reference solution of the stretching elliptical water drop, BL section 5.2 (Monaghan's test):
// an inviscid incompressible drop with no body force, a circle of radius R0 at t = 0, whose
// velocity field stays linear, u = -A(t) x, v = A(t) y. The drop stays an ellipse with semi-axes
// a (along x) and b (along y) and
//   db/dt = A b,   da/dt = -A a              (the boundary moves with the flow)
//   dA/dt = A^2 (a^2 - b^2) / (a^2 + b^2)    (momentum, pressure eliminated; see below)
//   a b = R0^2,  a(0) = b(0) = R0,  A(0) = A0.
// BL (65) writes the same system with B = -A and w = a b: db/dt = -b B,
// dB/dt = B^2 (b^4 - w^4) / (b^4 + w^4); substituting a = w / b turns one into the other.
//
// Why dA/dt holds for any R0 (BL state it for the unit circle only): the pressure that keeps the
// linear field is p = P(t) (1 - x^2/a^2 - y^2/b^2) (zero on the free surface). Euler's equation
// then reads (-A' + A^2) x = 2 P x / (rho a^2) and (A' + A^2) y = 2 P y / (rho b^2); eliminating
// P gives A' (a^2 + b^2) = A^2 (a^2 - b^2). Only the ratio (a^2 - b^2)/(a^2 + b^2) and b'/b
// appear, so scaling lengths by R0 leaves the system unchanged: b(t; A0, R0) = R0 b(t; A0, 1).
//
// The system has no closed form, so it is integrated here with classical RK4 at a step far below
// what its truncation error needs: kStepsPerUnit steps per unit of |A0 t|. |A| never exceeds
// |A0| starting from the circle (A' has the sign that shrinks |A| as the drop elongates), so
// |A0| bounds every rate of the system. At 20000 steps per unit the RK4 truncation error,
// ~(1/20000)^4 per unit, is ~1e-17, and the result is limited by round-off (~1e-14 relative).
//
// semi_axes_from_moments() measures a and b of a particle cloud for comparison with the above.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <span>
#include <stdexcept>
#include <vector>

namespace flume {

struct EllipticalDropState {
  double t = 0.0;  // time since the drop was a circle, s
  double a = 0.0;  // semi-axis along x, m
  double b = 0.0;  // semi-axis along y, m (BL's "b", the growing one for A0 > 0)
  double A = 0.0;  // velocity-gradient amplitude, 1/s: u = -A x, v = A y
};

namespace elliptical_drop_detail {

// RK4 steps per unit of |A0| * |t|; see the header comment for why this is converged.
inline constexpr double kStepsPerUnit = 20000.0;
// Floor so that tiny intervals still take a few steps (harmless, they are cheap).
inline constexpr long kMinSteps = 16;

inline long steps_for(double A0, double dt) {
  const double n = std::ceil(kStepsPerUnit * std::abs(A0 * dt));
  return std::max(kMinSteps, static_cast<long>(n));
}

// Advances (b, A) by dt in n RK4 steps with a b = w fixed (a = w / b).
// Integrates b, not a: b stays >= its initial value for A > 0, so a = w / b is well-conditioned.
inline void rk4_advance(double& b, double& A, double w, double dt, long n) {
  // Right-hand side of the system in the header comment, with a = w / b.
  const auto rhs = [w](double bb, double AA, double& db, double& dA) {
    const double a = w / bb;
    const double a2 = a * a;
    const double b2 = bb * bb;
    db = AA * bb;
    dA = AA * AA * (a2 - b2) / (a2 + b2);
  };
  const double h = dt / static_cast<double>(n);
  for (long i = 0; i < n; ++i) {
    double k1b = 0.0, k1A = 0.0, k2b = 0.0, k2A = 0.0;
    double k3b = 0.0, k3A = 0.0, k4b = 0.0, k4A = 0.0;
    rhs(b, A, k1b, k1A);
    rhs(b + 0.5 * h * k1b, A + 0.5 * h * k1A, k2b, k2A);
    rhs(b + 0.5 * h * k2b, A + 0.5 * h * k2A, k3b, k3A);
    rhs(b + h * k3b, A + h * k3A, k4b, k4A);
    b += h / 6.0 * (k1b + 2.0 * k2b + 2.0 * k3b + k4b);
    A += h / 6.0 * (k1A + 2.0 * k2A + 2.0 * k3A + k4A);
  }
}

inline void check_inputs(double A0, double R0, double t) {
  if (!(R0 > 0.0) || !std::isfinite(R0)) {
    throw std::invalid_argument("elliptical drop: R0 must be positive and finite");
  }
  if (!std::isfinite(A0) || !std::isfinite(t)) {
    throw std::invalid_argument("elliptical drop: A0 and t must be finite");
  }
}

}  // namespace elliptical_drop_detail

// The drop at time t, integrated from the circle of radius R0 with exactly n_steps RK4 steps.
// Exposed so that tests can check the step convergence; use elliptical_drop_exact() otherwise.
inline EllipticalDropState elliptical_drop_rk4(double A0, double R0, double t, long n_steps) {
  elliptical_drop_detail::check_inputs(A0, R0, t);
  if (n_steps < 1) throw std::invalid_argument("elliptical drop: n_steps must be >= 1");
  const double w = R0 * R0;
  double b = R0;
  double A = A0;
  elliptical_drop_detail::rk4_advance(b, A, w, t, n_steps);
  return {t, w / b, b, A};
}

// The converged ("exact") incompressible solution at time t (t < 0 integrates backwards).
inline EllipticalDropState elliptical_drop_exact(double A0, double R0, double t) {
  return elliptical_drop_rk4(A0, R0, t, elliptical_drop_detail::steps_for(A0, t));
}

// The solution at t_k = k t_end / n_intervals, k = 0..n_intervals, integrated continuously
// (each interval at the same step density as elliptical_drop_exact()).
inline std::vector<EllipticalDropState> elliptical_drop_series(double A0, double R0, double t_end,
                                                               int n_intervals) {
  elliptical_drop_detail::check_inputs(A0, R0, t_end);
  if (n_intervals < 1) throw std::invalid_argument("elliptical drop: n_intervals must be >= 1");
  const double w = R0 * R0;
  double b = R0;
  double A = A0;
  std::vector<EllipticalDropState> out;
  out.reserve(static_cast<std::size_t>(n_intervals) + 1);
  out.push_back({0.0, R0, R0, A0});
  double t_prev = 0.0;
  for (int k = 1; k <= n_intervals; ++k) {
    // t_k computed from k, not by accumulation, so the last sample lands exactly on t_end.
    const double t_k = t_end * static_cast<double>(k) / static_cast<double>(n_intervals);
    const double dt = t_k - t_prev;
    elliptical_drop_detail::rk4_advance(b, A, w, dt, elliptical_drop_detail::steps_for(A0, dt));
    out.push_back({t_k, w / b, b, A});
    t_prev = t_k;
  }
  return out;
}

// Semi-axes {a, b} (along x, along y) of a particle cloud that fills an axis-aligned ellipse,
// from its mass-weighted second moments about its mass-weighted centre:
//   a = 2 sqrt(<(x - xc)^2>),  b = 2 sqrt(<(y - yc)^2>).
// Derivation: for a uniform filled ellipse, map x = a r cos(th), y = b r sin(th), whose area
// element is a b r dr dth. Then
//   integral of x^2 dA = a^3 b * int_0^1 r^3 dr * int_0^{2 pi} cos^2(th) dth = a^3 b (1/4) pi,
// and the area is pi a b, so the area-weighted mean <x^2> = a^2 / 4 (likewise <y^2> = b^2 / 4).
// Equal-volume particles of uniform density carry mass proportional to area, hence the masses
// as weights. The moments are about x and y, so the ellipse must not be rotated (the drop's
// axes stay on x and y because its velocity field has no rotation).
inline std::array<double, 2> semi_axes_from_moments(std::span<const double> x,
                                                    std::span<const double> y,
                                                    std::span<const double> weights) {
  if (x.size() != y.size() || x.size() != weights.size()) {
    throw std::invalid_argument("semi_axes_from_moments: x, y and weights differ in size");
  }
  double m = 0.0, mx = 0.0, my = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    m += weights[i];
    mx += weights[i] * x[i];
    my += weights[i] * y[i];
  }
  if (!(m > 0.0)) throw std::invalid_argument("semi_axes_from_moments: total weight must be > 0");
  const double xc = mx / m;
  const double yc = my / m;
  // Second pass about the centre (not <x^2> - xc^2), so an offset cloud loses no digits.
  double sxx = 0.0, syy = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double dx = x[i] - xc;
    const double dy = y[i] - yc;
    sxx += weights[i] * dx * dx;
    syy += weights[i] * dy * dy;
  }
  return {2.0 * std::sqrt(sxx / m), 2.0 * std::sqrt(syy / m)};
}

}  // namespace flume

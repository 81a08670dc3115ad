// Solitary waves on water of depth H (W 6.4.1): the KdV solitary wave W (6.15)-(6.17),
//   eta(x, t) = A sech^2((x - V t) / lambda),  V = sqrt(g H) (1 + A / (2 H)),
//   lambda = sqrt(4 H^3 / (3 A)),
// the amplitude W (6.23) of the wave that all the water of the mound y = B exp(-k x) + H
// (W (6.21)) would make, A = (3 / H^3) (B / (4 k))^2 (W (6.22): the mound's area equals the
// wave's, see mound_amplitude), the stability limit at constant depth
// A / H < 0.78 (W (6.18)), and Grilli's breaking criterion on a plane slope s, A / H > 16.9 s^2
// (W (6.19)), with the breaker type from S0 = 1.521 s / sqrt(A / H) (W (6.20), Table 6.2).
#pragma once

#include <cmath>
#include <string>

namespace flume {

// W (6.16): the speed of a solitary wave of amplitude A on depth H.
inline double kdv_speed(double amplitude, double depth, double g) {
  return std::sqrt(g * depth) * (1.0 + amplitude / (2.0 * depth));
}

// W (6.16) solved for A: the amplitude of the solitary wave that travels at `speed`.
inline double kdv_amplitude(double speed, double depth, double g) {
  return 2.0 * depth * (speed / std::sqrt(g * depth) - 1.0);
}

// W (6.17): the width, the distance from the crest at which eta = sech^2(1) A = 0.42 A.
inline double kdv_width(double amplitude, double depth) {
  return std::sqrt(4.0 * depth * depth * depth / (3.0 * amplitude));
}

// W (6.15) at distance s from the crest.
inline double kdv_elevation(double amplitude, double depth, double s) {
  const double c = std::cosh(s / kdv_width(amplitude, depth));
  return amplitude / (c * c);
}

// The water under W (6.15)'s wave travelling toward +x, at distance s from the crest and height
// z above the bed, in the shallow-water form that keeps the KdV profile unchanged: a horizontal
// velocity uniform over the depth whose flux carries the wave, u (H + eta) = V eta (seen from
// the crest moving at V the flux (u - V)(H + eta) is -V H everywhere), and the vertical velocity
// that continuity then requires, w = -z du/dx (zero at the bed). At the surface this is the
// kinematic condition of a permanent wave, w = (u - V) d eta / dx. m/s
struct KdvVelocity {
  double u = 0.0;
  double w = 0.0;
};
inline KdvVelocity kdv_velocity(double amplitude, double depth, double g, double s, double z) {
  const double v = kdv_speed(amplitude, depth, g);
  const double lambda = kdv_width(amplitude, depth);
  const double eta = kdv_elevation(amplitude, depth, s);
  const double deta_dx = -2.0 * eta * std::tanh(s / lambda) / lambda;
  const double column = depth + eta;
  const double du_dx = v * depth / (column * column) * deta_dx;
  return {v * eta / column, -z * du_dx};
}

// W (6.23): all the water above H in W (6.21)'s mound made into one solitary wave. The mound
// holds B / k per unit width; the wave holds the integral of A sech^2(x / lambda), 2 A lambda;
// 2 A sqrt(4 H^3 / (3 A)) = B / k gives A = (3 / H^3) (B / (4 k))^2.
inline double mound_amplitude(double b, double k, double depth) {
  const double q = b / (4.0 * k);
  return 3.0 / (depth * depth * depth) * q * q;
}

// W (6.19) and Table 6.2 (Grilli et al. 1997): whether a solitary wave of relative amplitude
// A / H breaks on a plane slope s, and how.
inline bool grilli_breaks(double relative_amplitude, double slope) {
  return relative_amplitude > 16.9 * slope * slope;
}
inline double grilli_s0(double relative_amplitude, double slope) {
  return 1.521 * slope / std::sqrt(relative_amplitude);
}
inline std::string grilli_breaker_type(double relative_amplitude, double slope) {
  const double s0 = grilli_s0(relative_amplitude, slope);
  if (!grilli_breaks(relative_amplitude, slope)) return "none";
  if (s0 < 0.025) return "spilling";
  if (s0 < 0.30) return "plunging";
  if (s0 < 0.37) return "surging";
  return "none";  // beyond Table 6.2: a non-breaking reflection
}

}  // namespace flume

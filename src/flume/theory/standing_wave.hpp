// The standing waves of a closed rectangular tank (linear water-wave theory, free-slip walls):
// water of still depth H in a tank of length L sloshes in the modes
//   eta_n = a cos(k_n x) cos(omega_n t),  k_n = n pi / L,
// with the linear dispersion relation omega_n^2 = g k_n tanh(k_n H), so the n-th mode's period
// is T_n = 2 pi / sqrt(g k_n tanh(k_n H)). Not in BL or W: flume's check that a scheme carries a
// free-surface gravity wave at the right speed (the dispersion relation that the solitary waves
// of W 6.4 obey in their long-wave limit), free of the dam break's and the bore's friction and
// breaking. The amplitude shifts the period by O((a k)^2 / (k H)^3) (Tadjbakhsh & Keller 1960),
// under 0.5 % for a / H < 0.1 at k H > 0.5.
#pragma once

#include <cmath>
#include <numbers>

namespace flume {

// T_n = 2 pi / sqrt(g k tanh(k H)), k = n pi / L: the period of mode n (s).
inline double standing_wave_period(int mode, double length, double depth, double g) {
  const double k = mode * std::numbers::pi / length;
  return 2.0 * std::numbers::pi / std::sqrt(g * k * std::tanh(k * depth));
}

}  // namespace flume

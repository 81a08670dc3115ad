// Ideal (polytropic) gas, the equation of state of W's shock tube (W 4.2, methods.md):
//   p = (gamma - 1) rho e,   c = sqrt(gamma p / rho),
// e the specific internal energy, J/kg, which the gas schemes evolve (W (3.52), (3.81)).
#pragma once

#include <cmath>

namespace flume {

struct IdealGasEos {
  double gamma = 1.4;  // ratio of specific heats, -

  double pressure(double rho, double e) const { return (gamma - 1.0) * rho * e; }
  // c^2 = (dp/drho) at constant entropy = gamma p / rho.
  double sound_speed(double rho, double p) const { return std::sqrt(gamma * p / rho); }
};

}  // namespace flume

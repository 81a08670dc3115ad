// A prescribed motion of a wall along its own normal: the bore's push wall (BL 5.4, a constant
// velocity) and a piston wave-maker (a sinusoid about the rest position; the piston part of W's
// paddle W (6.9)). The wall's displacement from its position at t = 0 is
//   s(t) = u t + A sin(2 pi t / T),   its velocity u_w(t) = u + A (2 pi / T) cos(2 pi t / T).
// Both are exact functions of time (no integration), so a resumed or restarted run finds the
// wall where an uninterrupted one would.
#pragma once

#include <cmath>
#include <numbers>

namespace flume {

struct WallMotion {
  double velocity = 0.0;   // u, m/s, along the axis (positive = towards +axis)
  double amplitude = 0.0;  // A, m
  double period = 0.0;     // T, s (used when amplitude != 0)

  bool moves() const { return velocity != 0.0 || amplitude != 0.0; }

  double displacement(double t) const {
    double s = velocity * t;
    if (amplitude != 0.0) s += amplitude * std::sin(2.0 * std::numbers::pi * t / period);
    return s;
  }

  double speed(double t) const {
    double u = velocity;
    if (amplitude != 0.0) {
      const double w = 2.0 * std::numbers::pi / period;
      u += amplitude * w * std::cos(w * t);
    }
    return u;
  }
};

}  // namespace flume

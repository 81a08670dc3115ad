// The piston-flap paddle of Dalrymple & Rogers, W (6.9): a point of the paddle at height y above
// its foot stands at
//   x = x0 + (1/2) ((y + alpha0) / (y0 + alpha0)) A(t),   A(t) = A cos(omega t + phase),
// omega = 2 pi f: a flap hinged alpha0 below the foot (below the bed), so that the paddle both
// translates and turns. W's constants: alpha0 = 0.1344 m, y0 = 0.15 m, A = 0.2442 m; W gives no
// frequency (cases.md W-10). The phase is flume's (W's is 0: the paddle starts at its largest
// displacement); -pi/2 starts it from its rest position. Exact functions of time, as
// wall_motion.hpp's, so that a resumed run finds the paddle where an uninterrupted one would.
// The displacement is linear in y: the paddle stays a straight line.
#pragma once

#include <cmath>
#include <numbers>

namespace flume {

struct PistonFlapW69 {
  double hinge_depth = 0.1344;     // alpha0, m
  double reference_height = 0.15;  // y0, m
  double stroke = 0.0;             // A, m (0: the wall does not move)
  double frequency = 0.0;          // f, Hz
  double phase = 0.0;              // rad

  bool moves() const { return stroke != 0.0; }

  // x - x0 of the point at height y (m) above the foot, at time t (s), m.
  double displacement(double y, double t) const {
    if (!moves()) return 0.0;
    return lever(y) * stroke * std::cos(omega() * t + phase);
  }
  // Its velocity along x, m/s.
  double speed(double y, double t) const {
    if (!moves()) return 0.0;
    return -lever(y) * stroke * omega() * std::sin(omega() * t + phase);
  }

 private:
  double omega() const { return 2.0 * std::numbers::pi * frequency; }
  double lever(double y) const {
    return 0.5 * (y + hinge_depth) / (reference_height + hinge_depth);
  }
};

}  // namespace flume

// The Monaghan-Kos boundary force of a repulsive boundary particle, W (6.10)-(6.12):
//   f = n R(y) P(x),
//   R(y) = A (1 - q) / sqrt(q)  for q <= 1, 0 beyond,           W (6.11)
//   P(x) = (1 + cos(pi x / dp)) / 2  for |x| <= dp, 0 beyond,    W (6.12)
// with n the wall's unit normal (into the fluid), y the fluid particle's distance from the
// wall along n, x its distance along the wall from the boundary particle, dp the boundary
// particles' spacing. W leaves q and A undefined (errata.md); flume takes SPHysics's
// q = y / (2 h) and A = 0.01 c^2 / h, with h the fluid particle's smoothing length and c the
// reference sound speed, which makes f a force per unit mass (m/s^2). The reach 2h may be set
// to another distance r (q = y / r): the wall holds water at rest up to its reach off its plane
// (repulsive_walls.hpp), so a shorter reach brings the water nearer to where the wall stands.
// Why P: on a straight wall of boundary particles spaced dp, the two particles whose P is not
// zero at a point sit x and dp - x away, and P(x) + P(dp - x) = 1 (the cosines cancel), so the
// wall pushes with n R(y) wherever along it the fluid particle is: a smooth wall, unlike W (6.7).
// R's pole at y = 0 is never reached: a particle that crosses the wall is put back at a
// distance from it (W (6.8), repulsive_walls.hpp); the formula is evaluated at y no nearer
// than `nearest` for the stage between a crossing and its put-back.
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>

namespace flume {

struct MonaghanKosW610 {
  double sound_speed = 0.0;  // c, m/s
  double spacing = 0.0;      // dp, m: the boundary particles' spacing
  double nearest = 0.0;      // m: y is taken as at least this (R's pole at y = 0)
  double reach = 0.0;        // m: q = y / reach; 0 = 2h (SPHysics)

  // W (6.11): the push at distance y (m) from the wall of a particle of smoothing length h, m/s^2.
  double normal_part(double y, double h) const {
    const double q = std::max(y, nearest) / (reach > 0.0 ? reach : 2.0 * h);
    if (!(q <= 1.0)) return 0.0;
    const double a = 0.01 * sound_speed * sound_speed / h;
    return a * (1.0 - q) / std::sqrt(q);
  }
  // W (6.12): the share of a boundary particle at distance x (m) along the wall, -.
  double tangential_part(double x) const {
    if (!(std::abs(x) <= spacing)) return 0.0;
    return 0.5 * (1.0 + std::cos(std::numbers::pi * x / spacing));
  }
};

}  // namespace flume

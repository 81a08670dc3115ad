// The Lennard-Jones boundary force of a repulsive boundary particle, W (6.7):
//   f(r) = D ((r0 / r)^p1 - (r0 / r)^p2) r / r^2   for r <= r0,   0 beyond,
// with r the vector from the boundary particle to the fluid particle. W gives no constants;
// errata.md: p1 > p2 is meant (p1 = p2 is no force), and f is a force per unit mass, an
// acceleration (Monaghan 1994: p1 = 12, p2 = 4, r0 the initial spacing, D of the order of the
// largest velocity squared, e.g. 5 g H). D is in m^2/s^2, so f is in m/s^2. The force is
// central: a wall of such particles is rugged (W notes it), its push varying along the wall
// with the spacing of the boundary particles.
#pragma once

#include <cmath>

#include "flume/core/vec.hpp"

namespace flume {

struct LennardJonesW67 {
  double strength = 0.0;  // D, m^2/s^2
  double cutoff = 0.0;    // r0, m
  double p1 = 12.0;       // the repulsive power
  double p2 = 4.0;        // the attractive power

  // The acceleration of a fluid particle at r (m) from the boundary particle, m/s^2.
  template <int D>
  Vec<D> operator()(const Vec<D>& r) const {
    const double d2 = norm2(r);
    if (!(d2 <= cutoff * cutoff) || d2 == 0.0) return Vec<D>{};
    const double ratio = cutoff / std::sqrt(d2);
    return r * (strength * (std::pow(ratio, p1) - std::pow(ratio, p2)) / d2);
  }
};

}  // namespace flume

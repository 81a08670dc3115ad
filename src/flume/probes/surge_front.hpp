// Surge front of a collapsing column, as Martin & Moyce (1952) measured it: the distance from the
// wall behind the column to the leading edge of the water on the floor. flume takes the leading
// particle of the main body of water (fluid_body.hpp) among those within `layer` of the floor,
// and adds half a spacing (a particle stands for the cell of fluid around it), so that the front
// is exactly the column width at t = 0. Axis 0 is the flow direction and the last axis is
// vertical.
#pragma once

#include <algorithm>
#include <vector>

#include "flume/core/particle_set.hpp"

namespace flume {

template <int D>
double surge_front(const ParticleSet<D>& ps, const std::vector<char>& in_body, double wall_x,
                   double floor, double layer, double spacing) {
  double front = wall_x;
  for (std::size_t i = 0; i < ps.n_real; ++i)
    if (in_body[i] && ps.x[i][D - 1] - floor < layer)
      front = std::max(front, ps.x[i][0] + 0.5 * spacing);
  return front - wall_x;
}

}  // namespace flume

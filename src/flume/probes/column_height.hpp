// Residual column height at the back wall (Martin & Moyce's eta): the highest particle of the
// main body of water (fluid_body.hpp) among those within `band` of the wall, plus half a spacing,
// measured from the floor. At t = 0 it is exactly the column height.
#pragma once

#include <algorithm>
#include <vector>

#include "flume/core/particle_set.hpp"

namespace flume {

template <int D>
double column_height(const ParticleSet<D>& ps, const std::vector<char>& in_body, double wall_x,
                     double floor, double band, double spacing) {
  double top = floor;
  for (std::size_t i = 0; i < ps.n_real; ++i)
    if (in_body[i] && ps.x[i][0] - wall_x < band)
      top = std::max(top, ps.x[i][D - 1] + 0.5 * spacing);
  return top - floor;
}

}  // namespace flume

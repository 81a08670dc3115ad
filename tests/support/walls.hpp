// Helpers of the mirror-wall tests (test_box_walls.cpp, test_moving_walls.cpp): a unit box with
// one kind of wall on every side, and a particle whose every field the halo copies holds a
// distinct, recognisable value.
#pragma once

#include <cstdint>

#include "flume/boundaries/box_walls.hpp"
#include "flume/core/particle_set.hpp"
#include "flume/core/vec.hpp"

namespace flume::test {

template <int D>
BoxWalls<D> unit_box(WallKind all) {
  BoxWalls<D> b;
  for (int k = 0; k < D; ++k) {
    b.lo[k] = 0.0;
    b.hi[k] = 1.0;
    b.kind[k] = {all, all};
  }
  return b;
}

// A particle with distinct, recognisable values in every field the halo copies.
template <int D>
void add_particle(ParticleSet<D>& ps, const Vec<D>& x, const Vec<D>& v, const Vec<D>& v_half) {
  const auto i = static_cast<std::int64_t>(ps.size());
  ps.add_real(100 + i, x, v, 0.01 * (1.0 + static_cast<double>(i)), 1000.0 + static_cast<double>(i),
              0.02 + 0.001 * static_cast<double>(i));
  ps.v_half.back() = v_half;
  ps.p.back() = 50.0 + static_cast<double>(i);
}

// The halo's reach in the wall tests (m).
constexpr double kRange = 0.1;

}  // namespace flume::test

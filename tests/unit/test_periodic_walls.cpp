// Periodic sides of the box (boundaries/box_walls.hpp, W 6.1): ghosts are the other end's
// particles shifted by the box's length with their velocity, a particle leaving one end
// re-enters at the other, and before periodic_from the sides are free-slip walls (W 6.4.2).
#include <gtest/gtest.h>

#include "flume/boundaries/box_walls.hpp"

namespace flume {
namespace {

// [0, 4] x [0, 1], periodic along x, free-slip floor and lid.
BoxWalls<2> channel(double periodic_from = 0.0) {
  BoxWalls<2> box;
  box.lo = Vec<2>{0.0, 0.0};
  box.hi = Vec<2>{4.0, 1.0};
  box.kind[0] = {WallKind::periodic, WallKind::periodic};
  box.kind[1] = {WallKind::free_slip, WallKind::free_slip};
  box.periodic_from = periodic_from;
  return box;
}

TEST(PeriodicWalls, GhostsAreShiftedCopiesWithTheirVelocity) {
  auto box = channel();
  box.set_time(0.0);
  ParticleSet<2> ps;
  ps.add_real(0, Vec<2>{0.05, 0.5}, Vec<2>{0.3, -0.2}, 1.0, 1000.0, 0.05);  // near x = 0
  ps.add_real(1, Vec<2>{3.97, 0.02}, Vec<2>{0.1, 0.4}, 1.0, 1000.0, 0.05);  // near x = 4, floor
  ps.add_real(2, Vec<2>{2.0, 0.5}, Vec<2>{}, 1.0, 1000.0, 0.05);            // far from both
  Halo<2> halo;
  box.build_halo(ps, 0.1, halo);
  // Particle 0: one copy at x + 4. Particle 1: a copy at x - 4, the floor's mirror, and the
  // mirror of the copy (the corner): three.
  ASSERT_EQ(halo.size(), 4u);
  halo.append_ghosts(ps);
  const std::size_t g0 = ps.n_real;
  EXPECT_EQ(ps.id[g0], 0);
  EXPECT_DOUBLE_EQ(ps.x[g0][0], 4.05);
  EXPECT_DOUBLE_EQ(ps.x[g0][1], 0.5);
  EXPECT_DOUBLE_EQ(ps.v[g0][0], 0.3);  // a periodic copy keeps the velocity (W 6.1)
  EXPECT_DOUBLE_EQ(ps.v[g0][1], -0.2);
  int shifted = 0, mirrored = 0, corner = 0;
  for (std::size_t g = g0 + 1; g < ps.size(); ++g) {
    EXPECT_EQ(ps.id[g], 1);
    const bool copy = std::abs(ps.x[g][0] - (3.97 - 4.0)) < 1e-12;
    const bool below = std::abs(ps.x[g][1] + 0.02) < 1e-12;
    if (copy && !below) {
      ++shifted;
      EXPECT_DOUBLE_EQ(ps.v[g][1], 0.4);
    } else if (!copy && below) {
      ++mirrored;
      EXPECT_DOUBLE_EQ(ps.v[g][1], -0.4);  // free slip: the normal component reversed
    } else if (copy && below) {
      ++corner;
      EXPECT_DOUBLE_EQ(ps.v[g][0], 0.1);
      EXPECT_DOUBLE_EQ(ps.v[g][1], -0.4);
    }
  }
  EXPECT_EQ(shifted, 1);
  EXPECT_EQ(mirrored, 1);
  EXPECT_EQ(corner, 1);
}

TEST(PeriodicWalls, AParticleLeavingOneEndReentersAtTheOther) {
  // W 6.1's re-injection: x_i < l goes to r + (x_i - l), and the other way; velocities kept.
  auto box = channel();
  box.set_time(0.0);
  ParticleSet<2> ps;
  ps.add_real(0, Vec<2>{-0.01, 0.5}, Vec<2>{-1.0, 0.0}, 1.0, 1000.0, 0.05);
  ps.add_real(1, Vec<2>{4.02, 0.5}, Vec<2>{1.0, 0.2}, 1.0, 1000.0, 0.05);
  ps.add_real(2, Vec<2>{2.0, 0.5}, Vec<2>{1.0, 0.0}, 1.0, 1000.0, 0.05);
  box.reflect_crossings(ps, 0.1);
  EXPECT_DOUBLE_EQ(ps.x[0][0], 3.99);
  EXPECT_NEAR(ps.x[1][0], 0.02, 1e-15);
  EXPECT_DOUBLE_EQ(ps.x[2][0], 2.0);
  EXPECT_DOUBLE_EQ(ps.v[0][0], -1.0);
  EXPECT_DOUBLE_EQ(ps.v[1][1], 0.2);
  for (std::size_t i = 0; i < ps.n_real; ++i)
    EXPECT_TRUE(box.inside(ps, i)) << i;
}

TEST(PeriodicWalls, BeforePeriodicFromTheSidesAreFreeSlipWalls) {
  // W 6.4.2 forms its wave in a closed tank and joins the ends at t = 4 s.
  auto box = channel(4.0);
  ParticleSet<2> ps;
  ps.add_real(0, Vec<2>{0.05, 0.5}, Vec<2>{-0.3, 0.1}, 1.0, 1000.0, 0.05);
  Halo<2> halo;
  box.set_time(3.9);
  box.build_halo(ps, 0.1, halo);
  ASSERT_EQ(halo.size(), 1u);
  halo.append_ghosts(ps);
  EXPECT_DOUBLE_EQ(ps.x[1][0], -0.05);  // the wall's mirror image
  EXPECT_DOUBLE_EQ(ps.v[1][0], 0.3);
  ps.resize(ps.n_real);
  box.set_time(4.0);
  box.build_halo(ps, 0.1, halo);
  ASSERT_EQ(halo.size(), 1u);
  halo.append_ghosts(ps);
  EXPECT_DOUBLE_EQ(ps.x[1][0], 4.05);  // the other end's copy
  EXPECT_DOUBLE_EQ(ps.v[1][0], -0.3);
}

}  // namespace
}  // namespace flume

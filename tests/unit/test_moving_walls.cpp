// Unit tests of walls that move along their normal (src/flume/boundaries/wall_motion.hpp and the
// moving sides of box_walls.hpp): the prescribed motion, the ghosts mirrored about where the wall
// stands and relative to its velocity, and the put-back and escape checks at its present place.
// Tolerances: as test_box_walls.cpp (a mirror image rounds once: EXPECT_DOUBLE_EQ).
#include <gtest/gtest.h>

#include <numbers>
#include <vector>

#include "flume/boundaries/box_walls.hpp"
#include "flume/boundaries/halo.hpp"
#include "flume/core/particle_set.hpp"
#include "flume/core/vec.hpp"
#include "support/walls.hpp"

namespace flume {
namespace {

using test::add_particle;
using test::kRange;
using test::unit_box;

// A wall moving along its normal (the bore's push wall, a piston): at time t it stands at
// hi + u t + A sin(2 pi t / T), and its ghosts mirror the velocity relative to it,
// v' = P v + (I - P) u_w. Checked against the formula written out by hand; the positions are
// chosen so that every product is exact or rounds once (EXPECT_DOUBLE_EQ).
TEST(MovingWall, DisplacementAndSpeedAreThePrescribedMotion) {
  const WallMotion piston{-0.5, 0.0, 0.0};
  EXPECT_EQ(piston.displacement(0.25), -0.125);
  EXPECT_EQ(piston.speed(0.25), -0.5);
  const WallMotion sine{0.0, 0.1, 2.0};
  EXPECT_NEAR(sine.displacement(0.5), 0.1, 1e-16);              // a quarter period: the full stroke
  EXPECT_NEAR(sine.speed(0.0), 0.1 * std::numbers::pi, 1e-16);  // A omega at t = 0
  EXPECT_NEAR(sine.speed(0.5), 0.0, 1e-16);
  EXPECT_FALSE(WallMotion{}.moves());
}

TEST(MovingWall, GhostsMirrorAboutTheWallWhereItStandsAndRelativeToItsVelocity) {
  auto box = unit_box<2>(WallKind::free_slip);
  box.motion[0][1] = WallMotion{-0.5, 0.0, 0.0};  // the right wall moves left at 0.5 m/s
  box.set_time(0.25);                             // now at x = 0.875
  EXPECT_EQ(box.wall(0, 1), 0.875);
  EXPECT_EQ(box.wall_speed(0, 1), -0.5);
  EXPECT_EQ(box.wall(0, 0), 0.0);
  ParticleSet<2> ps;
  add_particle<2>(ps, {{0.8125, 0.5}}, {{0.25, 0.75}}, {{-0.5, 0.125}});
  Halo<2> halo;
  box.build_halo(ps, kRange, halo);
  ASSERT_EQ(halo.size(), 1u);
  halo.append_ghosts(ps);
  // x' = 2 w - x = 1.75 - 0.8125; v'_x = -v_x + 2 u = -0.25 - 1; tangential unchanged.
  EXPECT_EQ(ps.x[1], (Vec<2>{{0.9375, 0.5}}));
  EXPECT_EQ(ps.v[1], (Vec<2>{{-1.25, 0.75}}));
  // A particle moving with the wall has a ghost moving with it too.
  EXPECT_EQ(ps.v_half[1], (Vec<2>{{-0.5, 0.125}}));
  ps.v_half[0] = Vec<2>{{1.0, -2.0}};
  halo.update_velocity(ps, ps.v_half);
  EXPECT_EQ(ps.v_half[1], (Vec<2>{{-2.0, -2.0}}));
}

TEST(MovingWall, NoSlipAndCornerGhostsComposeTheMaps) {
  auto box = unit_box<2>(WallKind::no_slip);
  box.motion[0][0] = WallMotion{0.5, 0.0, 0.0};  // the left wall moves right at 0.5 m/s
  box.set_time(0.125);                           // now at x = 0.0625
  ParticleSet<2> ps;
  add_particle<2>(ps, {{0.125, 0.5}}, {{0.25, 0.75}}, {{0.25, 0.75}});     // near the left wall
  add_particle<2>(ps, {{0.125, 0.0625}}, {{0.25, 0.75}}, {{0.25, 0.75}});  // and the floor
  Halo<2> halo;
  box.build_halo(ps, kRange, halo);
  ASSERT_EQ(halo.size(), 4u);  // 1 + (left, floor, corner)
  halo.append_ghosts(ps);
  // No slip about a wall moving at u e_x: v' = -v + 2 u e_x.
  EXPECT_EQ(ps.x[2], (Vec<2>{{0.0, 0.5}}));
  EXPECT_EQ(ps.v[2], (Vec<2>{{0.75, -0.75}}));
  // The second particle's ghosts, in build_halo's order: left wall, floor, corner.
  EXPECT_EQ(ps.v[3], (Vec<2>{{0.75, -0.75}}));   // moving left wall
  EXPECT_EQ(ps.v[4], (Vec<2>{{-0.25, -0.75}}));  // static floor: -v
  // Corner: the left wall's map then the floor's, -(-v + 2 u e_x) = v - 2 u e_x.
  EXPECT_EQ(ps.x[5], (Vec<2>{{0.0, -0.0625}}));
  EXPECT_EQ(ps.v[5], (Vec<2>{{-0.75, 0.75}}));
}

TEST(MovingWall, PutBackAndEscapeUseTheWallsPresentPlace) {
  auto box = unit_box<2>(WallKind::free_slip);
  box.motion[0][1] = WallMotion{-0.5, 0.0, 0.0};
  box.set_time(0.25);  // right wall at 0.875
  ParticleSet<2> ps;
  add_particle<2>(ps, {{0.9375, 0.5}}, {{0.25, 0.75}}, {{0.125, 0.75}});  // behind the piston
  add_particle<2>(ps, {{0.8125, 0.5}}, {{0.25, 0.75}}, {{0.125, 0.75}});  // in front of it
  box.reflect_crossings(ps, kRange);
  // Put back as its mirror image about x = 0.875, velocity relative to the wall mirrored.
  EXPECT_EQ(ps.x[0], (Vec<2>{{0.8125, 0.5}}));
  EXPECT_EQ(ps.v[0], (Vec<2>{{-1.25, 0.75}}));
  EXPECT_EQ(ps.v_half[0], (Vec<2>{{-1.125, 0.75}}));
  EXPECT_EQ(ps.x[1], (Vec<2>{{0.8125, 0.5}}));
  EXPECT_EQ(box.first_outside(ps), -1);
  ps.x[1][0] = 0.9;  // between the wall's present place and its place at t = 0: outside
  EXPECT_EQ(box.first_outside(ps), 1);
}

}  // namespace
}  // namespace flume

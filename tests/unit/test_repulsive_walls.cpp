// Repulsive boundary particles (boundaries/repulsive_walls.hpp): the sizes of W (6.7) and
// W (6.10)-(6.12) against hand computations, the smoothness of the Monaghan-Kos wall, the
// orientation of a wall's normal, the put-back W (6.8) and the paddle's motion W (6.9).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "flume/boundaries/repulsive_walls.hpp"

namespace flume {
namespace {

Vec<2> at(double x, double y) {
  Vec<2> v;
  v[0] = x;
  v[1] = y;
  return v;
}

RepulsiveWall<2> wall(Vec<2> from, Vec<2> to, Repulsion force) {
  RepulsiveWall<2> w;
  w.from = from;
  w.to = to;
  w.force = force;
  w.spacing = 0.01;
  w.lennard_jones = LennardJonesW67{2.0, 0.01, 12.0, 4.0};
  w.sound_speed = 20.0;
  w.put_back_distance = 0.005;
  w.clearance = 0.005;
  return w;
}

TEST(LennardJonesW67, SizeAgainstAHandComputation) {
  const LennardJonesW67 lj{2.0, 0.01, 12.0, 4.0};
  // r = 0.005 m straight up: r0/r = 2, f = D (2^12 - 2^4) / r along +y = 2 * 4080 / 0.005.
  const Vec<2> f = lj(at(0.0, 0.005));
  EXPECT_NEAR(f[1], 2.0 * 4080.0 / 0.005, 1e-9 * 1.632e6);
  EXPECT_EQ(f[0], 0.0);
  // At r0 the two powers cancel; beyond it there is no force; at 0.8 r0 it still pushes
  // (p1 > p2): D ((1.25)^12 - (1.25)^4) / (0.8 r0), along the diagonal here.
  EXPECT_NEAR(norm(lj(at(0.0, 0.01))), 0.0, 1e-12);
  EXPECT_EQ(norm(lj(at(0.011, 0.0))), 0.0);
  const double r = 0.008;
  const Vec<2> g = lj(at(r / std::sqrt(2.0), r / std::sqrt(2.0)));
  const double expected = 2.0 * (std::pow(1.25, 12) - std::pow(1.25, 4)) / r;
  EXPECT_NEAR(norm(g), expected, 1e-12 * expected);
  EXPECT_NEAR(g[0], g[1], 1e-12 * expected);
  EXPECT_GT(g[0], 0.0);  // away from the boundary particle
}

TEST(MonaghanKosW610, SizeAgainstAHandComputation) {
  const MonaghanKosW610 mk{20.0, 0.01, 0.0};
  const double h = 0.013;
  // q = y / 2h = 0.25: R = A (1 - 0.25) / 0.5 = 1.5 A, A = 0.01 c^2 / h.
  const double a = 0.01 * 400.0 / h;
  EXPECT_NEAR(mk.normal_part(0.5 * h, h), 1.5 * a, 1e-12 * a);
  EXPECT_EQ(mk.normal_part(2.0 * h, h), 0.0);  // q = 1
  EXPECT_EQ(mk.normal_part(2.1 * h, h), 0.0);
  EXPECT_NEAR(mk.tangential_part(0.0), 1.0, 1e-15);
  EXPECT_NEAR(mk.tangential_part(0.005), 0.5, 1e-15);
  EXPECT_NEAR(mk.tangential_part(-0.0025), 0.5 * (1.0 + std::sqrt(0.5)), 1e-15);
  EXPECT_EQ(mk.tangential_part(0.0101), 0.0);
  // A reach of its own (q = y / reach): at y = reach / 4, R = A (1 - 1/4) / (1/2) = 1.5 A.
  const MonaghanKosW610 short_reach{20.0, 0.01, 0.0, 0.01};
  EXPECT_NEAR(short_reach.normal_part(0.0025, h), 1.5 * a, 1e-12 * a);
  EXPECT_EQ(short_reach.normal_part(0.0101, h), 0.0);
  // The pole at y = 0 is held at `nearest`.
  const MonaghanKosW610 held{20.0, 0.01, 0.002};
  EXPECT_EQ(held.normal_part(0.0, h), held.normal_part(0.002, h));
}

TEST(RepulsiveWalls, MonaghanKosWallIsSmoothAlongItsLength) {
  // P(x) + P(dp - x) = 1: along a straight wall the push is n R(y) wherever the particle is
  // (to round-off), and it points into the fluid, the wall's left (+y for a wall along +x).
  const RepulsiveWalls<2> walls({wall(at(0.0, 0.0), at(1.0, 0.0), Repulsion::monaghan_kos)});
  const double h = 0.013, y = 0.01;
  const MonaghanKosW610 mk{20.0, 0.01, 0.005};
  const double expected = mk.normal_part(y, h);
  for (double s = 0.1; s < 0.9; s += 0.00137) {
    const Vec<2> a = walls.acceleration(at(s, y), h);
    EXPECT_NEAR(a[1], expected, 1e-12 * expected) << "s = " << s;
    EXPECT_EQ(a[0], 0.0);
  }
  // Beyond its reach (y > 2h), behind its ends (one spacing past the last particle), nothing.
  EXPECT_EQ(norm(walls.acceleration(at(0.5, 2.01 * h), h)), 0.0);
  EXPECT_EQ(norm(walls.acceleration(at(1.0101, y), h)), 0.0);
  // Half a spacing beyond the last particle, half its share: P(dp/2) = 1/2.
  EXPECT_NEAR(walls.acceleration(at(1.005, y), h)[1], 0.5 * expected, 1e-12 * expected);
}

TEST(RepulsiveWalls, LennardJonesWallIsRugged) {
  // W notes that (6.7) makes a rugged wall: between two boundary particles the push is weaker
  // than above one. Above a particle at 0.8 r0 only that particle reaches (the next is
  // sqrt(0.64 + 1) r0 away); midway, two reach at sqrt(0.64 + 0.25) r0 each.
  const RepulsiveWalls<2> walls({wall(at(0.0, 0.0), at(1.0, 0.0), Repulsion::lennard_jones)});
  const LennardJonesW67 lj{2.0, 0.01, 12.0, 4.0};
  const Vec<2> above = walls.acceleration(at(0.5, 0.008), 0.013);
  EXPECT_NEAR(above[1], lj(at(0.0, 0.008))[1], 1e-9 * above[1]);
  const Vec<2> mid = walls.acceleration(at(0.505, 0.008), 0.013);
  EXPECT_NEAR(mid[1], 2.0 * lj(at(0.005, 0.008))[1], 1e-9 * mid[1]);
  EXPECT_NEAR(mid[0], 0.0, 1e-9 * mid[1]);
  EXPECT_LT(mid[1], above[1]);
}

TEST(RepulsiveWalls, SlopeNormalPointsIntoTheWaterAbove) {
  // A 1:1 beach from its toe (1, 0) up to (2, 1): walking up it, the water is on the left,
  // the normal (-1, 1)/sqrt(2).
  const RepulsiveWalls<2> walls({wall(at(1.0, 0.0), at(2.0, 1.0), Repulsion::monaghan_kos)});
  EXPECT_NEAR(walls.normal(0)[0], -std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(walls.normal(0)[1], std::sqrt(0.5), 1e-15);
  const double d = 0.01;  // a point d in front of the beach's middle
  const Vec<2> a =
      walls.acceleration(at(1.5 - d * std::sqrt(0.5), 0.5 + d * std::sqrt(0.5)), 0.013);
  const MonaghanKosW610 mk{20.0, 0.01, 0.005};
  EXPECT_NEAR(a[0], -std::sqrt(0.5) * mk.normal_part(d, 0.013), 1e-9);
  EXPECT_NEAR(a[1], std::sqrt(0.5) * mk.normal_part(d, 0.013), 1e-9);
  EXPECT_TRUE(walls.blocked(at(1.6, 0.5)));    // under the beach
  EXPECT_TRUE(walls.blocked(at(1.502, 0.5)));  // in front, nearer than the clearance
  EXPECT_FALSE(walls.blocked(at(1.4, 0.5)));
  EXPECT_FALSE(walls.blocked(at(0.5, 0.01)));  // offshore of the toe
}

TEST(RepulsiveWalls, PutBackW68PlacesInFrontAndMirrorsTheNormalVelocity) {
  const RepulsiveWalls<2> walls({wall(at(0.0, 0.0), at(1.0, 0.0), Repulsion::monaghan_kos)});
  ParticleSet<2> ps;
  ps.add_real(0, at(0.3, -0.002), at(0.4, -1.0), 1.0, 1000.0, 0.013);  // crossed
  ps.add_real(1, at(0.6, 0.003), at(0.4, -1.0), 1.0, 1000.0, 0.013);   // in front
  ps.add_real(2, at(1.2, -0.002), at(0.4, -1.0), 1.0, 1000.0, 0.013);  // beyond the end
  ps.v_half = ps.v;
  walls.put_back(ps, 0, ps.n_real);
  EXPECT_DOUBLE_EQ(ps.x[0][0], 0.3);
  EXPECT_NEAR(ps.x[0][1], 0.005, 1e-15);
  EXPECT_DOUBLE_EQ(ps.v[0][0], 0.4);
  EXPECT_DOUBLE_EQ(ps.v[0][1], 1.0);
  EXPECT_DOUBLE_EQ(ps.v_half[0][1], 1.0);
  EXPECT_DOUBLE_EQ(ps.x[1][1], 0.003);
  EXPECT_DOUBLE_EQ(ps.v[1][1], -1.0);
  EXPECT_DOUBLE_EQ(ps.x[2][1], -0.002);
}

TEST(PistonFlapW69, DisplacementAndSpeed) {
  const PistonFlapW69 paddle{0.1344, 0.15, 0.2442, 0.8, 0.0};
  // At t = 0, A(0) = A: the point at y0 is displaced A/2, the hinge (y = -alpha0) not at all.
  EXPECT_NEAR(paddle.displacement(0.15, 0.0), 0.1221, 1e-15);
  EXPECT_NEAR(paddle.displacement(-0.1344, 0.37), 0.0, 1e-15);
  // At the foot: (1/2) alpha0 / (y0 + alpha0) A cos(omega t).
  const double t = 0.2, w = 2.0 * std::numbers::pi * 0.8;
  EXPECT_NEAR(paddle.displacement(0.0, t), 0.5 * 0.1344 / 0.2844 * 0.2442 * std::cos(w * t), 1e-15);
  // The speed is the displacement's derivative (central difference, error O(dt^2) ~ 1e-9).
  const double dt = 1e-5;
  const double fd =
      (paddle.displacement(0.3, t + dt) - paddle.displacement(0.3, t - dt)) / (2 * dt);
  EXPECT_NEAR(paddle.speed(0.3, t), fd, 1e-8);
}

TEST(RepulsiveWalls, PaddleMovesItsWallAndPutBackUsesItsVelocity) {
  // A vertical paddle from (0.5, 0) up to (0.5, 0.3) has the water on its left walking up, i.e.
  // at x < 0.5: to push water toward +x it runs downward, from (0.5, 0.3) to (0.5, 0).
  auto w = wall(at(0.5, 0.3), at(0.5, 0.0), Repulsion::monaghan_kos);
  w.paddle = PistonFlapW69{0.1344, 0.15, 0.2442, 0.8, -0.5 * std::numbers::pi};
  RepulsiveWalls<2> walls({w});
  EXPECT_NEAR(walls.normal(0)[0], 1.0, 1e-15);
  // W (6.9) measures y from the paddle's foot, its lower end (`to` here).
  const double t = 0.3;
  walls.set_time(t);
  EXPECT_NEAR(walls.from(0)[0], 0.5 + w.paddle.displacement(0.3, t), 1e-15);
  EXPECT_NEAR(walls.to(0)[0], 0.5 + w.paddle.displacement(0.0, t), 1e-15);
  // A particle that crossed it halfway up is put back in front with v_n -> 2 u_n - v_n.
  ParticleSet<2> ps;
  const double x_mid = 0.5 * (walls.from(0)[0] + walls.to(0)[0]);
  ps.add_real(0, at(x_mid - 0.001, 0.15), at(0.0, 0.0), 1.0, 1000.0, 0.013);
  ps.v_half = ps.v;
  // The wall's velocity where the particle crossed: at its foot along the wall (s from `from`),
  // the paddle's speed at the height of that point of the wall.
  const Vec<2> along = walls.to(0) - walls.from(0);
  const double f = dot(ps.x[0] - walls.from(0), along) / norm2(along);
  const double u_mid = w.paddle.speed(0.3 * (1.0 - f), t);
  walls.put_back(ps, 0, 1);
  const Vec<2> n = walls.normal(0);
  EXPECT_NEAR(dot(ps.v[0], n), 2.0 * u_mid * n[0], 1e-12);
  const double y_after = dot(ps.x[0] - walls.from(0), n);
  EXPECT_NEAR(y_after, 0.005, 1e-12);
}

}  // namespace
}  // namespace flume

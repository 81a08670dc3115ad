// Unit tests of the mirror-wall box (src/flume/boundaries/box_walls.hpp) and the ghost halo
// (src/flume/boundaries/halo.hpp): which ghosts a particle gets near walls, edges and corners,
// where they are and how their velocities map for free-slip and no-slip walls; how the halo
// copies and refreshes ghost fields, including the transformed velocity gradient P G S; and the
// "put back" of particles that stepped across a wall (walls that move: test_moving_walls.cpp).
//
// Tolerances: a mirror image is x' = -x + 2 w. For a wall at 0 that is an exact negation; for a
// wall at 1 the subtraction 2 - x rounds once, hence EXPECT_DOUBLE_EQ (4 ulp) there. Velocity and
// gradient maps multiply by +-1 and are exact.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <span>
#include <utility>
#include <vector>

#include "flume/boundaries/box_walls.hpp"
#include "flume/boundaries/halo.hpp"
#include "flume/core/particle_set.hpp"
#include "flume/core/vec.hpp"
#include "flume/neighbors/cell_grid.hpp"
#include "support/walls.hpp"

namespace flume {
namespace {

using test::add_particle;
using test::kRange;
using test::unit_box;

TEST(BoxWalls, FreeSlipFloorMakesOneMirrorGhost) {
  ParticleSet<2> ps;
  add_particle<2>(ps, {{0.5, 0.05}}, {{0.3, 0.7}}, {{0.2, 0.6}});
  const auto box = unit_box<2>(WallKind::free_slip);
  Halo<2> halo;
  box.build_halo(ps, kRange, halo);
  ASSERT_EQ(halo.size(), 1u);
  const auto& g = halo.maps()[0];
  EXPECT_EQ(g.source, 0u);
  EXPECT_EQ(g.scale, (Vec<2>{{1.0, -1.0}}));
  EXPECT_EQ(g.shift, (Vec<2>{{0.0, 0.0}}));
  EXPECT_EQ(g.vscale, (Vec<2>{{1.0, -1.0}}));

  halo.append_ghosts(ps);
  ASSERT_EQ(ps.size(), 2u);
  EXPECT_EQ(ps.n_real, 1u);
  // Exact: the mirror in the wall y = 0 is a negation.
  EXPECT_EQ(ps.x[1], (Vec<2>{{0.5, -0.05}}));
  EXPECT_EQ(ps.v[1], (Vec<2>{{0.3, -0.7}}));
  EXPECT_EQ(ps.v_half[1], (Vec<2>{{0.2, -0.6}}));
  EXPECT_EQ(ps.id[1], ps.id[0]);
  EXPECT_EQ(ps.m[1], ps.m[0]);
  EXPECT_EQ(ps.rho[1], ps.rho[0]);
  EXPECT_EQ(ps.p[1], ps.p[0]);
  EXPECT_EQ(ps.h[1], ps.h[0]);
  // The real particle is untouched.
  EXPECT_EQ(ps.x[0], (Vec<2>{{0.5, 0.05}}));
  EXPECT_EQ(ps.v[0], (Vec<2>{{0.3, 0.7}}));
}

TEST(BoxWalls, UpperWallsMirrorAboutTheirPlane) {
  ParticleSet<2> ps;
  add_particle<2>(ps, {{0.93, 0.5}}, {{0.3, 0.7}}, {{0.2, 0.6}});
  add_particle<2>(ps, {{0.5, 0.96}}, {{0.3, 0.7}}, {{0.2, 0.6}});
  const auto box = unit_box<2>(WallKind::free_slip);
  Halo<2> halo;
  box.build_halo(ps, kRange, halo);
  ASSERT_EQ(halo.size(), 2u);
  halo.append_ghosts(ps);
  // 2 * 1 - x rounds once: 4 ulp.
  EXPECT_DOUBLE_EQ(ps.x[2][0], 1.07);
  EXPECT_EQ(ps.x[2][1], 0.5);
  EXPECT_EQ(ps.v[2], (Vec<2>{{-0.3, 0.7}}));
  EXPECT_EQ(ps.x[3][0], 0.5);
  EXPECT_DOUBLE_EQ(ps.x[3][1], 1.04);
  EXPECT_EQ(ps.v[3], (Vec<2>{{0.3, -0.7}}));
}

TEST(BoxWalls, CornerParticleGetsTwoSingleAndOneDoubleReflection) {
  ParticleSet<2> ps;
  const Vec<2> v{{0.3, 0.7}};
  add_particle<2>(ps, {{0.05, 0.03}}, v, {{0.2, 0.6}});
  const auto box = unit_box<2>(WallKind::free_slip);
  Halo<2> halo;
  box.build_halo(ps, kRange, halo);
  ASSERT_EQ(halo.size(), 3u);
  halo.append_ghosts(ps);
  ASSERT_EQ(ps.size(), 4u);
  struct Expected {
    Vec<2> x, v;
  };
  const std::vector<Expected> want{
      {{{-0.05, 0.03}}, {{-0.3, 0.7}}},    // left wall
      {{{0.05, -0.03}}, {{0.3, -0.7}}},    // floor
      {{{-0.05, -0.03}}, {{-0.3, -0.7}}},  // both: composition of the two maps
  };
  for (const auto& w : want) {
    int found = 0;
    for (std::size_t i = 1; i < ps.size(); ++i)
      if (ps.x[i] == w.x) {
        ++found;
        EXPECT_EQ(ps.v[i], w.v) << "ghost at (" << w.x[0] << ", " << w.x[1] << ")";
      }
    EXPECT_EQ(found, 1) << "ghost at (" << w.x[0] << ", " << w.x[1] << ")";
  }
}

TEST(BoxWalls, NoSlipReversesBothComponents) {
  ParticleSet<2> ps;
  add_particle<2>(ps, {{0.5, 0.05}}, {{0.3, 0.7}}, {{0.2, 0.6}});
  const auto box = unit_box<2>(WallKind::no_slip);
  Halo<2> halo;
  box.build_halo(ps, kRange, halo);
  ASSERT_EQ(halo.size(), 1u);
  EXPECT_EQ(halo.maps()[0].vscale, (Vec<2>{{-1.0, -1.0}}));
  halo.append_ghosts(ps);
  EXPECT_EQ(ps.x[1], (Vec<2>{{0.5, -0.05}}));
  EXPECT_EQ(ps.v[1], (Vec<2>{{-0.3, -0.7}}));
  EXPECT_EQ(ps.v_half[1], (Vec<2>{{-0.2, -0.6}}));
}

TEST(BoxWalls, CornerVelocityMapsComposeAcrossWallKinds) {
  // No-slip left wall (P = -I) and free-slip floor (P = diag(1, -1)).
  auto box = unit_box<2>(WallKind::free_slip);
  box.kind[0][0] = WallKind::no_slip;
  ParticleSet<2> ps;
  add_particle<2>(ps, {{0.05, 0.03}}, {{0.3, 0.7}}, {{0.2, 0.6}});
  Halo<2> halo;
  box.build_halo(ps, kRange, halo);
  ASSERT_EQ(halo.size(), 3u);
  for (const auto& g : halo.maps()) {
    const bool left = g.scale[0] < 0.0, floor = g.scale[1] < 0.0;
    Vec<2> want{{1.0, 1.0}};
    if (left) want = -want;
    if (floor) want[1] = -want[1];
    EXPECT_EQ(g.vscale, want) << "left " << left << " floor " << floor;
  }
  // Two no-slip walls: (-I)(-I) = I at the corner.
  const auto noslip = unit_box<2>(WallKind::no_slip);
  noslip.build_halo(ps, kRange, halo);
  ASSERT_EQ(halo.size(), 3u);
  for (const auto& g : halo.maps()) {
    if (g.scale[0] < 0.0 && g.scale[1] < 0.0) {
      EXPECT_EQ(g.vscale, (Vec<2>{{1.0, 1.0}}));
    }
  }
}

TEST(BoxWalls, OpenSidesMakeNoGhosts) {
  auto box = unit_box<2>(WallKind::free_slip);
  box.kind[1][0] = WallKind::open;  // open floor
  ParticleSet<2> ps;
  add_particle<2>(ps, {{0.5, 0.05}}, {{0.3, 0.7}}, {{0.2, 0.6}});   // near the open floor only
  add_particle<2>(ps, {{0.05, 0.03}}, {{0.3, 0.7}}, {{0.2, 0.6}});  // open floor + left wall
  Halo<2> halo;
  box.build_halo(ps, kRange, halo);
  ASSERT_EQ(halo.size(), 1u);
  EXPECT_EQ(halo.maps()[0].source, 1u);
  EXPECT_EQ(halo.maps()[0].scale, (Vec<2>{{-1.0, 1.0}}));

  const auto all_open = unit_box<2>(WallKind::open);
  all_open.build_halo(ps, kRange, halo);
  EXPECT_EQ(halo.size(), 0u);
}

TEST(BoxWalls, InteriorParticlesGetNoGhosts) {
  ParticleSet<2> ps;
  add_particle<2>(ps, {{0.5, 0.5}}, {{0.3, 0.7}}, {{0.2, 0.6}});
  add_particle<2>(ps, {{0.1, 0.5}}, {{0.3, 0.7}}, {{0.2, 0.6}});  // exactly range from a wall
  add_particle<2>(ps, {{0.11, 0.2}}, {{0.3, 0.7}}, {{0.2, 0.6}});
  const auto box = unit_box<2>(WallKind::free_slip);
  Halo<2> halo;
  box.build_halo(ps, kRange, halo);
  EXPECT_EQ(halo.size(), 0u);
  halo.append_ghosts(ps);
  EXPECT_EQ(ps.size(), 3u);
}

TEST(BoxWalls, AtMostOneWallPerAxis) {
  // A box thinner than twice the range: the particle sees floor and ceiling, and gets one ghost
  // for each, never a ghost reflected in both (that is not an image of the fluid).
  auto box = unit_box<2>(WallKind::free_slip);
  box.hi[1] = 0.15;
  ParticleSet<2> ps;
  add_particle<2>(ps, {{0.5, 0.07}}, {{0.3, 0.7}}, {{0.2, 0.6}});
  Halo<2> halo;
  box.build_halo(ps, kRange, halo);
  ASSERT_EQ(halo.size(), 2u);
  halo.append_ghosts(ps);
  std::vector<double> ys{ps.x[1][1], ps.x[2][1]};
  std::sort(ys.begin(), ys.end());
  EXPECT_EQ(ys[0], -0.07);        // exact negation
  EXPECT_DOUBLE_EQ(ys[1], 0.23);  // 2 * 0.15 - 0.07, rounded: 4 ulp
}

TEST(BoxWalls, GhostsOrderedBySourceParticle) {
  ParticleSet<2> ps;
  add_particle<2>(ps, {{0.05, 0.03}}, {{0.3, 0.7}}, {{0.2, 0.6}});  // 3 ghosts
  add_particle<2>(ps, {{0.5, 0.5}}, {{0.3, 0.7}}, {{0.2, 0.6}});    // none
  add_particle<2>(ps, {{0.97, 0.5}}, {{0.3, 0.7}}, {{0.2, 0.6}});   // 1
  add_particle<2>(ps, {{0.92, 0.95}}, {{0.3, 0.7}}, {{0.2, 0.6}});  // 3
  const auto box = unit_box<2>(WallKind::free_slip);
  Halo<2> halo;
  box.build_halo(ps, kRange, halo);
  std::vector<std::uint32_t> sources;
  for (const auto& g : halo.maps())
    sources.push_back(g.source);
  EXPECT_EQ(sources, (std::vector<std::uint32_t>{0, 0, 0, 2, 3, 3, 3}));
  // Rebuilding gives the same maps in the same order.
  Halo<2> again;
  box.build_halo(ps, kRange, again);
  ASSERT_EQ(again.size(), halo.size());
  for (std::size_t g = 0; g < halo.size(); ++g) {
    EXPECT_EQ(again.maps()[g].scale, halo.maps()[g].scale);
    EXPECT_EQ(again.maps()[g].shift, halo.maps()[g].shift);
    EXPECT_EQ(again.maps()[g].vscale, halo.maps()[g].vscale);
  }
}

TEST(BoxWalls, ThreeDimensionalCornerGetsSevenGhosts) {
  ParticleSet<3> ps;
  const Vec<3> x{{0.05, 0.04, 0.03}};
  const Vec<3> v{{0.3, 0.7, -0.2}};
  add_particle<3>(ps, x, v, v);
  const auto box = unit_box<3>(WallKind::free_slip);
  Halo<3> halo;
  box.build_halo(ps, kRange, halo);
  ASSERT_EQ(halo.size(), 7u);
  halo.append_ghosts(ps);
  // Each non-empty subset of the three walls, once: ghost = (s0 x0, s1 x1, s2 x2) with
  // velocity (s0 v0, s1 v1, s2 v2) for free slip. Exact (walls at 0).
  for (int mask = 1; mask < 8; ++mask) {
    Vec<3> wx, wv;
    for (int k = 0; k < 3; ++k) {
      const double s = (mask >> k) & 1 ? -1.0 : 1.0;
      wx[k] = s * x[k];
      wv[k] = s * v[k];
    }
    int found = 0;
    for (std::size_t i = 1; i < ps.size(); ++i)
      if (ps.x[i] == wx) {
        ++found;
        EXPECT_EQ(ps.v[i], wv) << "mask " << mask;
      }
    EXPECT_EQ(found, 1) << "mask " << mask;
  }
  // An edge particle (two walls) gets 3, a face particle 1.
  ParticleSet<3> edge;
  add_particle<3>(edge, {{0.05, 0.5, 0.97}}, v, v);
  add_particle<3>(edge, {{0.5, 0.5, 0.02}}, v, v);
  box.build_halo(edge, kRange, halo);
  EXPECT_EQ(halo.size(), 4u);
}

TEST(BoxWalls, AppendGhostsTwiceDoesNotGrow) {
  ParticleSet<2> ps;
  add_particle<2>(ps, {{0.05, 0.03}}, {{0.3, 0.7}}, {{0.2, 0.6}});
  const auto box = unit_box<2>(WallKind::free_slip);
  Halo<2> halo;
  box.build_halo(ps, kRange, halo);
  halo.append_ghosts(ps);
  const auto first = ps.x;
  halo.append_ghosts(ps);
  EXPECT_EQ(ps.size(), 4u);
  EXPECT_EQ(ps.x, first);
  ps.drop_ghosts();
  EXPECT_EQ(ps.size(), 1u);
}

TEST(BoxWalls, UpdateScalarCopiesFromSources) {
  ParticleSet<2> ps;
  add_particle<2>(ps, {{0.05, 0.03}}, {{0.3, 0.7}}, {{0.2, 0.6}});
  add_particle<2>(ps, {{0.5, 0.97}}, {{0.3, 0.7}}, {{0.2, 0.6}});
  const auto box = unit_box<2>(WallKind::free_slip);
  Halo<2> halo;
  box.build_halo(ps, kRange, halo);
  halo.append_ghosts(ps);
  ps.rho[0] = 1234.5;
  ps.rho[1] = 987.25;
  ps.p[0] = -3.0;
  ps.p[1] = 7.5;
  halo.update_scalar(ps, ps.rho);
  halo.update_scalar(ps, ps.p);
  for (std::size_t g = 0; g < halo.size(); ++g) {
    const std::size_t s = halo.maps()[g].source;
    EXPECT_EQ(ps.rho[ps.n_real + g], ps.rho[s]);
    EXPECT_EQ(ps.p[ps.n_real + g], ps.p[s]);
  }
}

// boundaries.ghost_pressure = "hydrostatic" (halo.hpp set_hydrostatic): a ghost below the floor
// carries p(rho_s) + rho_s g . (x_g - x_s) and the Tait density of that pressure; a ghost beside
// a side wall (g . (x_g - x_s) = 0) keeps its source's state. The expected values are computed
// here with std::pow from the Tait law, not with TaitEos; tolerance: the pow round trip, a few
// ulp of rho (1e-9 kg/m^3 against a step of 1.5 kg/m^3).
TEST(BoxWalls, HydrostaticGhostsCarryTheColumnAcrossTheFloor) {
  ParticleSet<2> ps;
  add_particle<2>(ps, {{0.05, 0.03}}, {{0.3, 0.7}}, {{0.2, 0.6}});
  const auto box = unit_box<2>(WallKind::free_slip);
  const double rho0 = 1000.0, gamma = 7.0, c0 = 20.0, kappa = rho0 * c0 * c0 / gamma, g = 9.81;
  Halo<2> halo;
  halo.set_hydrostatic(Vec<2>{{0.0, -g}}, TaitEos{rho0, gamma, kappa});
  box.build_halo(ps, kRange, halo);
  ASSERT_EQ(halo.size(), 3u);  // the left wall's, the floor's and the corner's
  const auto tait_p = [&](double rho) { return kappa * (std::pow(rho / rho0, gamma) - 1.0); };
  const auto tait_rho = [&](double p) { return rho0 * std::pow(1.0 + p / kappa, 1.0 / gamma); };
  for (const double rho_s : {1002.0, 999.5}) {
    ps.rho[0] = rho_s;
    if (rho_s == 1002.0)
      halo.append_ghosts(ps);
    else
      halo.update_density(ps);
    for (std::size_t k = 0; k < halo.size(); ++k) {
      const std::size_t i = ps.n_real + k;
      const double depth = -ps.x[i][1] - ps.x[0][1];  // 0.06 m below the source, or 0
      const double p = tait_p(rho_s) + rho_s * g * (ps.x[i][1] < 0.0 ? 2 * 0.03 : 0.0);
      EXPECT_NEAR(ps.p[i], p, 1e-9 * kappa) << "ghost " << k << " rho_s " << rho_s;
      EXPECT_NEAR(ps.rho[i], tait_rho(p), 1e-9) << "ghost " << k << " depth " << depth;
      EXPECT_NEAR(ps.c[i], std::sqrt(gamma * (p + kappa) / ps.rho[i]), 1e-9);
      // The step's size, to first order: dp / c_s^2 = rho_s g 2y / c_s^2, about 1.46 kg/m^3
      // (c_s the source's sound speed); the second-order term, (gamma - 1) / 2 drho / rho of
      // the step, is 0.45 % of it: within 1 %.
      const double c2 = gamma * (tait_p(rho_s) + kappa) / rho_s;
      if (ps.x[i][1] < 0.0)
        EXPECT_NEAR(ps.rho[i] - rho_s, rho_s * g * 0.06 / c2, 0.01 * rho_s * g * 0.06 / c2);
      else
        EXPECT_NEAR(ps.rho[i], rho_s, 1e-9);
    }
  }
  // update_pressure gives the same state (the sources' pressure is re-derived from rho).
  ps.rho[0] = 1001.0;
  halo.update_pressure(ps);
  const double p_floor = tait_p(1001.0) + 1001.0 * g * 0.06;
  bool seen = false;
  for (std::size_t k = 0; k < halo.size(); ++k)
    if (ps.x[ps.n_real + k][1] < 0.0) {
      EXPECT_NEAR(ps.p[ps.n_real + k], p_floor, 1e-9 * kappa);
      seen = true;
    }
  EXPECT_TRUE(seen);
}

TEST(BoxWalls, UpdateVelocityMapsFromSources) {
  auto box = unit_box<2>(WallKind::free_slip);
  box.kind[0][0] = WallKind::no_slip;
  ParticleSet<2> ps;
  add_particle<2>(ps, {{0.05, 0.03}}, {{0.3, 0.7}}, {{0.2, 0.6}});
  Halo<2> halo;
  box.build_halo(ps, kRange, halo);
  halo.append_ghosts(ps);
  ps.v_half[0] = Vec<2>{{-1.5, 2.5}};
  halo.update_velocity(ps, ps.v_half);
  for (std::size_t g = 0; g < halo.size(); ++g) {
    const auto& mp = halo.maps()[g];
    const Vec<2> want{{mp.vscale[0] * -1.5, mp.vscale[1] * 2.5}};
    EXPECT_EQ(ps.v_half[ps.n_real + g], want) << "ghost " << g;
  }
}

// The velocity-gradient map on a floor (y = 0): ghost (grad v)_{kl} = P_k G_kl S_l.
Mat<2> floor_ghost_gradient(WallKind kind, const Mat<2>& G) {
  auto box = unit_box<2>(WallKind::open);
  box.kind[1][0] = kind;
  ParticleSet<2> ps;
  add_particle<2>(ps, {{0.5, 0.05}}, {{0.3, 0.7}}, {{0.2, 0.6}});
  Halo<2> halo;
  box.build_halo(ps, kRange, halo);
  EXPECT_EQ(halo.size(), 1u);
  halo.append_ghosts(ps);
  ps.grad_v[0] = G;
  halo.update_velocity_gradient(ps);
  return ps.grad_v[1];
}

// [[a, b], [c, d]]
Mat<2> mat2(double a, double b, double c, double d) {
  Mat<2> m;
  m(0, 0) = a;
  m(0, 1) = b;
  m(1, 0) = c;
  m(1, 1) = d;
  return m;
}

TEST(BoxWalls, FreeSlipFloorFlipsShearComponentsOfTheGradient) {
  const double a = 1.5, b = -2.25, c = 0.75, d = 3.0;
  const Mat<2> G = mat2(a, b, c, d);
  // S = P = diag(1, -1): [[a, b], [c, d]] -> [[a, -b], [-c, d]].
  const Mat<2> got = floor_ghost_gradient(WallKind::free_slip, G);
  EXPECT_EQ(got(0, 0), a);
  EXPECT_EQ(got(0, 1), -b);
  EXPECT_EQ(got(1, 0), -c);
  EXPECT_EQ(got(1, 1), d);
}

TEST(BoxWalls, NoSlipFloorGradientIsPGS) {
  // S = diag(1, -1), P = -I: (P G S)_{kl} = -G_kl S_l, i.e. [[a, b], [c, d]] -> [[-a, b], [-c, d]]:
  // du/dy (the wall shear) is kept, the normal derivative of the normal velocity d is kept, the
  // tangential derivatives a and c flip. (The ghost field is v'(x, y) = -v(x, -y).)
  const double a = 1.5, b = -2.25, c = 0.75, d = 3.0;
  const Mat<2> G = mat2(a, b, c, d);
  const Mat<2> got = floor_ghost_gradient(WallKind::no_slip, G);
  EXPECT_EQ(got(0, 0), -a);
  EXPECT_EQ(got(0, 1), b);
  EXPECT_EQ(got(1, 0), -c);
  EXPECT_EQ(got(1, 1), d);
}

// Independent of the P G S formula: for an affine velocity field v(x) = v0 + G x around the
// source, the ghost carries the field v'(x') = P v(S (x' - t)); its gradient, measured by central
// differences of that field (exact for an affine field up to round-off), must equal what the halo
// writes. Checked for every ghost of a 3D corner particle with mixed wall kinds.
TEST(BoxWalls, GhostGradientIsTheGradientOfTheMirroredField3D) {
  auto box = unit_box<3>(WallKind::free_slip);
  box.kind[0][0] = WallKind::no_slip;
  box.kind[2][0] = WallKind::no_slip;
  ParticleSet<3> ps;
  add_particle<3>(ps, {{0.05, 0.04, 0.03}}, {{0.3, 0.7, -0.2}}, {{0.3, 0.7, -0.2}});
  Halo<3> halo;
  box.build_halo(ps, kRange, halo);
  ASSERT_EQ(halo.size(), 7u);
  halo.append_ghosts(ps);
  Mat<3> G;
  for (int k = 0; k < 3; ++k)
    for (int l = 0; l < 3; ++l)
      G(k, l) = 0.5 + 1.25 * k - 0.75 * l + (k == l ? 2.0 : 0.0);
  ps.grad_v[0] = G;
  halo.update_velocity_gradient(ps);

  const Vec<3> v0{{0.3, 0.7, -0.2}};
  auto field = [&](const Vec<3>& y) { return v0 + G * y; };
  for (std::size_t g = 0; g < halo.size(); ++g) {
    const auto& mp = halo.maps()[g];
    auto ghost_field = [&](const Vec<3>& xp) {
      Vec<3> pre;
      for (int k = 0; k < 3; ++k)
        pre[k] = mp.scale[k] * (xp[k] - mp.shift[k]);
      Vec<3> out = field(pre);
      for (int k = 0; k < 3; ++k)
        out[k] *= mp.vscale[k];
      return out;
    };
    const Vec<3> xg = ps.x[ps.n_real + g];
    const double eps = 0.125;  // affine field: the central difference is exact up to round-off
    for (int l = 0; l < 3; ++l) {
      Vec<3> e;
      e[l] = eps;
      const Vec<3> dv = (ghost_field(xg + e) - ghost_field(xg - e)) * (0.5 / eps);
      for (int k = 0; k < 3; ++k)
        // |G| <= 5, field values O(1): a few ulp of O(1) numbers divided by 2 eps = 0.25.
        EXPECT_NEAR(ps.grad_v[ps.n_real + g](k, l), dv[k], 1e-13)
            << "ghost " << g << " component (" << k << ", " << l << ")";
    }
  }
}

TEST(BoxWalls, ReflectCrossingsPutsParticleBackAsItsMirrorImage) {
  ParticleSet<2> ps;
  add_particle<2>(ps, {{0.5, -0.01}}, {{0.3, -0.7}}, {{0.2, -0.6}});  // just below the floor
  add_particle<2>(ps, {{0.4, -0.5}}, {{0.3, -0.7}}, {{0.2, -0.6}});   // beyond range: lost
  add_particle<2>(ps, {{0.6, 0.5}}, {{0.3, -0.7}}, {{0.2, -0.6}});    // inside
  add_particle<2>(ps, {{0.7, 0.0}}, {{0.3, -0.7}}, {{0.2, -0.6}});    // exactly on the wall
  const auto box = unit_box<2>(WallKind::free_slip);
  box.reflect_crossings(ps, kRange);
  EXPECT_EQ(ps.x[0], (Vec<2>{{0.5, 0.01}}));  // 2 * 0 - (-0.01): exact
  EXPECT_EQ(ps.v[0], (Vec<2>{{0.3, 0.7}}));
  EXPECT_EQ(ps.v_half[0], (Vec<2>{{0.2, 0.6}}));
  EXPECT_EQ(ps.x[1], (Vec<2>{{0.4, -0.5}}));
  EXPECT_EQ(ps.v[1], (Vec<2>{{0.3, -0.7}}));
  EXPECT_EQ(ps.x[2], (Vec<2>{{0.6, 0.5}}));
  EXPECT_EQ(ps.x[3], (Vec<2>{{0.7, 0.0}}));
  EXPECT_EQ(ps.v[3], (Vec<2>{{0.3, -0.7}}));
  EXPECT_EQ(box.first_outside(ps), 1);
}

TEST(BoxWalls, ReflectCrossingsNoSlipUpperAndCorner) {
  auto box = unit_box<2>(WallKind::free_slip);
  box.kind[0][1] = WallKind::no_slip;  // right wall
  ParticleSet<2> ps;
  add_particle<2>(ps, {{1.02, 0.5}}, {{0.3, -0.7}}, {{0.2, -0.6}});  // through the no-slip wall
  add_particle<2>(ps, {{-0.01, -0.02}}, {{-0.3, -0.7}}, {{-0.2, -0.6}});  // through a corner
  box.reflect_crossings(ps, kRange);
  EXPECT_DOUBLE_EQ(ps.x[0][0], 0.98);  // 2 * 1 - 1.02 rounds once: 4 ulp
  EXPECT_EQ(ps.x[0][1], 0.5);
  EXPECT_EQ(ps.v[0], (Vec<2>{{-0.3, 0.7}}));
  EXPECT_EQ(ps.v_half[0], (Vec<2>{{-0.2, 0.6}}));
  EXPECT_EQ(ps.x[1], (Vec<2>{{0.01, 0.02}}));
  EXPECT_EQ(ps.v[1], (Vec<2>{{0.3, 0.7}}));
  EXPECT_EQ(ps.v_half[1], (Vec<2>{{0.2, 0.6}}));
  EXPECT_EQ(box.first_outside(ps), -1);
}

TEST(BoxWalls, OpenSideIsNotReflectedAndParticleIsReportedLost) {
  auto box = unit_box<2>(WallKind::free_slip);
  box.kind[1][0] = WallKind::open;
  ParticleSet<2> ps;
  add_particle<2>(ps, {{0.5, 0.5}}, {{0.3, -0.7}}, {{0.2, -0.6}});
  add_particle<2>(ps, {{0.5, -0.01}}, {{0.3, -0.7}}, {{0.2, -0.6}});
  box.reflect_crossings(ps, kRange);
  EXPECT_EQ(ps.x[1], (Vec<2>{{0.5, -0.01}}));
  EXPECT_EQ(box.first_outside(ps), 1);
}

TEST(BoxWalls, FirstOutside) {
  const auto box = unit_box<2>(WallKind::free_slip);
  ParticleSet<2> ps;
  EXPECT_EQ(box.first_outside(ps), -1);                           // empty
  add_particle<2>(ps, {{0.0, 0.0}}, {{0.0, 0.0}}, {{0.0, 0.0}});  // on the corner: inside
  add_particle<2>(ps, {{1.0, 0.3}}, {{0.0, 0.0}}, {{0.0, 0.0}});
  add_particle<2>(ps, {{0.5, 0.5}}, {{0.0, 0.0}}, {{0.0, 0.0}});
  EXPECT_EQ(box.first_outside(ps), -1);
  add_particle<2>(ps, {{0.5, 1.5}}, {{0.0, 0.0}}, {{0.0, 0.0}});
  add_particle<2>(ps, {{-0.5, 0.5}}, {{0.0, 0.0}}, {{0.0, 0.0}});
  EXPECT_EQ(box.first_outside(ps), 3);
  ps.x[2][0] = std::numeric_limits<double>::quiet_NaN();  // NaN counts as outside
  EXPECT_EQ(box.first_outside(ps), 2);
  // Ghosts beyond n_real are ignored.
  ParticleSet<2> g;
  add_particle<2>(g, {{0.05, 0.5}}, {{0.0, 0.0}}, {{0.0, 0.0}});
  Halo<2> halo;
  box.build_halo(g, kRange, halo);
  halo.append_ghosts(g);
  ASSERT_EQ(g.size(), 2u);
  EXPECT_EQ(box.first_outside(g), -1);
}

// A simulation builds the halo from the particles of the cells near the walls only (the grid
// overload of build_halo); it must be the halo built from every particle,
// map for map and in the same order. Free-slip, no-slip and open sides, a moving wall placed
// away from its rest position, 2D and 3D.
template <int D>
void expect_halo_from_near_cells_is_the_full_halo(BoxWalls<D> box, double range,
                                                  std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  ParticleSet<D> ps;
  for (int i = 0; i < 3000; ++i) {
    Vec<D> x;
    for (int k = 0; k < D; ++k)
      x[k] = box.wall(k, 0) + (box.wall(k, 1) - box.wall(k, 0)) * u(rng);
    add_particle<D>(ps, x, Vec<D>{}, Vec<D>{});
  }
  CellGrid<D> grid;  // sorted by cell, as the simulation has them when it builds the halo
  const auto order = grid.sort_real(std::span<const Vec<D>>(ps.x.data(), ps.n_real), range);
  ParticleSet<D> sorted = ps;
  for (std::size_t k = 0; k < order.size(); ++k)
    sorted.x[k] = ps.x[order[k]];
  Halo<D> fast, full;
  box.build_halo(sorted, range, fast, grid);
  box.build_halo(sorted, range, full);
  ASSERT_GT(full.size(), 0u);
  ASSERT_EQ(fast.size(), full.size());
  for (std::size_t g = 0; g < full.size(); ++g) {
    const auto &a = fast.maps()[g], &b = full.maps()[g];
    ASSERT_EQ(a.source, b.source) << "ghost " << g;
    ASSERT_EQ(a.scale, b.scale) << "ghost " << g;
    ASSERT_EQ(a.shift, b.shift) << "ghost " << g;
    ASSERT_EQ(a.vscale, b.vscale) << "ghost " << g;
    ASSERT_EQ(a.vshift, b.vshift) << "ghost " << g;
  }
}

TEST(BoxWalls, HaloFromTheCellsNearTheWallsIsTheFullHalo) {
  auto box2 = unit_box<2>(WallKind::free_slip);
  box2.kind[0] = {WallKind::no_slip, WallKind::open};
  box2.motion[1][1] = WallMotion{-0.5, 0.0, 0.0};
  box2.set_time(0.5);  // the top wall at 0.75
  for (const double range : {0.02, 0.07, 0.2})
    expect_halo_from_near_cells_is_the_full_halo<2>(box2, range, 11);
  auto box3 = unit_box<3>(WallKind::free_slip);
  box3.kind[2] = {WallKind::open, WallKind::no_slip};
  box3.set_time(0.0);
  expect_halo_from_near_cells_is_the_full_halo<3>(box3, 0.1, 12);
}

}  // namespace
}  // namespace flume

// Unit tests of the dam-break and bore probes (src/flume/probes): the main body of water, the
// surge front, the residual column height, and the bore's front and height, on hand-made
// particle sets that include detached droplets.
//
// Positions are multiples of 0.125 and every result is a sum of two of them, so each expected
// value is exact in binary floating point: EXPECT_DOUBLE_EQ.
#include <gtest/gtest.h>

#include <vector>

#include "flume/core/particle_set.hpp"
#include "flume/probes/bore.hpp"
#include "flume/probes/column_height.hpp"
#include "flume/probes/fluid_body.hpp"
#include "flume/probes/surge_front.hpp"

namespace flume {
namespace {

constexpr double kDx = 0.25;

// A block of nx x ny particles of spacing kDx with its lower-left cell at `origin`.
void add_block(ParticleSet<2>& ps, int nx, int ny, Vec<2> origin) {
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      ps.add_real(static_cast<std::int64_t>(ps.size()),
                  {origin[0] + (i + 0.5) * kDx, origin[1] + (j + 0.5) * kDx}, {0.0, 0.0}, 1.0,
                  1000.0, kDx);
}

void add_droplet(ParticleSet<2>& ps, Vec<2> x) {
  ps.add_real(static_cast<std::int64_t>(ps.size()), x, {0.0, 0.0}, 1.0, 1000.0, kDx);
}

double front(const ParticleSet<2>& ps) {
  return surge_front(ps, main_fluid_body(ps, 3 * kDx), 0.0, 0.0, 2 * kDx, kDx);
}

double height(const ParticleSet<2>& ps) {
  return column_height(ps, main_fluid_body(ps, 3 * kDx), 0.0, 0.0, 2 * kDx, kDx);
}

TEST(FluidBody, IsTheLargestLinkedSet) {
  ParticleSet<2> ps;
  add_block(ps, 4, 4, {0.0, 0.0});
  add_block(ps, 2, 2, {3.0, 0.0});  // 1.75 from the big block: more than the 0.75 gap
  add_droplet(ps, {1.625, 0.125});  // 0.75 from the block's corner particle: linked
  const auto body = main_fluid_body(ps, 3 * kDx);
  ASSERT_EQ(body.size(), ps.n_real);
  for (std::size_t i = 0; i < 16; ++i)
    EXPECT_EQ(body[i], 1) << i;
  for (std::size_t i = 16; i < 20; ++i)
    EXPECT_EQ(body[i], 0) << i;
  EXPECT_EQ(body[20], 1);
}

TEST(FluidBody, TiesGoToTheSetWithTheLowestIndex) {
  ParticleSet<2> ps;
  add_block(ps, 2, 2, {5.0, 0.0});
  add_block(ps, 2, 2, {0.0, 0.0});
  const auto body = main_fluid_body(ps, 3 * kDx);
  EXPECT_EQ(body, (std::vector<char>{1, 1, 1, 1, 0, 0, 0, 0}));
}

TEST(FluidBody, LinksAcrossTheThreeDimensionalNeighbourCells) {
  ParticleSet<3> ps;
  for (int i = 0; i < 4; ++i)  // a diagonal chain with links of length sqrt(3) * 0.25 = 0.43
    ps.add_real(i, {0.25 * i, 0.25 * i, 0.25 * i}, {0.0, 0.0, 0.0}, 1.0, 1000.0, kDx);
  ps.add_real(4, {3.0, 3.0, 3.0}, {0.0, 0.0, 0.0}, 1.0, 1000.0, kDx);
  EXPECT_EQ(main_fluid_body(ps, 0.5), (std::vector<char>{1, 1, 1, 1, 0}));
}

TEST(Probes, BlockAtRestGivesItsWidthAndHeight) {
  ParticleSet<2> ps;
  add_block(ps, 8, 8, {0.0, 0.0});
  EXPECT_DOUBLE_EQ(front(ps), 2.0);
  EXPECT_DOUBLE_EQ(height(ps), 2.0);
}

TEST(Probes, DetachedDropletsAreNeitherFrontNorColumn) {
  ParticleSet<2> ps;
  add_block(ps, 8, 8, {0.0, 0.0});
  add_droplet(ps, {4.0, 0.125});  // spray on the floor well ahead of the front
  add_droplet(ps, {0.125, 5.0});  // spray high above the column
  EXPECT_DOUBLE_EQ(front(ps), 2.0);
  EXPECT_DOUBLE_EQ(height(ps), 2.0);
  // Within the gap a particle is part of the water: the front reaches it.
  add_droplet(ps, {2.5, 0.125});
  EXPECT_DOUBLE_EQ(front(ps), 2.625);
}

TEST(Probes, OnlyTheFloorLayerAndTheWallBandCount) {
  ParticleSet<2> ps;
  add_block(ps, 4, 4, {0.0, 0.0});
  // Linked to the block, but a jet above the floor layer is not the front, and a particle beyond
  // the wall band is not the column.
  add_droplet(ps, {1.25, 0.75});
  add_droplet(ps, {0.875, 1.25});
  EXPECT_DOUBLE_EQ(front(ps), 1.0);
  EXPECT_DOUBLE_EQ(height(ps), 1.0);
}

// A bore on a lattice of spacing dx = 0.25: lattice columns 8 particles tall (depth 2.0) up to
// x = 4, then the incoming layer 4 tall (h0 = 1.0) to x = 8. The probe samples the depth at the
// lattice columns, eta_c = dx (N_{c-1} + 4 N_c + N_{c+1}) / 6 (the cubic B-spline's weights
// 1/6, 4/6, 1/6 on a lattice), so across the step it reads 44/24 and 28/24 at x = 3.875 and
// 4.125; the mid-level 1.5 is crossed half-way between them, at 4.0; the height is the median
// behind, 2.0. Sums of sixths round: 1e-12.
// Masses 1 and rho0 = 1 / dx^2 = 16: each particle holds dx^2 of water.
BoreMeasure bore(const ParticleSet<2>& ps) {
  return measure_bore(ps, main_fluid_body(ps, 3 * kDx), 0.0, 1.0 / (kDx * kDx), 1.0, kDx);
}

TEST(BoreProbe, StepProfileGivesTheStepsPositionAndHeight) {
  ParticleSet<2> ps;
  add_block(ps, 16, 8, {0.0, 0.0});
  add_block(ps, 16, 4, {4.0, 0.0});
  auto m = bore(ps);
  EXPECT_NEAR(m.front, 4.0, 1e-12);
  EXPECT_NEAR(m.height, 2.0, 1e-12);
  // Spray above the incoming layer is not water of the bore.
  add_droplet(ps, {6.0, 3.0});
  m = bore(ps);
  EXPECT_NEAR(m.front, 4.0, 1e-12);
  EXPECT_NEAR(m.height, 2.0, 1e-12);
}

TEST(BoreProbe, MidLevelCrossingIsInterpolatedAndTheHeightIsAMedian) {
  ParticleSet<2> ps;
  add_block(ps, 16, 8, {0.0, 0.0});
  add_block(ps, 16, 4, {4.0, 0.0});
  // A step on the front's face: the lattice columns at 4.125 and 4.375 hold 7 particles, so
  // eta = (8 + 28 + 7) / 24, (7 + 28 + 4) / 24 = 1.625 and (7 + 16 + 4) / 24 = 1.125 at 4.125,
  // 4.375 and 4.625: X1 = 4.375 and the level 1.5 is crossed a quarter of the way on, at 4.4375.
  add_block(ps, 2, 3, {4.0, 1.0});
  // A run-up at the wall (x < 1) 12 particles tall: the median of the samples between X1/4 and
  // 3 X1/4 (x = 1.125 to 3.125: one reads 52/24, eight read 2) steps over it.
  add_block(ps, 4, 4, {0.0, 2.0});
  const auto m = bore(ps);
  EXPECT_NEAR(m.height, 2.0, 1e-12);
  EXPECT_NEAR(m.front, 4.4375, 1e-12);
}

TEST(BoreProbe, UndisturbedLayerHasNoBore) {
  ParticleSet<2> ps;
  add_block(ps, 32, 4, {0.0, 0.0});
  const auto m = bore(ps);
  EXPECT_EQ(m.front, 0.0);
  EXPECT_NEAR(m.height, 1.0, 1e-12);  // at the wall too: the mirror image's share
}

// The whole bore shifted by a fraction of a spacing: the front follows the step to within a
// tenth of a spacing (the B-spline's shifts sum to one, so the lattice does not alias; what is
// left is the linear interpolation of the smoothed step between samples) and the height stays.
TEST(BoreProbe, FrontFollowsAShiftedStep) {
  for (double shift : {0.03, 0.1, 0.125, 0.2}) {
    ParticleSet<2> ps;
    add_block(ps, 16, 8, {shift, 0.0});
    add_block(ps, 16, 4, {4.0 + shift, 0.0});
    const auto m = bore(ps);
    EXPECT_NEAR(m.front, 4.0 + shift, 0.1 * kDx) << shift;
    EXPECT_NEAR(m.height, 2.0, 1e-12) << shift;
  }
}

}  // namespace
}  // namespace flume

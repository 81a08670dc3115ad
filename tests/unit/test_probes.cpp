// Unit tests of the dam-break probes (src/flume/probes): the main body of water, the surge front
// and the residual column height, on hand-made particle sets that include detached droplets.
//
// Positions are multiples of 0.125 and every result is a sum of two of them, so each expected
// value is exact in binary floating point: EXPECT_DOUBLE_EQ.
#include <gtest/gtest.h>

#include <vector>

#include "flume/core/particle_set.hpp"
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

}  // namespace
}  // namespace flume

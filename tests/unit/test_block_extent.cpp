// Unit tests of a block's extent (src/flume/sim/block_extent.hpp) and of the walls' put-back
// that skips the walls no particle of the block stands beyond (BoxWalls::put_back with the
// extent): the drift's pass of every step relies on both for its put-back and its checks.
//
// Tolerances: none. A least and a largest value are exact (each is one of the inputs), and the
// put-back with the extent must give the same bits as the put-back that scans every wall.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <random>

#include "flume/boundaries/box_walls.hpp"
#include "flume/core/particle_set.hpp"
#include "flume/sim/block_extent.hpp"
#include "support/walls.hpp"

namespace flume {
namespace {

using test::add_particle;
using test::kRange;
using test::unit_box;

template <int D>
ParticleSet<D> random_particles(std::size_t n, double from, double to, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(from, to);
  ParticleSet<D> ps;
  for (std::size_t i = 0; i < n; ++i) {
    Vec<D> x, v;
    for (int k = 0; k < D; ++k) {
      x[k] = u(rng);
      v[k] = u(rng) - 0.5;
    }
    add_particle<D>(ps, x, v, v);
  }
  return ps;
}

// The extent by a plain scan of the finite positions.
template <int D>
BlockExtent<D> scanned(const ParticleSet<D>& ps, std::size_t b, std::size_t e) {
  BlockExtent<D> ext;
  for (int k = 0; k < D; ++k) {
    ext.lo[k] = std::numeric_limits<double>::infinity();
    ext.hi[k] = -std::numeric_limits<double>::infinity();
  }
  for (std::size_t i = b; i < e; ++i)
    for (int k = 0; k < D; ++k) {
      ext.finite = ext.finite && std::isfinite(ps.x[i][k]) && std::isfinite(ps.v[i][k]);
      if (std::isnan(ps.x[i][k])) continue;
      ext.lo[k] = std::min(ext.lo[k], ps.x[i][k]);
      ext.hi[k] = std::max(ext.hi[k], ps.x[i][k]);
    }
  return ext;
}

template <int D>
void expect_extents_equal(const BlockExtent<D>& got, const BlockExtent<D>& want) {
  for (int k = 0; k < D; ++k) {
    EXPECT_EQ(got.lo[k], want.lo[k]) << "axis " << k;
    EXPECT_EQ(got.hi[k], want.hi[k]) << "axis " << k;
  }
  EXPECT_EQ(got.finite, want.finite);
}

template <int D>
void extents_of_blocks_match_a_scan() {
  const auto ps = random_particles<D>(1000, -2.0, 3.0, 7 + D);
  // Blocks of every alignment and length, down to one particle (the vectorised loop's
  // remainders at both ends).
  for (const auto& [b, e] : std::vector<std::pair<std::size_t, std::size_t>>{
           {0, 1000}, {0, 512}, {512, 1000}, {3, 4}, {5, 22}, {17, 530}, {999, 1000}})
    expect_extents_equal(block_extent(ps, b, e), scanned(ps, b, e));
}

TEST(BlockExtent, EachAxisLeastAndLargestAreThoseOfAScan2D) {
  extents_of_blocks_match_a_scan<2>();
}
TEST(BlockExtent, EachAxisLeastAndLargestAreThoseOfAScan3D) {
  extents_of_blocks_match_a_scan<3>();
}

TEST(BlockExtent, AnInfiniteOrNaNPositionOrVelocityIsReported) {
  const double inf = std::numeric_limits<double>::infinity(), nan = std::nan("");
  for (int k = 0; k < 3; ++k)
    for (const double bad : {inf, -inf, nan})
      for (const std::size_t i : {std::size_t{40}, std::size_t{63}, std::size_t{70}})
        for (const bool in_velocity : {false, true}) {
          auto ps = random_particles<3>(71, 0.0, 1.0, 3);
          (in_velocity ? ps.v : ps.x)[i][k] = bad;
          const auto ext = block_extent(ps, 40, 71);
          EXPECT_FALSE(ext.finite) << "axis " << k << ", particle " << i << ", value " << bad
                                   << (in_velocity ? " in v" : " in x");
          // A NaN position takes no part in the bounds; an infinite one is the bound.
          expect_extents_equal(ext, scanned(ps, 40, 71));
        }
}

// put_back knowing the extent skips only walls that no particle stands beyond: every particle
// ends where the full scan of every wall puts it, its velocities too, and the particles across
// a wall are back inside the box.
template <int D>
void put_back_with_the_extent_is_the_full_put_back(WallKind kind) {
  auto box = unit_box<D>(kind);
  // Particles in [-0.15, 1.15]: some across each wall within the range (0.1), some beyond it.
  const auto start = random_particles<D>(600, -0.15, 1.15, 11);
  for (const auto& [b, e] :
       std::vector<std::pair<std::size_t, std::size_t>>{{0, 600}, {0, 7}, {7, 300}, {300, 600}}) {
    auto full = start, known = start;
    box.put_back(full, b, e, kRange);
    const auto ext = block_extent(known, b, e);
    const bool ran = box.put_back(known, b, e, kRange, ext.lo, ext.hi);
    EXPECT_TRUE(ran);  // blocks this large hold a particle across some wall
    for (std::size_t i = 0; i < start.n_real; ++i) {
      // What the put-back is, independently of either path: on each axis, a particle of the
      // block across a wall within the range (any distance when periodic) ends inside the box,
      // and every other coordinate is left as it was.
      for (int k = 0; k < D; ++k) {
        const double x0 = start.x[i][k];
        const double depth = std::max(-x0, x0 - 1.0);
        const bool moves =
            i >= b && i < e && depth > 0.0 && (kind == WallKind::periodic || depth <= kRange);
        if (moves) {
          EXPECT_GE(known.x[i][k], 0.0) << i << ", axis " << k;
          EXPECT_LE(known.x[i][k], 1.0) << i << ", axis " << k;
        } else {
          EXPECT_EQ(known.x[i][k], x0) << i << ", axis " << k;
        }
      }
      EXPECT_EQ(known.x[i], full.x[i]) << i;
      EXPECT_EQ(known.v[i], full.v[i]) << i;
      EXPECT_EQ(known.v_half[i], full.v_half[i]) << i;
    }
  }
}

TEST(BlockExtent, PutBackKnowingTheExtentIsTheFullPutBack) {
  put_back_with_the_extent_is_the_full_put_back<2>(WallKind::free_slip);
  put_back_with_the_extent_is_the_full_put_back<2>(WallKind::no_slip);
  put_back_with_the_extent_is_the_full_put_back<3>(WallKind::free_slip);
  put_back_with_the_extent_is_the_full_put_back<2>(WallKind::periodic);
}

TEST(BlockExtent, ABlockInsideTheBoxIsLeftAloneAndSaysSo) {
  const auto box = unit_box<2>(WallKind::free_slip);
  auto ps = random_particles<2>(100, 0.01, 0.99, 5);
  const auto before = ps;
  const auto ext = block_extent(ps, 0, 100);
  EXPECT_FALSE(box.put_back(ps, 0, 100, kRange, ext.lo, ext.hi));
  for (std::size_t i = 0; i < ps.n_real; ++i)
    EXPECT_EQ(ps.x[i], before.x[i]);
}

// A box narrower than the range: the particle put back across the lower wall lands beyond the
// upper one, which the extent taken before did not show; it is put back across that one too,
// as the full scan does.
TEST(BlockExtent, APutBackAcrossTheLowerWallIsSeenByTheUpperOne) {
  auto box = unit_box<2>(WallKind::free_slip);
  box.hi[0] = 0.01;  // 0.01 wide, the range 0.1
  ParticleSet<2> ps;
  add_particle<2>(ps, {{-0.015, 0.5}}, {{-0.3, 0.0}}, {{-0.2, 0.0}});  // to 0.015, then 0.005
  add_particle<2>(ps, {{0.005, 0.5}}, {{0.1, 0.0}}, {{0.1, 0.0}});
  auto full = ps;
  box.put_back(full, 0, 2, kRange);
  const auto ext = block_extent(ps, 0, 2);
  EXPECT_LT(ext.hi[0], box.hi[0]);
  EXPECT_TRUE(box.put_back(ps, 0, 2, kRange, ext.lo, ext.hi));
  EXPECT_DOUBLE_EQ(full.x[0][0], 0.005);  // 0.02 - 0.015: one rounding
  EXPECT_EQ(ps.x[0], full.x[0]);
  EXPECT_EQ(ps.v[0], full.v[0]);
  EXPECT_EQ(ps.v[0][0], -0.3);  // mirrored twice
}

}  // namespace
}  // namespace flume

// Unit tests of the cell grid and the sweep driver (src/flume/neighbors/cell_grid.*,
// src/flume/schemes/sweep.hpp): on uniform, clustered and degenerate clouds in 2D and 3D, with
// and without mirror-wall ghosts, the sweep hands every pair within the support to the equations
// exactly once (the self pair included), compared with the O(N^2) reference; the sums it builds
// do not depend on the thread count to the last bit; bad input is refused.
//
// Pair membership is the comparison |x_i - x_j|^2 < cutoff^2 in both searches (cutoff = 2h with
// the support-2 cubic spline, and 2 (cutoff / 2) == cutoff exactly), so every comparison here is
// exact: no tolerance is involved.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <span>
#include <vector>

#include "flume/core/error.hpp"
#include "flume/kernels/cubic_spline.hpp"
#include "flume/neighbors/brute_force.hpp"
#include "flume/neighbors/cell_grid.hpp"
#include "flume/schemes/sweep.hpp"
#include "support/rates.hpp"
#include "support/small_cases.hpp"

namespace flume {
namespace {

// --- clouds -------------------------------------------------------------------------------------
template <int D>
std::vector<Vec<D>> uniform_cloud(std::size_t n, double lo, double hi, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(lo, hi);
  std::vector<Vec<D>> x(n);
  for (auto& p : x)
    for (int k = 0; k < D; ++k)
      p[k] = u(rng);
  return x;
}

// A few tight Gaussian clusters far apart plus a thin uniform background: most cells are empty,
// a few are crowded.
template <int D>
std::vector<Vec<D>> clustered_cloud(std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  // A 3-unit box: with cutoffs ~0.05 the bounding-box grid (which covers empty space too) stays
  // at ~60^D cells, so the test stays fast.
  std::uniform_real_distribution<double> u(0.0, 3.0);
  std::normal_distribution<double> g(0.0, 0.05);
  std::vector<Vec<D>> centres(4);
  for (auto& c : centres)
    for (int k = 0; k < D; ++k)
      c[k] = u(rng);
  std::vector<Vec<D>> x(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (i % 10 == 9) {
      for (int k = 0; k < D; ++k)
        x[i][k] = u(rng);
    } else {
      const auto& c = centres[i % centres.size()];
      for (int k = 0; k < D; ++k)
        x[i][k] = c[k] + g(rng);
    }
  }
  return x;
}

// Points on an exact lattice of spacing `cutoff` / 2 (a dyadic cutoff, so every coordinate is an
// exact multiple of the cell edge and half the points sit exactly on cell faces, and many pairs
// are exactly `cutoff` apart, the excluded boundary of the strict test), every point duplicated,
// and a few random points mixed in.
template <int D>
std::vector<Vec<D>> face_cloud(double cutoff, int per_axis, std::uint64_t seed) {
  std::vector<Vec<D>> x;
  std::array<int, D> idx{};
  while (true) {
    Vec<D> p;
    for (int k = 0; k < D; ++k)
      p[k] = 0.5 * cutoff * idx[k];
    x.push_back(p);
    x.push_back(p);  // exact duplicate: distance 0 < cutoff
    int k = 0;
    while (k < D && ++idx[k] == per_axis)
      idx[k++] = 0;
    if (k == D) break;
  }
  auto extra = uniform_cloud<D>(x.size() / 4, 0.0, 0.5 * cutoff * (per_axis - 1), seed);
  x.insert(x.end(), extra.begin(), extra.end());
  // Interleave so that duplicates and face points are not all at the start.
  std::mt19937_64 rng(seed + 1);
  std::shuffle(x.begin(), x.end(), rng);
  return x;
}

// --- the counting equation ------------------------------------------------------------------

// Counts the pairs each particle is handed, and sums the partners' ids (a checksum of which
// partners), and m_j W_ij (a floating-point sum whose bits depend on the order of its terms).
struct PairTally {
  double count = 0.0;
  double id_sum = 0.0;
  double weighted = 0.0;
};

template <int D>
struct CountPairs {
  using Acc = PairTally;
  const ParticleSet<D>& ps;
  std::vector<PairTally>& out;

  Acc init(std::size_t) const { return {}; }
  void pair(Acc& ai, Acc& aj, std::size_t i, std::size_t j, const Pair<D>& g) const {
    ai.count += g.in;
    ai.id_sum += g.in * static_cast<double>(ps.id[j]);
    ai.weighted += ps.m[j] * g.w;
    aj.count += g.in;
    aj.id_sum += g.in * static_cast<double>(ps.id[i]);
    aj.weighted += ps.m[i] * g.w;
  }
  void finish(Acc& a, std::size_t i) const { out[i] = a; }
};

template <int D>
ParticleSet<D> particles(const std::vector<Vec<D>>& x, double h) {
  ParticleSet<D> ps;
  for (std::size_t i = 0; i < x.size(); ++i)
    ps.add_real(static_cast<std::int64_t>(i), x[i], Vec<D>{}, 1.0 + 0.001 * static_cast<double>(i),
                1000.0, h);
  return ps;
}

// The tallies of every real particle of ps (in the caller's order), by the sweep.
template <int D>
std::vector<PairTally> sweep_tally(ParticleSet<D> ps, const BoxWalls<D>* walls) {
  std::vector<PairTally> tally;
  test::in_cell_order(CubicSpline<D>::support, ps, walls,
                      [&](ParticleSet<D>& s, const SweepContext<D>& ctx, const Halo<D>&) {
                        std::vector<PairTally> sorted(s.n_real);
                        CountPairs<D> eq{s, sorted};
                        sweep<D, CubicSpline<D>>(ctx, s, "count", eq);
                        // Back to the caller's order through the ids (= caller's indices).
                        tally.resize(s.n_real);
                        for (std::size_t k = 0; k < s.n_real; ++k)
                          tally[static_cast<std::size_t>(s.id[k])] = sorted[k];
                      });
  return tally;
}

// The expected counts and id sums: every point within the cutoff, ghosts included (a ghost
// carries its source's id).
template <int D>
void expect_all_pairs_once(const std::vector<Vec<D>>& x, double cutoff,
                           const BoxWalls<D>* walls = nullptr) {
  auto ps = particles<D>(x, 0.5 * cutoff);
  const auto tally = sweep_tally<D>(ps, walls);
  // The reference: the real particles and (with walls) their ghosts, searched by brute force.
  Halo<D> halo;
  if (walls) walls->build_halo(ps, cutoff, halo);
  halo.append_ghosts(ps);
  const NeighborList nl =
      brute_force_neighbors<D>(std::span<const Vec<D>>(ps.x), ps.n_real, cutoff);
  ASSERT_EQ(tally.size(), ps.n_real);
  for (std::size_t i = 0; i < ps.n_real; ++i) {
    double count = 0.0, id_sum = 0.0;
    for (const auto j : nl.of(i)) {
      count += 1.0;
      id_sum += static_cast<double>(ps.id[j]);
    }
    EXPECT_EQ(tally[i].count, count) << "particle " << i;
    EXPECT_EQ(tally[i].id_sum, id_sum) << "particle " << i;
  }
}

// Restores the OpenMP thread count on scope exit, so a failing assertion cannot leak it.
class ThreadCount {
 public:
  ThreadCount() : saved_(omp_get_max_threads()) {}
  ~ThreadCount() { omp_set_num_threads(saved_); }
  ThreadCount(const ThreadCount&) = delete;
  ThreadCount& operator=(const ThreadCount&) = delete;

 private:
  int saved_;
};

// --- tests --------------------------------------------------------------------------------------

TEST(Sweep, UniformCloudEveryPairOnce2D) {
  expect_all_pairs_once<2>(uniform_cloud<2>(900, 0.0, 1.0, 1), 0.08);
}
TEST(Sweep, UniformCloudEveryPairOnce3D) {
  expect_all_pairs_once<3>(uniform_cloud<3>(1500, 0.0, 1.0, 2), 0.2);
}
TEST(Sweep, ClusteredCloudEveryPairOnce2D) {
  expect_all_pairs_once<2>(clustered_cloud<2>(800, 3), 0.05);
}
TEST(Sweep, ClusteredCloudEveryPairOnce3D) {
  expect_all_pairs_once<3>(clustered_cloud<3>(800, 4), 0.1);
}
TEST(Sweep, DuplicatesAndFacePointsEveryPairOnce2D) {
  expect_all_pairs_once<2>(face_cloud<2>(0.125, 12, 5), 0.125);
}
TEST(Sweep, DuplicatesAndFacePointsEveryPairOnce3D) {
  expect_all_pairs_once<3>(face_cloud<3>(0.25, 6, 6), 0.25);
}

TEST(Sweep, MirrorGhostsEveryPairOnce) {
  // A cloud in the unit box whose four (2D) or six (3D) sides are mirror walls: particles near a
  // side or a corner meet their one, two or three images.
  const auto walls2 = [] {
    auto w = test::open_box<2>(0.0, 1.0);
    for (auto& axis : w.kind)
      axis = {WallKind::free_slip, WallKind::no_slip};
    return w;
  }();
  expect_all_pairs_once<2>(uniform_cloud<2>(900, 0.0, 1.0, 7), 0.08, &walls2);
  const auto walls3 = [] {
    auto w = test::open_box<3>(0.0, 1.0);
    for (auto& axis : w.kind)
      axis = {WallKind::free_slip, WallKind::free_slip};
    return w;
  }();
  expect_all_pairs_once<3>(uniform_cloud<3>(1500, 0.0, 1.0, 8), 0.2, &walls3);
}

// A square box, and a tank four times as long as it is deep (few slabs holding particles).
TEST(Sweep, SumsAreBitIdenticalForAnyThreadCount) {
  const ThreadCount restore;
  for (const double length : {1.0, 4.0}) {
    auto x = uniform_cloud<2>(4000, 0.0, 1.0, 9);
    for (auto& p : x)
      p[0] *= length;
    auto walls = test::open_box<2>(0.0, 1.0);
    walls.hi[0] = length;
    for (auto& axis : walls.kind)
      axis = {WallKind::free_slip, WallKind::free_slip};
    std::vector<std::vector<PairTally>> runs;
    for (const int threads : {1, 2, 3}) {
      omp_set_num_threads(threads);
      runs.push_back(sweep_tally<2>(particles<2>(x, 0.02), &walls));
    }
    for (std::size_t r = 1; r < runs.size(); ++r)
      for (std::size_t i = 0; i < x.size(); ++i) {
        ASSERT_EQ(runs[r][i].weighted, runs[0][i].weighted)
            << "length " << length << ", threads run " << r << ", particle " << i;
        ASSERT_EQ(runs[r][i].count, runs[0][i].count);
      }
  }
}

// sweep_least hands then(b, e) blocks that cover the real particles once each, after their
// finish, and returns the least value: each particle's value here is distinct, and the least
// one is put on every particle in turn of a few positions (first, last, the ends of blocks),
// so a block that skipped a particle or an end would return a larger value.
TEST(Sweep, SweepLeastCoversEveryParticleOnceAndReturnsTheLeast) {
  const ThreadCount restore;
  const auto x = uniform_cloud<2>(3000, 0.0, 1.0, 99);
  auto ps = particles<2>(x, 0.02);
  for (const int threads : {1, 2, 3}) {
    omp_set_num_threads(threads);
    for (const std::size_t least_at : {std::size_t{0}, kParticleBlock - 1, kParticleBlock,
                                       2 * kParticleBlock - 1, x.size() - 1}) {
      test::in_cell_order(
          CubicSpline<2>::support, ps, static_cast<const BoxWalls<2>*>(nullptr),
          [&](ParticleSet<2>& s, const SweepContext<2>& ctx, const Halo<2>&) {
            std::vector<PairTally> tally(s.n_real);
            std::vector<int> seen(s.n_real, 0);
            CountPairs<2> eq{s, tally};
            // The value of the particle with caller's index id: 1 + id, or 0 at least_at.
            const double least = sweep_least<2, CubicSpline<2>>(
                ctx, s, "count",
                [&](std::size_t b, std::size_t e) {
                  double m = std::numeric_limits<double>::infinity();
                  for (std::size_t i = b; i < e; ++i) {
                    ++seen[i];
                    EXPECT_GT(tally[i].count, 0.0) << "then() before the finish of " << i;
                    const auto id = static_cast<std::size_t>(s.id[i]);
                    m = std::min(m, id == least_at ? 0.0 : 1.0 + static_cast<double>(id));
                  }
                  return m;
                },
                eq);
            EXPECT_EQ(least, 0.0) << threads << " threads, least at " << least_at;
            for (std::size_t i = 0; i < s.n_real; ++i)
              ASSERT_EQ(seen[i], 1) << "particle " << i;
          });
    }
  }
}

TEST(CellGrid, NonFinitePositionThrows) {
  for (const double bad :
       {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
        -std::numeric_limits<double>::infinity()}) {
    for (int axis = 0; axis < 3; ++axis) {
      auto x = uniform_cloud<3>(50, 0.0, 1.0, 81);
      x[17][axis] = bad;
      CellGrid<3> grid;
      EXPECT_THROW(grid.sort_real(std::span<const Vec<3>>(x), 0.2), SimulationError)
          << "value " << bad << " on axis " << axis;
    }
  }
}

TEST(CellGrid, NonPositiveRangeThrows) {
  const auto x = uniform_cloud<2>(10, 0.0, 1.0, 91);
  CellGrid<2> grid;
  EXPECT_THROW(grid.sort_real(std::span<const Vec<2>>(x), 0.0), SimulationError);
  EXPECT_THROW(grid.sort_real(std::span<const Vec<2>>(x), -1.0), SimulationError);
  EXPECT_THROW(grid.sort_real(std::span<const Vec<2>>(x), std::numeric_limits<double>::quiet_NaN()),
               SimulationError);
}

TEST(CellGrid, EscapedParticleThrowsInsteadOfAllocating) {
  auto x = uniform_cloud<3>(20, 0.0, 1.0, 92);
  x[3][2] = 1e12;  // 1e13 ranges away: far beyond any sane grid
  CellGrid<3> grid;
  EXPECT_THROW(grid.sort_real(std::span<const Vec<3>>(x), 0.1), SimulationError);
}

// The order the sweeps rely on: by cell, and within a cell by x (ties by index), so that each
// row of cells is sorted by x; the same for the ghosts.
TEST(CellGrid, SortIsAPermutationByCellThenX) {
  auto x = uniform_cloud<2>(500, 0.0, 1.0, 93);
  for (std::size_t k = 0; k < 40; ++k)
    x[k + 40][0] = x[k][0];  // equal x-coordinates: their order is by index
  CellGrid<2> grid;
  const auto order = grid.sort_real(std::span<const Vec<2>>(x), 0.1);
  std::vector<std::uint32_t> seen(order.begin(), order.end());
  std::sort(seen.begin(), seen.end());
  for (std::size_t k = 0; k < seen.size(); ++k)
    ASSERT_EQ(seen[k], k);
  for (std::size_t k = 1; k < order.size(); ++k) {
    ASSERT_LE(grid.cell_of_real(k - 1), grid.cell_of_real(k));
    if (grid.cell_of_real(k - 1) == grid.cell_of_real(k)) {
      const double xa = x[order[k - 1]][0], xb = x[order[k]][0];
      ASSERT_TRUE(xa < xb || (xa == xb && order[k - 1] < order[k])) << k;
    }
  }
  // A row of cells along x is one run sorted by x.
  const std::size_t row = 5 * grid.strides()[1];
  for (std::uint32_t k = grid.real_begin(row) + 1; k < grid.real_begin(row + grid.dims()[0]); ++k)
    ASSERT_LE(x[order[k - 1]][0], x[order[k]][0]);
}

TEST(CellGrid, GhostsAreSortedByCellThenX) {
  const auto x = uniform_cloud<2>(300, 0.0, 1.0, 94);
  const auto gx = uniform_cloud<2>(200, -0.2, 1.2, 95);
  CellGrid<2> grid;
  grid.sort_real(std::span<const Vec<2>>(x), 0.1);
  const auto order = grid.sort_ghosts(std::span<const Vec<2>>(gx));
  std::vector<Vec<2>> sorted(gx.size());
  for (std::size_t k = 0; k < gx.size(); ++k)
    sorted[k] = gx[order[k]];
  for (std::size_t c = 0; c < grid.cells(); ++c)
    for (std::uint32_t k = grid.ghost_begin(c) + 1; k < grid.ghost_begin(c + 1); ++k)
      ASSERT_LE(sorted[k - x.size() - 1][0], sorted[k - x.size()][0]) << c;
}

// The sorts of more points than one thread bins (the parallel counting sort, its running sum
// over the cells shared among the threads) give the order of one thread for 2 and 3 threads, and
// that order is by cell, then x, then index: real particles (20,000) and ghosts, few (binned by
// one thread, their runs found along the order) and many (binned in parallel).
TEST(CellGrid, SortsDoNotDependOnTheThreadCount) {
  const ThreadCount restore;
  auto x = uniform_cloud<2>(20000, 0.0, 1.0, 101);
  for (std::size_t k = 0; k < 200; ++k)
    x[k + 200][0] = x[k][0];  // equal x-coordinates: their order is by index
  const auto few = uniform_cloud<2>(3000, -0.02, 1.02, 102);
  const auto many = uniform_cloud<2>(12000, -0.02, 1.02, 103);
  struct Sorted {
    std::vector<std::uint32_t> real, real_start, ghosts_few, start_few, ghosts_many, start_many;
  };
  // Ghosts by cell (starts from n_real to n_real + ghosts), then x, then index.
  auto expect_ghosts_sorted = [&](const std::vector<Vec<2>>& g,
                                  const std::vector<std::uint32_t>& order,
                                  const std::vector<std::uint32_t>& start) {
    ASSERT_EQ(start.front(), x.size());
    ASSERT_EQ(start.back(), x.size() + g.size());
    for (std::size_t c = 0; c + 1 < start.size(); ++c)
      for (std::uint32_t k = start[c] + 1; k < start[c + 1]; ++k) {
        const std::uint32_t a = order[k - x.size() - 1], b = order[k - x.size()];
        ASSERT_TRUE(g[a][0] < g[b][0] || (g[a][0] == g[b][0] && a < b)) << k;
      }
  };
  std::vector<Sorted> runs;
  for (const int threads : {1, 2, 3}) {
    omp_set_num_threads(threads);
    CellGrid<2> grid;
    Sorted s;
    s.real = grid.sort_real(std::span<const Vec<2>>(x), 0.013);
    for (std::size_t c = 0; c <= grid.cells(); ++c)
      s.real_start.push_back(grid.real_begin(c));
    s.ghosts_few = grid.sort_ghosts(std::span<const Vec<2>>(few));
    for (std::size_t c = 0; c <= grid.cells(); ++c)
      s.start_few.push_back(grid.ghost_begin(c));
    s.ghosts_many = grid.sort_ghosts(std::span<const Vec<2>>(many));
    for (std::size_t c = 0; c <= grid.cells(); ++c)
      s.start_many.push_back(grid.ghost_begin(c));
    if (threads == 1) {
      // By cell (each cell's run holds its particles only), then x, then index.
      ASSERT_EQ(s.real_start.front(), 0u);
      ASSERT_EQ(s.real_start.back(), x.size());
      for (std::size_t c = 0; c < grid.cells(); ++c)
        for (std::uint32_t k = s.real_start[c]; k < s.real_start[c + 1]; ++k) {
          ASSERT_EQ(grid.cell_of_real(k), c) << k;
          if (k == s.real_start[c]) continue;
          const std::uint32_t a = s.real[k - 1], b = s.real[k];
          ASSERT_TRUE(x[a][0] < x[b][0] || (x[a][0] == x[b][0] && a < b)) << k;
        }
      std::vector<std::uint32_t> seen(s.real);
      std::sort(seen.begin(), seen.end());
      for (std::size_t k = 0; k < seen.size(); ++k)
        ASSERT_EQ(seen[k], k);
      expect_ghosts_sorted(few, s.ghosts_few, s.start_few);
      expect_ghosts_sorted(many, s.ghosts_many, s.start_many);
    }
    runs.push_back(std::move(s));
  }
  for (std::size_t r = 1; r < runs.size(); ++r) {
    EXPECT_EQ(runs[r].real, runs[0].real) << "threads run " << r;
    EXPECT_EQ(runs[r].real_start, runs[0].real_start) << "threads run " << r;
    EXPECT_EQ(runs[r].ghosts_few, runs[0].ghosts_few) << "threads run " << r;
    EXPECT_EQ(runs[r].ghosts_many, runs[0].ghosts_many) << "threads run " << r;
    EXPECT_EQ(runs[r].start_few, runs[0].start_few) << "threads run " << r;
    EXPECT_EQ(runs[r].start_many, runs[0].start_many) << "threads run " << r;
  }
}

// The few ghosts' counting sort (one thread, over the occupied cells only) gives the order and
// the cell starts of the parallel counting sort over every cell: the same 3,000 ghosts sorted
// alone, and with 9,000 more far beyond the grid (clamped into its last cell, after every other
// cell) so that they are binned in parallel. Sorted alone twice, with the many between: the
// few ghosts' counts start from zero each time.
TEST(CellGrid, FewGhostsSortAsTheParallelCountingSortDoes) {
  const auto x = uniform_cloud<2>(20000, 0.0, 1.0, 111);
  const auto few = uniform_cloud<2>(3000, -0.02, 1.02, 112);
  auto many = few;
  many.resize(12000, Vec<2>{{5.0, 5.0}});
  CellGrid<2> grid;
  grid.sort_real(std::span<const Vec<2>>(x), 0.013);
  auto starts = [&] {
    std::vector<std::uint32_t> s;
    for (std::size_t c = 0; c <= grid.cells(); ++c)
      s.push_back(grid.ghost_begin(c));
    return s;
  };
  const auto order_few = grid.sort_ghosts(std::span<const Vec<2>>(few));
  const auto start_few = starts();
  const auto order_many = grid.sort_ghosts(std::span<const Vec<2>>(many));
  const auto start_many = starts();
  const auto order_again = grid.sort_ghosts(std::span<const Vec<2>>(few));
  EXPECT_EQ(order_again, order_few);
  EXPECT_EQ(starts(), start_few);
  const std::size_t cells = grid.cells();
  ASSERT_EQ(start_few[cells], x.size() + few.size());
  ASSERT_EQ(start_many[cells], x.size() + many.size());
  ASSERT_EQ(start_many[cells - 1], x.size() + few.size());  // the far ones: the last cell
  for (std::size_t c = 0; c < cells; ++c)
    ASSERT_EQ(start_few[c], start_many[c]) << c;
  for (std::size_t k = 0; k < few.size(); ++k)
    ASSERT_EQ(order_few[k], order_many[k]) << k;
}

// runs_outside: every real particle outside the box is in a run; the runs are increasing and
// merged (a gap between any two). Boxes with finite and infinite sides, one that holds every
// particle and one that holds none; 2D and 3D; uniform and clustered clouds.
template <int D>
void expect_runs_hold_the_particles_outside(const std::vector<Vec<D>>& x, double range,
                                            const Vec<D>& lo, const Vec<D>& hi) {
  CellGrid<D> grid;
  const auto order = grid.sort_real(std::span<const Vec<D>>(x), range);
  std::vector<std::pair<std::uint32_t, std::uint32_t>> runs;
  grid.runs_outside(lo, hi, runs);
  std::vector<bool> in_run(x.size(), false);
  for (std::size_t r = 0; r < runs.size(); ++r) {
    ASSERT_LT(runs[r].first, runs[r].second) << "run " << r << " is empty";
    if (r > 0) {
      ASSERT_LT(runs[r - 1].second, runs[r].first) << "runs " << r - 1 << ", " << r;
    }
    for (std::uint32_t k = runs[r].first; k < runs[r].second; ++k)
      in_run[k] = true;
  }
  std::size_t outside = 0;
  for (std::size_t k = 0; k < x.size(); ++k) {
    const Vec<D>& p = x[order[k]];
    bool out = false;
    for (int a = 0; a < D; ++a)
      out = out || !(p[a] > lo[a] && p[a] < hi[a]);
    if (!out) continue;
    ++outside;
    EXPECT_TRUE(in_run[k]) << "particle at sorted index " << k << " is outside but in no run";
  }
  if (outside > 0) {
    EXPECT_GT(runs.size(), 0u);
  }
}

TEST(CellGrid, RunsOutsideHoldEveryParticleOutsideTheBox) {
  const double inf = std::numeric_limits<double>::infinity();
  const auto x2 = uniform_cloud<2>(3000, 0.0, 1.0, 96);
  for (const double r : {0.03, 0.1, 0.3}) {
    expect_runs_hold_the_particles_outside<2>(x2, r, Vec<2>{{r, r}}, Vec<2>{{1 - r, 1 - r}});
    expect_runs_hold_the_particles_outside<2>(x2, r, Vec<2>{{-inf, r}}, Vec<2>{{1 - r, inf}});
    expect_runs_hold_the_particles_outside<2>(x2, r, Vec<2>{{0.5, -inf}}, Vec<2>{{inf, inf}});
  }
  // No particle outside, and all of them outside.
  expect_runs_hold_the_particles_outside<2>(x2, 0.05, Vec<2>{{-inf, -inf}}, Vec<2>{{inf, inf}});
  expect_runs_hold_the_particles_outside<2>(x2, 0.05, Vec<2>{{2.0, 2.0}}, Vec<2>{{3.0, 3.0}});
  const auto x3 = clustered_cloud<3>(4000, 97);
  expect_runs_hold_the_particles_outside<3>(x3, 0.1, Vec<3>{{0.5, 0.4, 0.3}},
                                            Vec<3>{{2.5, 2.6, 2.7}});
  expect_runs_hold_the_particles_outside<3>(x3, 0.1, Vec<3>{{-inf, 1.0, -inf}},
                                            Vec<3>{{inf, 2.0, 1.5}});
}

// The runs are a small part of the particles when the box is most of the cloud: a halo built
// from them costs a layer of cells near the walls, not the whole set.
TEST(CellGrid, RunsOutsideAreTheCellsNearTheBoxOnly) {
  const auto x = uniform_cloud<2>(20000, 0.0, 1.0, 98);
  CellGrid<2> grid;
  grid.sort_real(std::span<const Vec<2>>(x), 0.01);
  std::vector<std::pair<std::uint32_t, std::uint32_t>> runs;
  grid.runs_outside(Vec<2>{{0.01, 0.01}}, Vec<2>{{0.99, 0.99}}, runs);
  std::size_t held = 0;
  for (const auto& [b, e] : runs)
    held += e - b;
  // The band within 0.01 of the sides holds 4 % of the particles; with the two extra layers
  // of cells (and the cells' margin) on each side, at most about three times that.
  EXPECT_LT(static_cast<double>(held), 0.13 * static_cast<double>(x.size()));
  EXPECT_GT(static_cast<double>(held), 0.039 * static_cast<double>(x.size()));
}

}  // namespace
}  // namespace flume

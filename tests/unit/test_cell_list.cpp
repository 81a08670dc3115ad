// Unit tests of the cell-list neighbour search (src/flume/neighbors/cell_list.*): on uniform,
// clustered and degenerate clouds in 2D and 3D the neighbour sets equal the O(N^2) reference
// exactly, every list holds its query, the per-list order is the documented one and does not
// depend on the thread count, cell_order is a permutation, one object can be rebuilt many times,
// non-finite input is refused, and the number of cells grows like N.
//
// Neighbour membership is a comparison |x_i - x_j|^2 < cutoff^2 evaluated with the same
// expression in both searches, so every comparison here is exact: no tolerance is involved.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <random>
#include <span>
#include <vector>

#include "flume/core/error.hpp"
#include "flume/core/vec.hpp"
#include "flume/neighbors/brute_force.hpp"
#include "flume/neighbors/cell_list.hpp"
#include "flume/neighbors/neighbor_list.hpp"

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

// --- checks -------------------------------------------------------------------------------------

// Every neighbour list of `got` equals the brute-force one as a set, and contains its query.
template <int D>
void expect_same_sets(const std::vector<Vec<D>>& x, std::size_t n_query, double cutoff,
                      const NeighborList& got) {
  const std::span<const Vec<D>> xs(x);
  const NeighborList ref = brute_force_neighbors<D>(xs, n_query, cutoff);
  ASSERT_EQ(got.queries(), n_query);
  ASSERT_EQ(got.offset.front(), 0u);
  ASSERT_EQ(got.offset.back(), got.index.size());
  ASSERT_EQ(got.index.size(), ref.index.size());
  for (std::size_t i = 0; i < n_query; ++i) {
    auto a = std::vector<std::uint32_t>(got.of(i).begin(), got.of(i).end());
    const auto b = std::vector<std::uint32_t>(ref.of(i).begin(), ref.of(i).end());
    EXPECT_NE(std::find(a.begin(), a.end(), static_cast<std::uint32_t>(i)), a.end())
        << "query " << i << " missing from its own list";
    std::sort(a.begin(), a.end());
    EXPECT_TRUE(std::adjacent_find(a.begin(), a.end()) == a.end())
        << "query " << i << " has a repeated neighbour";
    ASSERT_EQ(a, b) << "neighbour set of query " << i << " differs from brute force";
  }
}

// The documented per-list order: ascending cell, then ascending index. cell_order(size) is the
// stable sort of all points by cell, so that order is ascending rank in cell_order(size).
template <int D>
void expect_documented_order(const CellList<D>& cl, std::size_t n_points, const NeighborList& nl) {
  const auto order = cl.cell_order(n_points);
  ASSERT_EQ(order.size(), n_points);
  std::vector<std::size_t> rank(n_points);
  for (std::size_t r = 0; r < order.size(); ++r)
    rank[order[r]] = r;
  for (std::size_t i = 0; i < nl.queries(); ++i) {
    const auto l = nl.of(i);
    for (std::size_t k = 1; k < l.size(); ++k)
      ASSERT_LT(rank[l[k - 1]], rank[l[k]]) << "list of query " << i << " out of order at " << k;
  }
}

template <int D>
NeighborList search(CellList<D>& cl, const std::vector<Vec<D>>& x, std::size_t n_query,
                    double cutoff) {
  const std::span<const Vec<D>> xs(x);
  cl.build(xs, cutoff);
  NeighborList nl;
  cl.find_neighbors(xs, n_query, nl);
  return nl;
}

template <int D>
void check_cloud(const std::vector<Vec<D>>& x, std::size_t n_query, double cutoff) {
  CellList<D> cl;
  const NeighborList nl = search(cl, x, n_query, cutoff);
  expect_same_sets(x, n_query, cutoff, nl);
  expect_documented_order(cl, x.size(), nl);
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

TEST(CellList, UniformCloudMatchesBruteForce2D) {
  // ~20 neighbours each; queries are a strict prefix (real particles before ghosts).
  const auto x = uniform_cloud<2>(800, -1.0, 2.0, 11);
  check_cloud<2>(x, 600, 0.3);
}

TEST(CellList, UniformCloudMatchesBruteForce3D) {
  const auto x = uniform_cloud<3>(800, -1.0, 1.0, 12);
  check_cloud<3>(x, 600, 0.35);
}

TEST(CellList, ClusteredCloudMatchesBruteForce2D) {
  const auto x = clustered_cloud<2>(800, 21);
  check_cloud<2>(x, 600, 0.04);
}

TEST(CellList, ClusteredCloudMatchesBruteForce3D) {
  const auto x = clustered_cloud<3>(800, 22);
  check_cloud<3>(x, 600, 0.06);
}

TEST(CellList, DuplicatesAndFacePointsMatchBruteForce2D) {
  const auto x = face_cloud<2>(0.125, 18, 31);
  check_cloud<2>(x, x.size() - 100, 0.125);
}

TEST(CellList, DuplicatesAndFacePointsMatchBruteForce3D) {
  const auto x = face_cloud<3>(0.25, 7, 32);
  check_cloud<3>(x, x.size() - 100, 0.25);
}

TEST(CellList, NonDyadicCutoffOnLatticeMatchesBruteForce) {
  // cutoff = 0.1 is not representable: lattice points k * 0.1 land within an ulp of the cell faces
  // on either side, the case where a rounding slip in the binning would lose a neighbour.
  std::vector<Vec<2>> x;
  for (int i = 0; i < 25; ++i)
    for (int j = 0; j < 25; ++j)
      x.push_back(Vec<2>{{0.1 * i, 0.1 * j}});
  check_cloud<2>(x, x.size(), 0.1);
  check_cloud<2>(x, x.size(), 0.1 * (1.0 + 1e-15));
  check_cloud<2>(x, x.size(), 0.2);
}

TEST(CellList, ListContainsQueryEvenWhenIsolated) {
  // Points far apart: each list is exactly the query itself.
  std::vector<Vec<3>> x;
  for (int i = 0; i < 10; ++i)
    x.push_back(Vec<3>{{3.0 * i, -2.0 * i, 1.0 * i}});
  CellList<3> cl;
  const auto nl = search(cl, x, 7, 0.5);
  ASSERT_EQ(nl.queries(), 7u);
  for (std::size_t i = 0; i < 7; ++i) {
    ASSERT_EQ(nl.of(i).size(), 1u);
    EXPECT_EQ(nl.of(i)[0], i);
  }
}

TEST(CellList, OrderIsDeterministicAcrossRebuildsAndThreadCounts) {
  const ThreadCount restore;
  const auto x = clustered_cloud<3>(1000, 41);
  const std::size_t nq = 800;
  const double cutoff = 0.05;

  omp_set_num_threads(2);
  CellList<3> a;
  const auto first = search(a, x, nq, cutoff);
  const auto again = search(a, x, nq, cutoff);  // same object rebuilt
  CellList<3> b;
  const auto other_object = search(b, x, nq, cutoff);
  omp_set_num_threads(1);
  CellList<3> c;
  const auto serial = search(c, x, nq, cutoff);

  EXPECT_EQ(first.offset, again.offset);
  EXPECT_EQ(first.index, again.index);
  EXPECT_EQ(first.offset, other_object.offset);
  EXPECT_EQ(first.index, other_object.index);
  EXPECT_EQ(first.offset, serial.offset);
  EXPECT_EQ(first.index, serial.index);
}

TEST(CellList, OrderIsDeterministicAcrossThreadCounts2D) {
  const ThreadCount restore;
  const auto x = uniform_cloud<2>(2000, 0.0, 1.0, 42);
  omp_set_num_threads(1);
  CellList<2> a;
  const auto serial = search(a, x, 1500, 0.05);
  omp_set_num_threads(2);
  const auto parallel = search(a, x, 1500, 0.05);
  EXPECT_EQ(serial.offset, parallel.offset);
  EXPECT_EQ(serial.index, parallel.index);
}

TEST(CellList, CellOrderIsAStablePermutationOfThePrefix) {
  const auto x = uniform_cloud<2>(800, 0.0, 1.0, 51);
  CellList<2> cl;
  cl.build(std::span<const Vec<2>>(x), 0.1);
  const auto all = cl.cell_order(x.size());
  for (std::size_t n : {std::size_t{0}, std::size_t{1}, std::size_t{500}, x.size()}) {
    const auto order = cl.cell_order(n);
    ASSERT_EQ(order.size(), n);
    auto sorted = order;
    std::sort(sorted.begin(), sorted.end());
    std::vector<std::size_t> iota(n);
    std::iota(iota.begin(), iota.end(), std::size_t{0});
    EXPECT_EQ(sorted, iota) << "cell_order(" << n << ") is not a permutation of [0, n)";
    // The prefix order is the full order with the ghosts (indices >= n) removed.
    std::vector<std::size_t> filtered;
    for (std::size_t k : all)
      if (k < n) filtered.push_back(k);
    EXPECT_EQ(order, filtered);
  }
}

TEST(CellList, CellOrderGroupsSpatialNeighbours) {
  // Two well separated blobs given in interleaved index order: the cell order must not
  // interleave them (that is what the memory re-sort is for).
  std::vector<Vec<2>> x;
  for (int i = 0; i < 50; ++i) {
    x.push_back(Vec<2>{{0.001 * i, 0.0}});
    x.push_back(Vec<2>{{10.0 + 0.001 * i, 0.0}});
  }
  CellList<2> cl;
  cl.build(std::span<const Vec<2>>(x), 0.5);
  const auto order = cl.cell_order(x.size());
  ASSERT_EQ(order.size(), x.size());
  int switches = 0;
  for (std::size_t k = 1; k < order.size(); ++k)
    if ((x[order[k]][0] > 5.0) != (x[order[k - 1]][0] > 5.0)) ++switches;
  EXPECT_EQ(switches, 1);
}

TEST(CellList, ReusedObjectHandlesBuildsOfDifferentSizes) {
  CellList<3> cl;
  // Grow, shrink, change the extent and the cutoff, then grow again: stale buffers from a
  // previous build must never leak into the next one.
  const std::vector<std::size_t> sizes{300, 800, 40, 1, 500};
  const std::vector<double> cutoffs{0.3, 0.2, 0.5, 0.1, 0.35};
  for (std::size_t r = 0; r < sizes.size(); ++r) {
    const double half = 0.5 * static_cast<double>(r + 1);
    const auto x = uniform_cloud<3>(sizes[r], -half, half, 60 + r);
    const std::size_t nq = sizes[r] - sizes[r] / 5;
    const auto nl = search(cl, x, nq, cutoffs[r]);
    expect_same_sets<3>(x, nq, cutoffs[r], nl);
    expect_documented_order(cl, x.size(), nl);
  }
  // An empty cloud after non-empty ones.
  const std::vector<Vec<3>> empty;
  const auto nl = search(cl, empty, 0, 0.1);
  EXPECT_EQ(nl.queries(), 0u);
  EXPECT_TRUE(nl.index.empty());
  EXPECT_TRUE(cl.cell_order(0).empty());
}

TEST(CellList, ReusedNeighborListIsOverwritten) {
  // find_neighbors into a NeighborList that held a bigger result must not keep stale entries.
  CellList<2> cl;
  NeighborList nl;
  const auto big = uniform_cloud<2>(1000, 0.0, 1.0, 71);
  cl.build(std::span<const Vec<2>>(big), 0.1);
  cl.find_neighbors(std::span<const Vec<2>>(big), big.size(), nl);
  const auto small = uniform_cloud<2>(100, 0.0, 1.0, 72);
  cl.build(std::span<const Vec<2>>(small), 0.1);
  cl.find_neighbors(std::span<const Vec<2>>(small), 60, nl);
  expect_same_sets<2>(small, 60, 0.1, nl);
}

TEST(CellList, NonFinitePositionThrows) {
  for (const double bad :
       {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
        -std::numeric_limits<double>::infinity()}) {
    for (int axis = 0; axis < 3; ++axis) {
      auto x = uniform_cloud<3>(50, 0.0, 1.0, 81);
      x[17][axis] = bad;
      CellList<3> cl;
      EXPECT_THROW(cl.build(std::span<const Vec<3>>(x), 0.2), SimulationError)
          << "value " << bad << " on axis " << axis;
    }
    auto x2 = uniform_cloud<2>(50, 0.0, 1.0, 82);
    x2[0][1] = bad;
    CellList<2> cl2;
    EXPECT_THROW(cl2.build(std::span<const Vec<2>>(x2), 0.2), SimulationError);
  }
}

TEST(CellList, NonPositiveCutoffThrows) {
  const auto x = uniform_cloud<2>(10, 0.0, 1.0, 91);
  CellList<2> cl;
  EXPECT_THROW(cl.build(std::span<const Vec<2>>(x), 0.0), SimulationError);
  EXPECT_THROW(cl.build(std::span<const Vec<2>>(x), -1.0), SimulationError);
  EXPECT_THROW(cl.build(std::span<const Vec<2>>(x), std::numeric_limits<double>::quiet_NaN()),
               SimulationError);
}

TEST(CellList, EscapedParticleThrowsInsteadOfAllocating) {
  auto x = uniform_cloud<3>(20, 0.0, 1.0, 92);
  x[3][2] = 1e12;  // 1e13 cut-off lengths away: far beyond any sane grid
  CellList<3> cl;
  EXPECT_THROW(cl.build(std::span<const Vec<3>>(x), 0.1), SimulationError);
}

TEST(CellList, CellCountGrowsLinearlyForUniformClouds) {
  // Fixed mean spacing s and cutoff 2 s: the grid covers the box with ~(L / 2s + 1)^D cells, i.e.
  // about N / 2^D plus boundary layers. cells / N must stay bounded and roughly constant.
  for (const std::size_t n : {std::size_t{1000}, std::size_t{8000}, std::size_t{64000}}) {
    const double side = std::cbrt(static_cast<double>(n));  // unit mean spacing
    const auto x = uniform_cloud<3>(n, 0.0, side, 100 + n);
    CellList<3> cl;
    cl.build(std::span<const Vec<3>>(x), 2.0);
    const double ratio = static_cast<double>(cl.cells()) / static_cast<double>(n);
    // (side / 2 + 1)^3 / side^3 is 0.216 at n = 1000 and tends to 1/8 = 0.125: bounds with margin.
    EXPECT_GT(ratio, 0.1) << "n = " << n;
    EXPECT_LT(ratio, 0.3) << "n = " << n;
  }
  for (const std::size_t n : {std::size_t{1000}, std::size_t{16000}}) {
    const double side = std::sqrt(static_cast<double>(n));
    const auto x = uniform_cloud<2>(n, 0.0, side, 200 + n);
    CellList<2> cl;
    cl.build(std::span<const Vec<2>>(x), 2.0);
    const double ratio = static_cast<double>(cl.cells()) / static_cast<double>(n);
    // (side / 2 + 1)^2 / side^2: 0.315 at n = 1000, 0.266 at n = 16000, limit 0.25.
    EXPECT_GT(ratio, 0.2) << "n = " << n;
    EXPECT_LT(ratio, 0.4) << "n = " << n;
  }
}

// Regression: binning with cells exactly `cutoff` wide computed s = (x - origin) / cutoff in
// floating point, and the rounding could put two points closer than `cutoff` into cells two
// apart, so the 3^D stencil missed the pair (cells are now a hair wider than the cut-off). Here
// (x_i - o) / c = 4.999999999999999 (cell 4) and (x_j - o) / c rounds up to exactly 6.0 (cell 6),
// while x_j - x_i < c and (x_j - x_i)^2 < c^2 also in floating point, so brute force lists the pair
// and the cell list does not. Found by a random search over points placed within a few ulps of the
// cell faces.
TEST(CellList, RoundingInBinningMustNotLoseAPair) {
  const double c = 0.48814312045512825;
  const std::vector<Vec<2>> x{Vec<2>{{-3.0153157186106849, 0.0}},
                              Vec<2>{{-0.57460011633504382, 0.0}},
                              Vec<2>{{-0.086456995879915607, 0.0}}};
  ASSERT_LT(norm2(x[2] - x[1]), c * c);  // the pair is within the cutoff
  check_cloud<2>(x, x.size(), c);
}

}  // namespace
}  // namespace flume

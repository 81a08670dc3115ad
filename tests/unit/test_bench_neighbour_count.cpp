// The neighbour count of `flume bench` (src/flume/bench/neighbour_count.*), which is independent
// of flume's neighbour search: on jittered lattices in 2D and 3D it equals an O(N^2) count, and
// on a square lattice with support 2.83 spacings it is the exact count (24 per interior particle).
#include <gtest/gtest.h>

#include <random>
#include <span>
#include <vector>

#include "flume/bench/neighbour_count.hpp"

namespace flume {
namespace {

template <int D>
double brute_force_mean(const std::vector<Vec<D>>& x, double radius) {
  std::size_t pairs = 0;
  for (std::size_t i = 0; i < x.size(); ++i)
    for (std::size_t j = 0; j < x.size(); ++j) {
      if (i == j) continue;
      double d2 = 0.0;
      for (int k = 0; k < D; ++k)
        d2 += (x[i][k] - x[j][k]) * (x[i][k] - x[j][k]);
      if (d2 < radius * radius) ++pairs;
    }
  return static_cast<double>(pairs) / static_cast<double>(x.size());
}

template <int D>
std::vector<Vec<D>> jittered_lattice(int side, double dx, double jitter) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-jitter, jitter);
  std::vector<Vec<D>> x;
  int total = 1;
  for (int k = 0; k < D; ++k)
    total *= side;
  for (int n = 0; n < total; ++n) {
    Vec<D> p;
    int rest = n;
    for (int k = 0; k < D; ++k) {
      p[k] = (rest % side + 0.5) * dx + u(rng) * dx;
      rest /= side;
    }
    x.push_back(p);
  }
  return x;
}

TEST(BenchNeighbourCount, EqualsTheQuadraticCount) {
  for (double radius : {0.5e-3, 2.83e-3, 7.1e-3}) {
    const auto x2 = jittered_lattice<2>(30, 1e-3, 0.3);
    EXPECT_DOUBLE_EQ(mean_neighbour_count<2>(std::span<const Vec<2>>(x2), radius),
                     brute_force_mean(x2, radius))
        << radius;
    const auto x3 = jittered_lattice<3>(9, 1e-3, 0.3);
    EXPECT_DOUBLE_EQ(mean_neighbour_count<3>(std::span<const Vec<3>>(x3), radius),
                     brute_force_mean(x3, radius))
        << radius;
  }
}

TEST(BenchNeighbourCount, SquareLatticeWithDualSphysicsSupport) {
  // Support 2.83 spacings reaches the 24 lattice points with di^2 + dj^2 <= 8 (sqrt(8) = 2.828).
  // On an L x L block each offset (di, dj) pairs (L - |di|)(L - |dj|) particles:
  // 4 (L-1) L + 4 (L-1)^2 + 4 (L-2) L + 8 (L-2)(L-1) + 4 (L-2)^2 ordered pairs, -> 24 L^2.
  for (int side : {5, 40}) {
    const double L = side;
    const double pairs = 4 * (L - 1) * L + 4 * (L - 1) * (L - 1) + 4 * (L - 2) * L +
                         8 * (L - 2) * (L - 1) + 4 * (L - 2) * (L - 2);
    const auto x = jittered_lattice<2>(side, 1.0, 0.0);
    EXPECT_DOUBLE_EQ(mean_neighbour_count<2>(std::span<const Vec<2>>(x), 2.83), pairs / (L * L))
        << side;
  }
}

TEST(BenchNeighbourCount, StrictlyInsideTheRadius) {
  const std::vector<Vec<2>> pair{Vec<2>{{0.0, 0.0}}, Vec<2>{{1.0, 0.0}}};
  EXPECT_EQ(mean_neighbour_count<2>(std::span<const Vec<2>>(pair), 1.0), 0.0);
  EXPECT_EQ(mean_neighbour_count<2>(std::span<const Vec<2>>(pair), 1.0 + 1e-9), 1.0);
  EXPECT_EQ(mean_neighbour_count<2>(std::span<const Vec<2>>(), 1.0), 0.0);
}

}  // namespace
}  // namespace flume

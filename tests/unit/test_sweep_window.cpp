// The sweep cuts each x-sorted run of cells to the particles within one range of x_i by
// bisection (sweep.hpp, bisect_x). A wrong bound drops pairs silently (fewer neighbours, a
// slightly wrong density) or wastes lanes, so it is checked against std::lower_bound and
// std::upper_bound on runs with repeated values, at both ends and for empty runs.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "flume/schemes/sweep.hpp"

namespace flume {
namespace {

TEST(SweepWindow, BisectionMatchesLowerAndUpperBound) {
  std::mt19937_64 rng(7);
  for (int trial = 0; trial < 5000; ++trial) {
    const std::size_t n = rng() % 40;
    std::vector<double> v(n);
    for (double& q : v)
      q = static_cast<double>(rng() % 10);  // repeated values
    std::sort(v.begin(), v.end());
    // The run sits at [1, n + 1) of the particle array, as a run inside a set does.
    std::vector<Vec<2>> x(n + 2);
    for (std::size_t k = 0; k < n; ++k)
      x[k + 1] = Vec<2>{{v[k], -1.0}};
    const double q = static_cast<double>(rng() % 12) - 1.0;
    const auto lower =
        static_cast<std::size_t>(std::lower_bound(v.begin(), v.end(), q) - v.begin());
    const auto upper =
        static_cast<std::size_t>(std::upper_bound(v.begin(), v.end(), q) - v.begin());
    ASSERT_EQ((detail::bisect_x<2, false>(x.data(), 1, n + 1, q)), 1 + lower) << trial;
    ASSERT_EQ((detail::bisect_x<2, true>(x.data(), 1, n + 1, q)), 1 + upper) << trial;
  }
}

}  // namespace
}  // namespace flume

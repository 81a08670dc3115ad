// Which slabs each thread of a sweep takes (schemes/slab_schedule.hpp, slabs_of_thread): the
// threads' ranges follow one another and cover every slab once (with the even-then-odd order of
// sweep_pairs, that keeps a sweep's results independent of the thread count), and a thread's
// slabs are those whose first particle lies in its share of the particles, the share the
// per-particle passes give it.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "flume/schemes/slab_schedule.hpp"

namespace flume {
namespace {

TEST(SlabSchedule, ThreadsTakeConsecutiveRangesThatCoverEverySlabOnce) {
  std::mt19937 rng(7);
  for (long slabs = 0; slabs <= 41; ++slabs) {
    // First particles of the slabs: non-decreasing, with empty slabs (runs of equal values).
    std::vector<std::size_t> begin(static_cast<std::size_t>(slabs));
    std::size_t n = 0;
    for (auto& b : begin) {
      b = n;
      n += rng() % 3 == 0 ? 0 : rng() % 50;
    }
    const auto slab_begin = [&](long s) { return begin[static_cast<std::size_t>(s)]; };
    for (std::size_t threads = 1; threads <= 5; ++threads) {
      long next = 0;
      for (std::size_t t = 0; t < threads; ++t) {
        const auto [first, last] = detail::slabs_of_thread(slabs, n, t, threads, slab_begin);
        ASSERT_EQ(first, next) << slabs << " slabs, thread " << t << " of " << threads;
        ASSERT_LE(first, last);
        for (long s = first; s < last; ++s) {
          // Thread t's share is [t n / T, (t + 1) n / T); the first thread also takes the slabs
          // before, the last the slabs after.
          if (t > 0) {
            EXPECT_GE(slab_begin(s), t * n / threads) << "slab " << s;
          }
          if (t + 1 < threads) {
            EXPECT_LT(slab_begin(s), (t + 1) * n / threads) << "slab " << s;
          }
        }
        next = last;
      }
      EXPECT_EQ(next, slabs) << slabs << " slabs, " << threads << " threads";
    }
  }
}

// A hand-checked case: 6 slabs holding 10 particles each, two threads: slabs 0-2 and 3-5.
TEST(SlabSchedule, TwoThreadsSplitEvenSlabsInHalves) {
  const auto slab_begin = [](long s) { return static_cast<std::size_t>(10 * s); };
  EXPECT_EQ(detail::slabs_of_thread(6, 60, 0, 2, slab_begin), std::make_pair(0L, 3L));
  EXPECT_EQ(detail::slabs_of_thread(6, 60, 1, 2, slab_begin), std::make_pair(3L, 6L));
}

}  // namespace
}  // namespace flume

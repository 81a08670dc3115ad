// The order in which a sweep hands out its slabs (schemes/slab_schedule.hpp): every slab once, and
// each odd slab after both its even neighbours. That is what keeps a sweep's results independent of
// the thread count (each accumulator gets the even slab's terms first) and free of deadlock (a
// thread waits only for slabs already handed out).
#include <gtest/gtest.h>

#include <vector>

#include "flume/schemes/slab_schedule.hpp"

namespace flume {
namespace {

TEST(SlabOrder, EverySlabOnceAndEachOddSlabAfterItsEvenNeighbours) {
  for (long slabs = 1; slabs <= 41; ++slabs) {
    for (long lead = 2; lead <= 12; ++lead) {
      std::vector<long> position(static_cast<std::size_t>(slabs), -1);
      for (long k = 0; k < slabs; ++k) {
        const long s = detail::slab_in_order(k, slabs, lead);
        ASSERT_GE(s, 0) << slabs << " slabs, lead " << lead << ", k " << k;
        ASSERT_LT(s, slabs) << slabs << " slabs, lead " << lead << ", k " << k;
        ASSERT_EQ(position[static_cast<std::size_t>(s)], -1)
            << "slab " << s << " twice (" << slabs << " slabs, lead " << lead << ")";
        position[static_cast<std::size_t>(s)] = k;
      }
      for (long s = 1; s < slabs; s += 2) {
        EXPECT_GT(position[static_cast<std::size_t>(s)], position[static_cast<std::size_t>(s - 1)])
            << "odd slab " << s << " before slab " << s - 1 << " (" << slabs << " slabs, lead "
            << lead << ")";
        if (s + 1 < slabs) {
          EXPECT_GT(position[static_cast<std::size_t>(s)],
                    position[static_cast<std::size_t>(s + 1)])
              << "odd slab " << s << " before slab " << s + 1 << " (" << slabs << " slabs, lead "
              << lead << ")";
        }
      }
    }
  }
}

// The even slabs go out `lead` ahead, so an odd slab's later neighbour left well before it.
TEST(SlabOrder, EvenSlabsLeadByTheGivenCount) {
  const std::vector<long> expected{0, 2, 4, 6, 1, 8, 3, 10, 5, 7, 9};
  for (long k = 0; k < 11; ++k)
    EXPECT_EQ(detail::slab_in_order(k, 11, 4), expected[static_cast<std::size_t>(k)]) << k;
}

}  // namespace
}  // namespace flume

// The slabs in which a sweep's threads share the grid (sweep.hpp, sweep_pairs): how many there
// are, and the order in which they are handed out so that an odd slab comes after both its even
// neighbours.
#pragma once

#include <algorithm>
#include <atomic>

#include "flume/neighbors/cell_grid.hpp"

namespace flume::detail {

constexpr int kSlabLayers = 2;  // cell layers per slab (>= 1: a pair reaches one layer ahead)

// The slabs of a grid: kSlabLayers cell layers along the slowest axis each.
template <int D>
long slab_count(const CellGrid<D>& grid) {
  const long layers = static_cast<long>(grid.dims()[D - 1]);
  return (layers + kSlabLayers - 1) / kSlabLayers;
}

// The order in which the slabs are handed out: the even slabs `lead` ahead, then odd and even
// in turn, then what is left: 0, 2, 4, 6, 1, 8, 3, 10, 5, ... for lead 4. Slab k of the order.
// Every odd slab comes after both its even neighbours (lead >= 2), so that a thread that takes
// an odd slab finds them done, or being finished by another thread, and never waits for a
// slab that no thread has taken (no deadlock).
inline long slab_in_order(long k, long slabs, long lead) {
  const long evens = (slabs + 1) / 2, odds = slabs / 2;
  const long first = std::min(lead, evens);
  if (k < first) return 2 * k;
  const long m = k - first;
  const long alternating = std::min(odds, evens - first);  // (odd, even) couples
  if (m < 2 * alternating) return m % 2 == 0 ? 2 * (m / 2) + 1 : 2 * (first + m / 2);
  const long rest = m - 2 * alternating;
  return odds > alternating ? 2 * (alternating + rest) + 1 : 2 * (first + alternating + rest);
}

// What the threads of a sweep share to hand out the slabs: flag[0] is the next position in
// the order, flag[1 + s] is set once slab s is done. A type of its own for the workspace.
struct SlabFlag {
  int v;
};

// Marks a slab done and wakes a thread asleep on its flag (no system call when none is).
inline void mark_done(std::atomic_ref<int> flag) {
  flag.store(1, std::memory_order_release);
  flag.notify_all();
}

// Waits until a slab is done. Spins first: when every thread has a core the neighbour is being
// finished and the wait is short, and a sleep costs a kernel wake-up (tens of microseconds on a
// virtual machine). Then sleeps in the kernel (std::atomic_ref::wait): with more threads than
// free cores (another job, ctest -j) the neighbour's thread may be off its core, and a waiter
// that kept spinning or yielding held the core it needs; two 2-thread runs side by side on two
// cores spent their time in such waits.
inline void wait_done(std::atomic_ref<int> flag) {
  constexpr int kSpins = 1 << 18;  // a few milliseconds, as long as libgomp spins at a barrier
  for (int k = 0; k < kSpins; ++k) {
    if (flag.load(std::memory_order_acquire) != 0) return;
#if defined(__x86_64__) || defined(__i386__)
    __builtin_ia32_pause();
#endif
  }
  flag.wait(0, std::memory_order_acquire);
}

}  // namespace flume::detail

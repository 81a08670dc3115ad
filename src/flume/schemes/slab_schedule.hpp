// The slabs in which a sweep's threads share the grid (sweep.hpp, sweep_pairs): how many there
// are, and which of them each thread takes.
#pragma once

#include <atomic>
#include <cstddef>
#include <utility>

#include "flume/neighbors/cell_grid.hpp"

namespace flume::detail {

constexpr int kSlabLayers = 2;  // cell layers per slab (>= 1: a pair reaches one layer ahead)

// The slabs of a grid: kSlabLayers cell layers along the slowest axis each.
template <int D>
long slab_count(const CellGrid<D>& grid) {
  const long layers = static_cast<long>(grid.dims()[D - 1]);
  return (layers + kSlabLayers - 1) / kSlabLayers;
}

// The slabs of thread t of `threads`: [first, last), those whose first particle lies in the
// thread's share of the real particles, [t n / threads, (t + 1) n / threads) (slab_begin(s):
// the index of slab s's first particle, non-decreasing in s). The per-particle passes give
// each thread about the same share (OpenMP's static schedule, particle_passes.hpp), so a
// particle's fields are written by one core from one pass to the next. With the slabs handed
// out in turn (as before), half of them were written on the other core, each such line taken
// from its cache: in this machine's slow spells (its two virtual cores, it seems, then not
// sharing a cache) a `standard` step at 1e5 took 1.0 s per 100 steps against 0.73 (the
// integration pass 5 x slower, the neighbour search 2 x); with the shares, 0.75-0.80.
template <class SlabBegin>
std::pair<long, long> slabs_of_thread(long slabs, std::size_t n, std::size_t t, std::size_t threads,
                                      const SlabBegin& slab_begin) {
  auto first_from = [&](std::size_t share) {
    if (share == 0) return 0L;
    if (share >= threads) return slabs;
    const std::size_t from = share * n / threads;
    long lo = 0, hi = slabs;  // the first slab whose first particle is at or after `from`
    while (lo < hi) {
      const long mid = lo + (hi - lo) / 2;
      if (slab_begin(mid) < from)
        lo = mid + 1;
      else
        hi = mid;
    }
    return lo;
  };
  return {first_from(t), first_from(t + 1)};
}

// What the threads of a sweep share: flag[2 s] is set once slab s is done, flag[2 s + 1] once a
// thread has claimed it. A type of its own for the workspace.
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

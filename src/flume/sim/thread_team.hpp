// How many threads a step of a simulation runs on. Every loop gives the same result for any
// thread count (sweep.hpp), so this is a question of speed alone: a step's threads meet at every
// parallel pass's end and at each sweep's barriers, and below about a thousand particles a
// thread the split saves less than those waits cost. A still tank of 430 particles on a beach
// (tests/settling/test_slope_tank.cpp) took 1.53 s on one thread and 2.74 s on two, 79 % of the
// two threads' samples (perf) in libgomp's barrier and pool waits. Ratios of 2 threads to 1 in
// `flume bench --threads 1,2 --steps 300` (noisy, one run each) at 1,024 / 1,521 / 2,025 /
// 2,500 / 3,025 particles:
//   standard 1.09 / 0.88 / 1.14 / 1.49 / 1.78,
//   wsph     0.95 / 0.95 / 1.26 / 1.49 / 1.28,
//   csph     1.32 / 1.46 / 1.63 / 1.44 / 1.15.
#pragma once

#include <algorithm>
#include <cstddef>

#include <omp.h>

namespace flume {

// The default of SimulationConfig::particles_per_thread.
inline constexpr std::size_t kParticlesPerThread = 1000;

// The threads for `particles` real particles when `threads` are asked: at most one per
// `per_thread` particles, at least one; per_thread = 0 takes every thread asked.
inline int team_size(std::size_t particles, int threads, std::size_t per_thread) {
  if (per_thread == 0 || threads <= 1) return std::max(threads, 1);
  const std::size_t most = particles / per_thread;
  return static_cast<int>(std::clamp<std::size_t>(most, 1, static_cast<std::size_t>(threads)));
}

// Sets OpenMP's thread count for the parallel regions started in its scope (from this thread),
// and puts the previous count back at its end.
class ThreadTeam {
 public:
  explicit ThreadTeam(int threads) : saved_(omp_get_max_threads()) {
    if (threads != saved_) omp_set_num_threads(threads);
  }
  ~ThreadTeam() {
    if (omp_get_max_threads() != saved_) omp_set_num_threads(saved_);
  }
  ThreadTeam(const ThreadTeam&) = delete;
  ThreadTeam& operator=(const ThreadTeam&) = delete;

 private:
  int saved_;
};

}  // namespace flume

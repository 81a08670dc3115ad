// The per-particle passes over the real particles (equation of state, time integration,
// checks): the loops, threads and blocking are the driver's, as the pair sweeps' are
// (sweep.hpp); a pass gives only what happens to one particle, or to one block of them.
#pragma once

#include <algorithm>
#include <cstddef>

namespace flume {

// Particles per block of the passes that work block by block (least_over_blocks, and the
// finish of sweep_least).
inline constexpr std::size_t kParticleBlock = 512;

// A per-particle pass over the real particles (equation of state, stresses, body forces).
template <class F>
void for_each_real(std::size_t n_real, F&& f) {
  const auto n = static_cast<long>(n_real);
#pragma omp parallel for schedule(static)
  for (long ii = 0; ii < n; ++ii)
    f(static_cast<std::size_t>(ii));
}

// The real particles in blocks [b, e) of kParticleBlock, in parallel: f(b, e) does a block's
// work (loops over it that the compiler vectorises, the block's fields still in cache from one
// loop to the next) and returns a number; returns the least of them, or init. A minimum is
// exact, so it does not depend on the thread count.
template <class T, class F>
T least_over_blocks(std::size_t n_real, T init, F&& f) {
  const auto blocks = static_cast<long>((n_real + kParticleBlock - 1) / kParticleBlock);
  T least = init;
#pragma omp parallel for schedule(static) reduction(min : least)
  for (long bb = 0; bb < blocks; ++bb) {
    const std::size_t b = static_cast<std::size_t>(bb) * kParticleBlock;
    least = std::min(least, static_cast<T>(f(b, std::min(n_real, b + kParticleBlock))));
  }
  return least;
}

// f(b, e) for each block of the real particles, as least_over_blocks shares them out.
template <class F>
void for_each_block(std::size_t n_real, F&& f) {
  least_over_blocks(n_real, 0, [&](std::size_t b, std::size_t e) {
    f(b, e);
    return 0;
  });
}

}  // namespace flume

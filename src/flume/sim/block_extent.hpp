// The extent of a block of particles [b, e): the least and largest position along each axis,
// and whether every component of their positions and velocities is finite. One flat pass over
// the D components of x and v, without a branch or a gather: what the drift's pass needs to
// know of a block before its walls' put-back and its checks (Simulation::put_back_and_check).
// Read per particle as x[i][k], the same tests compiled to gathers (in each wall's scan and in
// the checks: the checks alone 1.6 % of a `standard` step's samples at 1e5, perf).
#pragma once

#include <cstddef>
#include <limits>

#include "flume/core/particle_set.hpp"

namespace flume {

template <int D>
struct BlockExtent {
  Vec<D> lo, hi;       // NaN components take no part (the finite flag reports them)
  bool finite = true;  // every component of x and v finite
};

// The extent of no particle (every least +inf, every largest -inf): what join starts from.
template <int D>
BlockExtent<D> empty_extent() {
  BlockExtent<D> ext;
  for (int k = 0; k < D; ++k) {
    ext.lo[k] = std::numeric_limits<double>::infinity();
    ext.hi[k] = -std::numeric_limits<double>::infinity();
  }
  return ext;
}

// into becomes the extent of both blocks (exact: a least and a largest in any order).
template <int D>
void join(BlockExtent<D>& into, const BlockExtent<D>& other) {
  for (int k = 0; k < D; ++k) {
    into.lo[k] = other.lo[k] < into.lo[k] ? other.lo[k] : into.lo[k];
    into.hi[k] = other.hi[k] > into.hi[k] ? other.hi[k] : into.hi[k];
  }
  into.finite = into.finite && other.finite;
}

template <int D>
BlockExtent<D> block_extent(const ParticleSet<D>& ps, std::size_t b, std::size_t e) {
  static_assert(D >= 1 && D <= 3 && sizeof(Vec<D>) == D * sizeof(double));
  const double* __restrict x = ps.x.data()->c.data();
  const double* __restrict v = ps.v.data()->c.data();
  // One scalar per axis, reduced by the simd loop (reductions over an array section of D
  // compiled to 2-wide vectors; written by lanes of an array, the loop stayed scalar).
  constexpr double inf = std::numeric_limits<double>::infinity();
  double lo0 = inf, lo1 = inf, lo2 = inf, hi0 = -inf, hi1 = -inf, hi2 = -inf, nan = 0.0;
  // x - x is 0 for a finite x and NaN for an infinite or NaN one; a sum of them stays 0 exactly
  // unless one is NaN. A NaN x fails both comparisons and leaves lo and hi alone.
#pragma omp simd reduction(min : lo0, lo1, lo2) reduction(max : hi0, hi1, hi2) reduction(+ : nan)
  for (std::size_t i = b; i < e; ++i) {
    const double* xi = x + D * i;
    const double* vi = v + D * i;
    lo0 = xi[0] < lo0 ? xi[0] : lo0;
    hi0 = xi[0] > hi0 ? xi[0] : hi0;
    if constexpr (D > 1) {
      lo1 = xi[1] < lo1 ? xi[1] : lo1;
      hi1 = xi[1] > hi1 ? xi[1] : hi1;
    }
    if constexpr (D > 2) {
      lo2 = xi[2] < lo2 ? xi[2] : lo2;
      hi2 = xi[2] > hi2 ? xi[2] : hi2;
    }
    for (int k = 0; k < D; ++k)
      nan += (xi[k] - xi[k]) + (vi[k] - vi[k]);
  }
  const double lo[3] = {lo0, lo1, lo2}, hi[3] = {hi0, hi1, hi2};
  BlockExtent<D> ext;
  for (int k = 0; k < D; ++k) {
    ext.lo[k] = lo[k];
    ext.hi[k] = hi[k];
  }
  ext.finite = nan == 0.0;
  return ext;
}

}  // namespace flume

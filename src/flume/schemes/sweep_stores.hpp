// Where a sweep keeps its numbers (sweep.hpp): each equation's per-particle factors and
// accumulators, stored component by component, and particle i's shares of a block of pairs with
// their partial sums.
#pragma once

#include <array>
#include <bit>
#include <cstddef>
#include <cstring>
#include <type_traits>

#include "flume/core/vec.hpp"

namespace flume::detail {

// An equation's per-particle factors (own.hpp) for the n particles of the set, real and ghost,
// stored component by component like the accumulators (AccStore), so that the block loop reads
// j's factors with unit stride. Equations without factors have an empty store.
template <class O>
struct OwnStore {
  static constexpr std::size_t kDoubles = std::is_empty_v<O> ? 0 : sizeof(O) / sizeof(double);
  static_assert(std::is_empty_v<O> ||
                    (std::is_trivially_copyable_v<O> && sizeof(O) % sizeof(double) == 0),
                "per-particle factors are made of doubles only");
  struct Component {  // a buffer type of its own: the factors live while accumulators do
    double v;
  };
  Component* base = nullptr;
  std::size_t n = 0;

  O get(std::size_t b) const {
    if constexpr (kDoubles == 0) {
      return O{};
    } else {
      std::array<double, kDoubles> f;
      for (std::size_t d = 0; d < kDoubles; ++d)
        f[d] = base[d * n + b].v;
      return std::bit_cast<O>(f);
    }
  }
  // One double at a time out of o. Through a bit_cast to an array GCC copied o on the stack
  // with a 32-byte load that spanned the narrower stores that had just built o, which the store
  // buffer does not forward: half of the factors' fill in CSPH's continuity sweep (perf).
  void set(std::size_t b, const O& o) const {
    if constexpr (kDoubles > 0) {
      const auto* bytes = reinterpret_cast<const unsigned char*>(&o);
      for (std::size_t d = 0; d < kDoubles; ++d) {
        double v;
        std::memcpy(&v, bytes + d * sizeof(double), sizeof v);
        base[d * n + b].v = v;
      }
    }
  }
};

constexpr std::size_t kChunk = 64;  // candidates evaluated in one vectorised block
constexpr std::size_t kLanes = 8;   // partial sums of i's share: term k goes to sum k % kLanes

// Particle i's shares of the pairs of one block, and their kLanes partial sums. An accumulator
// is seen as the doubles it is made of (every Acc is: double, Vec, Mat, or arrays and structs
// of them), stored component by component so that the block loop writes them with unit stride.
template <class Acc>
struct Shares {
  static_assert(std::is_trivially_copyable_v<Acc> && sizeof(Acc) % sizeof(double) == 0,
                "an accumulator is made of doubles only");
  static constexpr std::size_t kDoubles = sizeof(Acc) / sizeof(double);
  using Flat = std::array<double, kDoubles>;

  alignas(64) double block[kDoubles][kChunk];
  alignas(64) double partial[kDoubles][kLanes];

  void clear() {
    for (auto& p : partial)
      for (double& v : p)
        v = 0.0;
  }
  void put(std::size_t k, const Acc& a) {
    const auto f = std::bit_cast<Flat>(a);
    for (std::size_t d = 0; d < kDoubles; ++d)
      block[d][k] = f[d];
  }
  void add_lane(std::size_t l, const Acc& a) {
    const auto f = std::bit_cast<Flat>(a);
    for (std::size_t d = 0; d < kDoubles; ++d)
      partial[d][l] += f[d];
  }
  // Adds the first n shares of the block: share k to partial sum k % kLanes.
  void fold(std::size_t n) {
    for (std::size_t d = 0; d < kDoubles; ++d) {
      std::size_t k0 = 0;
      for (; k0 + kLanes <= n; k0 += kLanes)
        for (std::size_t l = 0; l < kLanes; ++l)
          partial[d][l] += block[d][k0 + l];
      for (std::size_t l = 0; k0 + l < n; ++l)
        partial[d][l] += block[d][k0 + l];
    }
  }
  // a + the partial sums, added pairwise in a fixed tree (an order fixed by the positions
  // alone; a tree rather than a chain, whose latency would stall every particle's end).
  // The tree is ((p0 + p4) + (p2 + p6)) + ((p1 + p5) + (p3 + p7)), taken as halves of one
  // vector: the block loop has just stored the partial sums as whole vectors, and reading them
  // back one double at a time stalled on the store (13 % of a momentum sweep). The vector is
  // pinned in a register (the empty asm): otherwise GCC reads its low half again from memory, a
  // narrower load than the store it follows, which the store buffer does not forward (18 % of
  // the density sweep, flume_bench BM_SweepDensity at 1e5 on one thread: 4.27 -> 3.51 ms).
  Acc total(const Acc& a) const {
    static_assert(kLanes == 8);
    using V8 = double __attribute__((vector_size(64)));
    using V4 = double __attribute__((vector_size(32)));
    using V2 = double __attribute__((vector_size(16)));
    auto sum = std::bit_cast<Flat>(a);
    for (std::size_t d = 0; d < kDoubles; ++d) {
      V8 p;
      std::memcpy(&p, partial[d], sizeof p);
#if defined(__AVX512F__)
      asm("" : "+v"(p));  // a register for a whole vector of eight doubles: AVX-512 only
#endif
      const V4 q =
          __builtin_shufflevector(p, p, 0, 1, 2, 3) + __builtin_shufflevector(p, p, 4, 5, 6, 7);
      const V2 r = __builtin_shufflevector(q, q, 0, 1) + __builtin_shufflevector(q, q, 2, 3);
      sum[d] += r[0] + r[1];
    }
    return std::bit_cast<Acc>(sum);
  }
};

// The accumulators of one equation for n particles, stored component by component (structure
// of arrays): the block loop adds j's share to each component with unit stride, where an array
// of Acc would have the vector lanes transposed to and from it for every block (an 8 x 8
// transpose each way for CSPH's two matrices). A store of one double per particle lives in a
// workspace buffer of double, one of D doubles in a buffer of Vec<D>: the buffers that the
// re-ordering of the state uses between sweeps, so the sweeps' scalar and vector accumulators
// cost no memory of their own. Equation I of a group has slot kFirstAccSlot + I; a caller that
// needs a buffer during a sweep takes a slot past the group's.
inline constexpr std::size_t kFirstAccSlot = 0;
template <std::size_t K, int D>
using AccBuffer =
    std::conditional_t<K == 1, double, std::conditional_t<K == D, Vec<D>, std::array<double, K>>>;
template <class Acc>
struct AccStore {
  using Value = Acc;
  static constexpr std::size_t kDoubles = Shares<Acc>::kDoubles;
  using Flat = typename Shares<Acc>::Flat;
  double* base = nullptr;
  std::size_t n = 0;

  Acc get(std::size_t i) const {
    Flat f;
    for (std::size_t d = 0; d < kDoubles; ++d)
      f[d] = base[d * n + i];
    return std::bit_cast<Acc>(f);
  }
  void set(std::size_t i, const Acc& a) const {
    const auto f = std::bit_cast<Flat>(a);
    for (std::size_t d = 0; d < kDoubles; ++d)
      base[d * n + i] = f[d];
  }
  void add(std::size_t j, const Acc& a) const {
    const auto f = std::bit_cast<Flat>(a);
    for (std::size_t d = 0; d < kDoubles; ++d)
      base[d * n + j] += f[d];
  }
};

}  // namespace flume::detail

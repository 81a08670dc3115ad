// Per-particle factors of an equation: what its pair term needs of each particle that does not
// depend on the pair (p_b / rho_b^2 in BL (7), the volume m_b / rho_b in BL (4)). An equation
// that has some declares them (docs/adding_an_equation.md):
//   using Own = ...;                  double, or a struct of them
//   Own own(std::size_t b) const;     particle b's factors (b real or ghost)
//   void pair(Acc& ai, Acc& aj, const Own& oi, const Own& oj, i, j, const Pair<D>& g) const;
// The sweep computes own(b) once for every particle before its pairs, so the pair loop reads a
// number instead of redoing a division for every pair. Without Own, pair has the plain form
//   void pair(Acc& ai, Acc& aj, i, j, const Pair<D>& g) const.
// This header lets the driver and AccelerationSum call either form alike.
#pragma once

#include <cstddef>
#include <type_traits>

namespace flume {

template <class Eq>
concept HasOwn = requires {
  typename Eq::Own;
};

struct NoOwn {};  // what an equation without per-particle factors gets

template <class Eq>
struct OwnOfT {
  using type = NoOwn;
};
template <HasOwn Eq>
struct OwnOfT<Eq> {
  using type = typename Eq::Own;
};
template <class Eq>
using OwnOf = typename OwnOfT<Eq>::type;

// Particle b's factors for eq (NoOwn{} when it has none).
template <class Eq>
OwnOf<Eq> own_of(const Eq& eq, std::size_t b) {
  if constexpr (HasOwn<Eq>)
    return eq.own(b);
  else
    return NoOwn{};
}

// eq's pair term for (i, j), in whichever form eq has.
template <class Eq, class Acc, class Geometry>
void pair_of(const Eq& eq, Acc& ai, Acc& aj, const OwnOf<Eq>& oi, const OwnOf<Eq>& oj,
             std::size_t i, std::size_t j, const Geometry& g) {
  if constexpr (HasOwn<Eq>)
    eq.pair(ai, aj, oi, oj, i, j, g);
  else
    eq.pair(ai, aj, i, j, g);
}

}  // namespace flume

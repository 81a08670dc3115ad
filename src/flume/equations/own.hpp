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

// The factors of several equations side by side (AccelerationSum's terms): a plain aggregate of
// doubles, which the sweep stores component by component; a term without factors takes no room.
template <class... Os>
struct OwnPack {};
template <class O, class... Rest>
struct OwnPack<O, Rest...> {
  [[no_unique_address]] O first;
  [[no_unique_address]] OwnPack<Rest...> rest;
};
template <class... Os>
OwnPack<Os...> make_own_pack(const Os&... os) {
  if constexpr (sizeof...(Os) == 0) {
    return {};
  } else {
    return [](const auto& first, const auto&... rest) {
      return OwnPack<Os...>{first, make_own_pack(rest...)};
    }(os...);
  }
}
template <std::size_t K, class O, class... Rest>
const auto& own_get(const OwnPack<O, Rest...>& pack) {
  if constexpr (K == 0)
    return pack.first;
  else
    return own_get<K - 1>(pack.rest);
}

// Particle b's factors for eq (NoOwn{} when it has none).
template <class Eq>
OwnOf<Eq> own_of(const Eq& eq, std::size_t b) {
  if constexpr (HasOwn<Eq>)
    return eq.own(b);
  else
    return NoOwn{};
}

// An equation every term of which carries grad W (none carries W itself) may declare
//   static constexpr bool kGradientOnly = true;
// Its self pair (r = 0, grad W = 0) adds exact zeros, so the driver skips it: the self pair of
// the momentum sweep, with the artificial viscosity's division, cost as much as a block of
// eight pairs. tests/properties/test_self_pair.cpp checks every such declaration.
template <class Eq>
constexpr bool gradient_only() {
  if constexpr (requires { Eq::kGradientOnly; })
    return Eq::kGradientOnly;
  else
    return false;
}

// A central pair force, a_i -= m_j s grad W and a_j += m_i s grad W with a scalar s (a pressure
// force, the artificial viscosity), may say so by giving s:
//   double radial(const Own& oi, const Own& oj, i, j, const Pair<D>& g) const;   (or without
//   the Own arguments, as pair)
// AccelerationSum then adds the s of its radial terms and multiplies grad W once, as a
// hand-written momentum loop does, instead of building and adding a vector for each term.
template <class Eq>
concept HasRadial = requires {
  Eq::kRadial;
};

template <class Eq, class Geometry>
double radial_of(const Eq& eq, const OwnOf<Eq>& oi, const OwnOf<Eq>& oj, std::size_t i,
                 std::size_t j, const Geometry& g) {
  if constexpr (HasOwn<Eq>)
    return eq.radial(oi, oj, i, j, g);
  else
    return eq.radial(i, j, g);
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
